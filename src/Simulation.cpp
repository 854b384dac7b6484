#include "vp/Simulation.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Logging.hpp"
#include "vp/core/Options.hpp"
#include "vp/coupling/HydroForce.hpp"
#include "vp/fluid/AnalyticFlow.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/io/CollapseMonitor.hpp"
#include "vp/io/Diagnostics.hpp"
#include "vp/io/OutputDir.hpp"
#include "vp/io/ParticleTracker.hpp"
#include "vp/io/Probes.hpp"
#include "vp/io/RheologyMonitor.hpp"
#include "vp/io/RunRecord.hpp"
#include "vp/particles/ParticleCheckpoint.hpp"
#include <algorithm>
#include <cmath>
#include <csignal>
#include <map>
#include <sstream>

namespace vp {

namespace {

std::string hms(double seconds)
{
  long s = std::lround(std::max(0.0, seconds));
  char b[32];
  std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return b;
}

} // namespace

Simulation::Simulation(MPI_Comm comm, const RunConfig& rc)
  : cfg_(rc.main), grid_(comm, cfg_.grid, cfg_.bc), particleCfg_(rc.particles), collapseCfg_(rc.collapse), rheologyCfg_(rc.rheology),
    stepControl_(cfg_, particleCfg_.any()),
    snapshots_(cfg_.output.every, cfg_.output.dt, 0), checkpointSchedule_(cfg_.checkpoint.every, cfg_.checkpoint.dt, cfg_.checkpoint.dt),
    guard_(comm, cfg_)
{
  wallStart_ = MPI_Wtime();
  std::unique_ptr<CheckpointReader> restart;
  std::vector<ParticleRecord> restartParticles;
  if (!cfg_.checkpoint.restart.empty()) {
    restart = std::make_unique<CheckpointReader>(comm, cfg_.checkpoint.restart, cfg_);
    restartParticles = loadParticles(*restart);
    const std::size_t n = restartParticles.size();
    if ((n > 0) != particleCfg_.any())
      failOption("-restart", n > 0 ? "the checkpoint holds " + std::to_string(n) + " particles: give the original run's particle options "
                                     "too (the particles come from the checkpoint, the contact and lubrication options from the command line)"
                                   : "the checkpoint holds no particles, but particle options are given");
    compareSetup(*restart);
  }
  if (particleCfg_.any() && !cfg_.fluid.off) {
    penalization_ = std::make_unique<Penalization>(grid_, rc.penalization, cfg_.fluid.rho, cfg_.fluid.nu());
    particleCfg_.maskSupport = penalization_->support();
  }
  if (restart && particleCfg_.any())
    dem_ = std::make_unique<DemSolver>(grid_, cfg_, particleCfg_, restartParticles, true);
  else if (particleCfg_.any())
    dem_ = std::make_unique<DemSolver>(grid_, cfg_, particleCfg_);
  if (penalization_ && particleCfg_.lubrication.replace) {
    patches_ = std::make_unique<LubricationPatches>(particleCfg_.lubrication, domainWalls(cfg_));
    dem_->setPatches(patches_.get());
  }
  fluid_ = std::make_unique<Projection>(grid_, cfg_, rc.solvers, penalization_ && rc.penalization.weightedProjection);
  if (rc.solvers.viscousMgLevels > 1) {
    // Fewer grids than asked where halving stops (Grid::coarsenable).
    const int want = rc.solvers.viscousMgLevels, levels = fluid_->diffusionSolver().multigridLevels();
    const char* why = "halving the grid again would leave an axis below 2 cells or a rank's cell range odd";
    if (levels < 2)
      PetscPrintf(grid_.comm(), "vpsolve: -velocity_mg_levels %d: %s; the viscous CG keeps Jacobi\n", want, why);
    else if (levels < want)
      PetscPrintf(grid_.comm(), "vpsolve: viscous CG preconditioned by a multigrid V-cycle over %d grids, not %d: %s\n", levels,
                  want, why);
    else
      PetscPrintf(grid_.comm(), "vpsolve: viscous CG preconditioned by a multigrid V-cycle over %d grids\n", levels);
  }
  if (restart)
    restore(*restart);
  else {
    AnalyticFlow flow(cfg_);
    sampleVelocity(grid_, flow, 0, fluid_->velocity());
    samplePressure(grid_, flow, 0, fluid_->pressure());
    fluid_->applyBoundaryConditions();
    if (dem_ && cfg_.fluid.init == InitFlow::Couette) startWithShear(flow);
  }
  if (penalization_) {
    buildMask(0);
    hydroSums_.assign(kHydroSums * dem_->particles().size(), 0.0);
    if (!restart) hydroForce(0);  // a restart has the fluid momentum inside each particle
  }
  if (dem_) particlesAtStart_ = dem_->diagnostics().particles;
  if (rheologyCfg_.on) rheologyCfg_.validateCell(cfg_, dem_->particles(), comm);
  firstStep_ = step_;
  firstTime_ = time_;
}

// A sheared suspension starts in equilibrium with the flow: each free sphere at the velocity of the
// Couette profile at its centre and spinning at half its vorticity (else the start is an impulse).
void Simulation::startWithShear(const AnalyticFlow& flow)
{
  const GridConfig& g = cfg_.grid;
  const Vec3 bottom{g.lo[0], g.lo[1], g.lo[2]}, top{g.lo[0], g.lo[1], g.hi[2]};
  const double L = g.hi[2] - g.lo[2];
  const Vec3 spin{-0.5 * (flow.velocity(1, top, 0) - flow.velocity(1, bottom, 0)) / L,
                  0.5 * (flow.velocity(0, top, 0) - flow.velocity(0, bottom, 0)) / L, 0};
  ParticleStore& s = dem_->particles();
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    if (s.fixed(i)) continue;
    for (int c = 0; c < 3; ++c) s.v[i][c] = flow.velocity(c, s.x[i], 0);
    s.w[i] = spin;
  }
  dem_->syncGhosts();
}

void Simulation::openOutputs()
{
  if (!cfg_.output.files) return;
  const MPI_Comm comm = grid_.comm();
  const std::string& dir = cfg_.output.dir;
  prepareOutputDir(comm, dir, restart_ != nullptr, cfg_.output.overwrite);
  writeRunRecord(comm, dir);
  fields_ = std::make_unique<FieldWriter>(grid_, dir);
  // A restart continues the time series after the checkpoint's row (dropping later ones).
  const double resumeStep = restart_ ? step_ : -1, resumeTime = restart_ ? time_ : -1;
  if (dem_) {
    particleWriter_ = std::make_unique<ParticleWriter>(comm, dir);
    monitors_.push_back(std::make_unique<ParticleTracker>(comm, dir, particleCfg_, dem_->particles(), resumeTime));
  }
  if (!cfg_.output.probes.empty() && !cfg_.fluid.off)
    monitors_.push_back(std::make_unique<Probes>(grid_, cfg_.output.probes, dir, resumeTime));
  if (collapseCfg_.on) monitors_.push_back(std::make_unique<CollapseMonitor>(grid_, collapseCfg_, dir, resumeTime));
  if (rheologyCfg_.on)
    monitors_.push_back(std::make_unique<RheologyMonitor>(grid_, cfg_, rheologyCfg_, *dem_, *penalization_, dir, resumeTime));
  monitors_.push_back(std::make_unique<Diagnostics>(comm, dir, dem_ != nullptr, cfg_.fluid.rho, resumeStep));
  if (restart_) {
    fields_->resume(restart_->fieldSnapshots);
    if (particleWriter_) particleWriter_->resume(restart_->particleSnapshots);
  }
  // Also without -checkpoint_every/_dt: a run stopped early (signal, wall-time limit) checkpoints.
  checkpoints_ = std::make_unique<CheckpointWriter>(comm, dir, cfg_.checkpoint.keep);
}

void Simulation::compareSetup(const CheckpointReader& cp) const
{
  auto parse = [](const std::string& text) {
    std::map<std::string, std::string> m;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      const std::size_t space = line.find(' ');
      if (space != std::string::npos) m[line.substr(0, space)] = line.substr(space + 1);
    }
    return m;
  };
  if (cp.setupOptions().empty()) return;  // a checkpoint from before the set-up was recorded
  const auto then = parse(cp.setupOptions()), now = parse(setupOptionsText());
  std::string changes;
  for (const auto& [name, value] : now) {
    const auto it = then.find(name);
    if (it != then.end() && it->second != value) changes += " " + name + " " + it->second + " (now " + value + ")";
  }
  if (changes.empty()) return;
  if (!cfg_.checkpoint.allowChanges)
    failOption("-restart", "the checkpoint was written with other set-up options:" + changes +
                               "; give the original values, or -restart_allow_changes to continue with the new ones");
  PetscPrintf(grid_.comm(), "vpsolve: warning: continuing with changed set-up options (-restart_allow_changes):%s\n", changes.c_str());
}

void Simulation::restore(const CheckpointReader& cp)
{
  const RunState& r = cp.run();
  fluid_->loadState(cp, r.dtOld);
  step_ = r.step;
  time_ = r.time;
  penalizationFloor_ = r.penalizationFloor;
  snapshots_.resume(r.lastOutputStep, r.nextOutputTime);
  // A run that did not checkpoint by time before starts counting from here.
  checkpointSchedule_.resume(step_, r.nextCheckpointTime > time_ ? r.nextCheckpointTime : time_ + cfg_.checkpoint.dt);
  restart_ = std::make_unique<RunState>(r);
  PetscPrintf(grid_.comm(), "vpsolve: restart from %s at step %d, t = %.6g s\n", cfg_.checkpoint.restart.c_str(), step_, time_);
}

void Simulation::checkpoint()
{
  if (!checkpoints_) return;
  StageScope stage(Stage::IO);
  for (auto& m : monitors_) m->flush();  // the time series hold every row up to the checkpoint
  checkpointSchedule_.done(step_, time_);
  const double particles = dem_ ? 60.0 * 8 * dem_->diagnostics().particles : 0;
  requireSpace(grid_.comm(), cfg_.output.dir, 11.0 * 8 * grid_.cells() + particles, "the checkpoint of step " + std::to_string(step_));
  RunState r;
  r.step = step_;
  r.time = time_;
  r.dtOld = fluid_->previousDt();
  r.nextOutputTime = snapshots_.nextTime();
  r.nextCheckpointTime = checkpointSchedule_.nextTime();
  r.lastOutputStep = snapshots_.lastStep();
  r.penalizationFloor = penalizationFloor_;
  if (fields_) r.fieldSnapshots = fields_->snapshotList();
  if (particleWriter_) r.particleSnapshots = particleWriter_->snapshotList();
  checkpoints_->write(grid_, cfg_.bc, r, [&](StateWriter& w) {
    fluid_->saveState(w);
    if (dem_) dem_->saveState(w);
  });
}

Simulation::~Simulation() = default;

double Simulation::nextDt() const
{
  return stepControl_.next(time_, fluid_->stats().maxRate, dem_.get(), grid_.comm());
}

void Simulation::buildMask(double dt)
{
  StageScope stage(Stage::Penalization);
  dem_->syncGhosts();
  // lambda's floor: 20 / dt of the step at CFL 0.5 that the motion allows, the largest so far (a
  // stiffness that does not follow the step taken, nor change within a collision: docs/coupling.md).
  const double rate = std::max(fluid_->stats().maxRate, stepControl_.particleRate(dem_.get(), grid_.comm()));
  penalizationFloor_ = std::max(penalizationFloor_, 20 / stepControl_.motionStep(0.5, rate));
  penalization_->build(dem_->particles(), dt, penalizationFloor_);
  if (patches_) patches_->find(dem_->particles());
}

void Simulation::penalize()
{
  StageScope stage(Stage::Penalization);
  penalization_->forces(dem_->particles(), fluid_->velocity(), hydroSums_, patches_.get());
}

void Simulation::hydroForce(double dt)
{
  StageScope stage(Stage::HydroForce);
  // The fluid momentum inside each particle after the projection (the penalization sums are in).
  penalization_->addFluidMomentum(dem_->particles(), fluid_->velocity(), hydroSums_);
  hydroForces(dem_->particles(), dem_->exchange(), hydroSums_, dt, cfg_.fluid.rho, cfg_.gravity);
}

void Simulation::advance(double dt)
{
  if (!cfg_.fluid.off) {
    if (penalization_) {
      // Penalization implicit in the predictor, then the projection: the pressure then blocks the
      // flow through the particles (docs/coupling.md).
      buildMask(dt);
      last_ = fluid_->predict(dt, penalization_->theta(), penalization_->thetaUs());
      // The weighted projection completes the implicit penalized step: its force is taken from
      // u^{n+1} (docs/coupling.md); the plain one leaves the pressure impulse to the momentum term.
      if (!fluid_->weighted()) penalize();
      last_.pressureIterations = fluid_->project(dt);
      if (fluid_->weighted()) penalize();
      hydroForce(dt);
    } else {
      last_ = fluid_->step(dt);
    }
    fluid_->finishStep();
  }
  if (dem_) dem_->advance(time_, dt);
  time_ += dt;
  ++step_;
  pressureIterationsTotal_ += last_.pressureIterations;
}

int Simulation::run()
{
  openOutputs();
  printSetup();
  // A restart continues the previous run's outputs: its snapshots and tracked-particle rows are written.
  if (!restart_) {
    if (snapshots_.on()) output();
    const RunView start = view();
    for (auto& m : monitors_) m->start(start);
  }
  restart_.reset();
  std::string stop;
  int status = 0;
  const double loopStart = MPI_Wtime();
  while (true) {
    if (time_ >= cfg_.time.final * (1 - 1e-12)) {
      stop = "reached -time_final";
      break;
    }
    if (step_ >= cfg_.time.maxSteps) {
      stop = "reached -time_max_steps";
      break;
    }
    const double dt = nextDt();
    const double t0 = MPI_Wtime();
    try {
      advance(dt);
    } catch (const StepFailure& e) {
      // Decided collectively. The state is half-advanced: no snapshot of it (the earlier ones stay).
      stopOnFailure("in the step of dt = " + formatNumber(dt) + " s to t = " + formatNumber(time_ + dt) + " s: " + e.what(),
                    loopStart, false);
    }
    wallLastStep_ = MPI_Wtime() - t0;
    if (step_ % cfg_.output.seriesEvery == 0) record();
    const StepVerdict v = guard_.check(dt, fluid_->stats(), dem_.get(), MPI_Wtime() - wallStart_, wallLastStep_);
    if (!v.problem.empty()) stopOnFailure(v.problem, loopStart, true);
    if (cfg_.output.monitorEvery > 0 && step_ % cfg_.output.monitorEvery == 0) {
      monitor(dt);
      for (auto& m : monitors_) m->flush();  // a running case's particle_<id>.csv can be followed too
    }
    if (snapshots_.due(step_, time_)) output();
    if (checkpointSchedule_.due(step_, time_)) checkpoint();
    if (v.signal) {
      stop = std::string("signal ") + (v.signal == SIGTERM ? "SIGTERM" : v.signal == SIGINT ? "SIGINT" : std::to_string(v.signal));
      status = 128 + v.signal;
      break;
    }
    if (v.wallLimit) {
      stop = "reached -time_wall_limit";
      break;
    }
    for (auto& m : monitors_)
      if (stop.empty()) stop = m->stopRequest();
    if (!stop.empty()) break;
  }
  loopWall_ = MPI_Wtime() - loopStart;
  if (recordedStep_ != step_ && step_ > firstStep_) record();  // the time series end with the final state
  if (snapshots_.lastStep() != step_) output();  // always the final state
  const bool early = status != 0 || stop == "reached -time_wall_limit";
  if ((checkpointSchedule_.on() || early) && checkpointSchedule_.lastStep() != step_) checkpoint();
  for (auto& m : monitors_) m->flush();
  const RunView last = view();
  for (auto& m : monitors_) m->finish(last);
  finish(stop);
  return status;
}

void Simulation::stopOnFailure(const std::string& problem, double loopStart, bool snapshot)
{
  snapshot = snapshot && snapshots_.lastStep() != step_;
  if (snapshot && recordedStep_ != step_) record();  // the row of the step that failed a check
  if (snapshot) output();  // the completed step that failed a check, for inspection
  loopWall_ = MPI_Wtime() - loopStart;
  finish("failed: " + problem);
  throw RunFailure(snapshot ? "the run stopped (above); the snapshot of step " + std::to_string(step_) + " is written for inspection"
                            : "the run stopped (above); the outputs of the last completed step are kept");
}

void Simulation::record()
{
  recordedStep_ = step_;
  const RunView now = view();
  for (auto& m : monitors_) m->record(now);
}

RunView Simulation::view() const
{
  RunView v;
  v.step = step_;
  v.time = time_;
  v.wallTime = MPI_Wtime() - wallStart_;
  v.fluid = fluid_.get();
  v.solvers = &last_;
  v.dem = dem_.get();
  return v;
}

void Simulation::output()
{
  if (!fields_) return;
  StageScope stage(Stage::IO);
  const double particles = dem_ ? 20.0 * 8 * dem_->diagnostics().particles : 0;
  requireSpace(grid_.comm(), cfg_.output.dir, (cfg_.fluid.off ? 0 : 5.0 * 8 * grid_.cells()) + particles,
               "the snapshot of step " + std::to_string(step_));
  if (!cfg_.fluid.off)
    fields_->write(step_, time_, fluid_->velocityLocal(), fluid_->pressure(), penalization_ ? penalization_->chi() : nullptr);
  if (particleWriter_) particleWriter_->write(dem_->particles(), step_, time_);
  snapshots_.done(step_, time_);
}

void Simulation::monitor(double dt) const
{
  const auto& s = fluid_->stats();
  const double elapsed = MPI_Wtime() - wallStart_;
  const double perStep = elapsed / std::max(step_ - firstStep_, 1);
  const double byTime = time_ > firstTime_ ? elapsed / (time_ - firstTime_) * (cfg_.time.final - time_) : 0;
  const double bySteps = perStep * (cfg_.time.maxSteps - step_);
  const std::string eta = hms(std::min(byTime, bySteps));
  if (cfg_.fluid.off) {
    const DemDiagnostics d = dem_->diagnostics();
    PetscPrintf(grid_.comm(), "step %6d  t %.4e  dt %.3e  particle KE %.4e J  contacts %ld  wall contacts %ld  %.2e s/step  ETA %s\n",
                step_, time_, dt, d.kineticEnergy, d.contacts, d.wallContacts, wallLastStep_, eta.c_str());
    return;
  }
  PetscPrintf(grid_.comm(), "step %6d  t %.4e  dt %.3e  cfl %.3f  p_its %3d  v_its %3d  max|div u| %.2e  %.3f s/step  ETA %s\n",
              step_, time_, dt, dt * s.maxRate, last_.pressureIterations, last_.velocityIterations, s.maxDivergence,
              wallLastStep_, eta.c_str());
}

void Simulation::printSetup() const
{
  int size;
  MPI_Comm_size(grid_.comm(), &size);
  PetscInt m, n, p;
  VP_CALL(DMDAGetInfo(grid_.cellDM(), nullptr, nullptr, nullptr, nullptr, &m, &n, &p, nullptr, nullptr, nullptr,
                      nullptr, nullptr, nullptr));
  PetscPrintf(grid_.comm(), "vpsolve: grid %d x %d x %d cells (%ld), h = %.4g, %.4g, %.4g m, %d ranks as %d x %d x %d\n",
              grid_.n(0), grid_.n(1), grid_.n(2), grid_.cells(), grid_.h(0), grid_.h(1), grid_.h(2), size, int(m),
              int(n), int(p));
  PetscPrintf(grid_.comm(), "vpsolve: boundaries x %s/%s  y %s/%s  z %s/%s; rho %g kg/m^3, mu %g Pa s; until t = %g s or %d steps\n",
              bcName(cfg_.bc.type[0]), bcName(cfg_.bc.type[1]), bcName(cfg_.bc.type[2]), bcName(cfg_.bc.type[3]),
              bcName(cfg_.bc.type[4]), bcName(cfg_.bc.type[5]), cfg_.fluid.rho, cfg_.fluid.mu, cfg_.time.final,
              cfg_.time.maxSteps);
}

void Simulation::finish(const std::string& stopReason)
{
  const MPI_Comm comm = grid_.comm();
  const double wall = MPI_Wtime() - wallStart_;
  const int steps = step_ - firstStep_;  // of this run (a restart continues the count)
  PetscPrintf(comm, "vpsolve: stopped at step %d, t = %.6g s: %s\n", step_, time_, stopReason.c_str());
  if (!cfg_.fluid.off)
    PetscPrintf(comm, "vpsolve: %d steps to t = %.6g s in %.2f s (%.4f s/step, %.3f us per cell and step); "
                "mean pressure iterations %.1f; kinetic energy %.6e J\n",
                steps, time_, wall, wall / std::max(steps, 1), wall / std::max(steps, 1) / grid_.cells() * 1e6,
                double(pressureIterationsTotal_) / std::max(steps, 1), cfg_.fluid.rho * fluid_->stats().kineticEnergy);
  RunEnd end;
  end.stopReason = stopReason;
  end.step = step_;
  end.stepsThisRun = steps;
  end.time = time_;
  end.wallSeconds = wall;
  end.loopSeconds = loopWall_;
  end.fluid = !cfg_.fluid.off;
  end.kineticEnergy = cfg_.fluid.rho * fluid_->stats().kineticEnergy;
  if (dem_) {
    const DemDiagnostics d = dem_->diagnostics();
    end.particles = true;
    end.particlesAtStart = particlesAtStart_;
    end.particleCount = d.particles;
    end.particleKineticEnergy = d.kineticEnergy;
    const double particleSteps = double(d.particles) * steps * particleCfg_.substeps;
    PetscPrintf(comm, "vpsolve: DEM %ld particles (%ld at the start of this run), %d x %d sub-steps, loop time %.3f s, "
                "%.4g particle-steps/s, %zu neighbour-list rebuilds; particle kinetic energy %.6e J\n",
                d.particles, particlesAtStart_, steps, particleCfg_.substeps, loopWall_, particleSteps / loopWall_, dem_->rebuilds(),
                d.kineticEnergy);
    // Particle traffic between ranks (migration, ghosts, ghost updates, hydrodynamic partial sums).
    double traffic[2] = {double(dem_->exchange().messagesSent()), dem_->exchange().bytesSent()};
    MPI_Allreduce(MPI_IN_PLACE, traffic, 2, MPI_DOUBLE, MPI_SUM, comm);
    PetscPrintf(comm, "vpsolve: particle exchange between ranks: %.0f messages, %.4g MB (all ranks)\n", traffic[0],
                traffic[1] / 1e6);
  }
  // Stage timings: the slowest rank's seconds per stage.
  PetscPrintf(comm, "vpsolve: stage timings (slowest rank)   seconds   %% of run    ms/step\n");
  for (int k = 0; k < static_cast<int>(Stage::Count); ++k) {
    double t = stageSeconds(static_cast<Stage>(k));
    MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, comm);
    if (t == 0) continue;
    PetscPrintf(comm, "vpsolve:   %-30s %9.3f %9.1f %11.3f\n", stageName(static_cast<Stage>(k)), t,
                100 * t / std::max(wall, 1e-30), 1e3 * t / std::max(steps, 1));
    end.stageSeconds.emplace_back(stageName(static_cast<Stage>(k)), t);
  }
  if (!fields_) return;
  try {
    writeRunRecord(comm, cfg_.output.dir, runEndJson(end));
  } catch (const std::runtime_error& e) {  // a full disk: the start record stays
    PetscPrintf(comm, "vpsolve: warning: %s\n", e.what());
  }
}

} // namespace vp
