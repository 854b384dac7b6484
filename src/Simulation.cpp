#include "vp/Simulation.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Logging.hpp"
#include "vp/coupling/HydroForce.hpp"
#include "vp/fluid/AnalyticFlow.hpp"
#include "vp/grid/Boundary.hpp"
#include <algorithm>
#include <cmath>

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

Simulation::Simulation(MPI_Comm comm, const Config& cfg)
  : cfg_(cfg), grid_(comm, cfg.grid, cfg.bc), particleCfg_(ParticleConfig::fromOptions(comm))
{
  wallStart_ = MPI_Wtime();
  if (cfg_.fluid.off && !particleCfg_.any())
    throw InputError("option -fluid_off: a DEM-only run needs particles (-particles_file, -particles_lattice, -particles_random or -particle_position)");
  std::unique_ptr<CheckpointReader> restart;
  if (!cfg_.checkpoint.restart.empty()) {
    restart = std::make_unique<CheckpointReader>(comm, cfg_.checkpoint.restart, cfg_);
    const std::size_t n = restart->particles().size();
    if ((n > 0) != particleCfg_.any())
      failOption("-restart", n > 0 ? "the checkpoint holds " + std::to_string(n) + " particles: give the original run's particle options "
                                     "too (the particles come from the checkpoint, the contact and lubrication options from the command line)"
                                   : "the checkpoint holds no particles, but particle options are given");
  }
  // Read (and listed by -help) even without particles.
  const PenalizationConfig penalizationCfg = PenalizationConfig::fromOptions(comm);
  if (particleCfg_.any() && !cfg_.fluid.off) {
    penalization_ = std::make_unique<Penalization>(grid_, penalizationCfg, cfg_.fluid.rho, cfg_.fluid.nu());
    particleCfg_.maskSupport = penalization_->support();
  }
  if (restart && particleCfg_.any())
    dem_ = std::make_unique<DemSolver>(grid_, cfg_, particleCfg_, restart->particles(), true);
  else if (particleCfg_.any())
    dem_ = std::make_unique<DemSolver>(grid_, cfg_, particleCfg_);
  fluid_ = std::make_unique<Projection>(grid_, cfg_);
  if (restart)
    restore(*restart);
  else {
    AnalyticFlow flow(cfg_);
    sampleVelocity(grid_, flow, 0, fluid_->velocity());
    samplePressure(grid_, flow, 0, fluid_->pressure());
    fluid_->applyBoundaryConditions();
    nextCheckpointTime_ = cfg_.checkpoint.dt;
  }
  if (penalization_) {
    buildMask(0);
    hydroSums_.assign(kHydroSums * dem_->particles().size(), 0.0);
    if (!restart) hydroForce(0);  // a restart has the fluid momentum inside each particle
  }
  if (cfg_.output.files) {
    makeOutputDir(comm, cfg_.output.dir);
    fields_ = std::make_unique<FieldWriter>(grid_, cfg_.output.dir);
    std::vector<std::string> columns{"step", "time", "dt", "cfl", "pressure_iterations", "max_divergence",
                                     "kinetic_energy", "wall_time", "velocity_iterations", "mean_u", "mean_v", "mean_w"};
    // A restart continues the time series after the checkpoint's row (dropping later ones).
    const double resumeStep = restart ? step_ : -1, resumeTime = restart ? time_ : -1;
    if (dem_) {
      for (const char* c : {"particle_kinetic_energy", "contacts", "wall_contacts"}) columns.push_back(c);
      particleWriter_ = std::make_unique<ParticleWriter>(comm, cfg_.output.dir);
      tracker_ = std::make_unique<ParticleTracker>(comm, cfg_.output.dir, particleCfg_, dem_->particles(), resumeTime);
    }
    diagnostics_ = std::make_unique<CsvWriter>(comm, cfg_.output.dir + "/diagnostics.csv", columns, resumeStep);
    if (restart) {
      fields_->resume(restart->run().fieldSnapshots);
      if (particleWriter_) particleWriter_->resume(restart->run().particleSnapshots);
    }
    if (cfg_.checkpoint.on()) checkpoints_ = std::make_unique<CheckpointWriter>(comm, cfg_.output.dir, cfg_.checkpoint.keep);
  }
  firstStep_ = step_;
  firstTime_ = time_;
}

void Simulation::restore(const CheckpointReader& cp)
{
  const RunState& r = cp.run();
  cp.loadFluid(fluidState());
  fluid_->setPreviousDt(r.dtOld);
  fluid_->finishStep();
  step_ = r.step;
  time_ = r.time;
  nextOutputTime_ = r.nextOutputTime;
  lastOutputStep_ = r.lastOutputStep;
  // A run that did not checkpoint by time before starts counting from here.
  nextCheckpointTime_ = r.nextCheckpointTime > time_ ? r.nextCheckpointTime : time_ + cfg_.checkpoint.dt;
  lastCheckpointStep_ = step_;
  PetscPrintf(grid_.comm(), "vpsolve: restart from %s at step %d, t = %.6g s\n", cfg_.checkpoint.restart.c_str(), step_, time_);
}

FluidState Simulation::fluidState() const
{
  return {fluid_->velocity(), fluid_->pressure(), fluid_->convectionOld(), fluid_->pressureIncrement(),
          fluid_->velocityIncrement()};
}

void Simulation::checkpoint()
{
  if (!checkpoints_) return;
  StageScope stage(Stage::IO);
  if (tracker_) tracker_->flush();  // the time series hold every row up to the checkpoint
  if (cfg_.checkpoint.dt > 0)
    while (nextCheckpointTime_ <= time_ * (1 + 1e-12)) nextCheckpointTime_ += cfg_.checkpoint.dt;
  RunState r;
  r.step = step_;
  r.time = time_;
  r.dtOld = fluid_->previousDt();
  r.nextOutputTime = nextOutputTime_;
  r.nextCheckpointTime = nextCheckpointTime_;
  r.lastOutputStep = lastOutputStep_;
  if (fields_) r.fieldSnapshots = fields_->snapshotList();
  if (particleWriter_) r.particleSnapshots = particleWriter_->snapshotList();
  checkpoints_->write(grid_, cfg_.bc, r, fluidState(),
                      dem_ ? dem_->ownedRecords() : std::vector<ParticleRecord>{});
  lastCheckpointStep_ = step_;
}

Simulation::~Simulation() = default;

double Simulation::particleRate() const
{
  if (!dem_) return 0;
  const ParticleStore& s = dem_->particles();
  double rate = 0;
  for (std::size_t i = 0; i < s.nOwned; ++i)
    for (int c = 0; c < 3; ++c) rate = std::max(rate, (std::fabs(s.v[i][c]) + norm(s.w[i]) * s.radius[i]) / grid_.h(c));
  double global = 0;
  MPI_Allreduce(&rate, &global, 1, MPI_DOUBLE, MPI_MAX, grid_.comm());
  return global;
}

double Simulation::nextDt() const
{
  double dt = cfg_.time.dt;
  // DEM only: the step is -dem_substeps stable DEM steps.
  if (dt <= 0 && cfg_.fluid.off) dt = dem_->suggestedStep() * particleCfg_.substeps;
  if (dt <= 0) {
    const double hmin = std::min({grid_.h(0), grid_.h(1), grid_.h(2)});
    dt = cfg_.time.dtMax > 0 ? cfg_.time.dtMax : hmin * hmin / cfg_.fluid.nu();
    // Moving walls count too: they set the flow in motion from rest.
    double rate = std::max(fluid_->stats().maxRate, particleRate());
    for (int f = 0; f < 6; ++f)
      for (int c = 0; c < 3; ++c) rate = std::max(rate, std::fabs(wallVelocity(cfg_.bc, f)[c]) / grid_.h(c));
    if (rate > 0) dt = std::min(dt, cfg_.time.cfl / rate);
    // Particles released from rest: a step may not let gravity move them more than cfl cells.
    const double g = norm(cfg_.gravity);
    if (dem_ && g > 0) dt = std::min(dt, std::sqrt(2 * cfg_.time.cfl * hmin / g));
    // The saturated lubrication is an explicit dashpot in the DEM sub-steps.
    if (dem_) dt = std::min(dt, dem_->lubricationStepLimit());
  }
  const double left = cfg_.time.final - time_;
  // Land on -time_final exactly instead of leaving a sliver of a step.
  if (dt > left || left - dt < 1e-9 * dt) dt = left;
  return dt;
}

void Simulation::buildMask(double dt)
{
  StageScope stage(Stage::Penalization);
  dem_->syncGhosts();
  penalization_->build(dem_->particles(), dt);
}

void Simulation::penalize()
{
  StageScope stage(Stage::Penalization);
  penalization_->forces(dem_->particles(), fluid_->velocity(), hydroSums_);
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
      penalize();
      last_.pressureIterations = fluid_->project(dt);
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

void Simulation::run()
{
  printSetup();
  const bool snapshots = cfg_.output.every > 0 || cfg_.output.dt > 0;
  // A restart continues the previous run's outputs: its snapshots and tracker rows are written.
  const bool restarted = !cfg_.checkpoint.restart.empty();
  if (snapshots && !restarted) output();
  if (tracker_ && !restarted) tracker_->record(dem_->particles(), time_);
  const double loopStart = MPI_Wtime();
  while (time_ < cfg_.time.final * (1 - 1e-12) && step_ < cfg_.time.maxSteps) {
    const double dt = nextDt();
    const double t0 = MPI_Wtime();
    advance(dt);
    wallLastStep_ = MPI_Wtime() - t0;
    const auto& s = fluid_->stats();
    std::vector<double> row{double(step_), time_, dt, dt * s.maxRate, double(last_.pressureIterations), s.maxDivergence,
                            cfg_.fluid.rho * s.kineticEnergy, MPI_Wtime() - wallStart_, double(last_.velocityIterations),
                            s.meanVelocity.x, s.meanVelocity.y, s.meanVelocity.z};
    if (dem_) {
      const DemDiagnostics d = dem_->diagnostics();
      row.insert(row.end(), {d.kineticEnergy, double(d.contacts), double(d.wallContacts)});
      if (tracker_) tracker_->record(dem_->particles(), time_);
    }
    if (diagnostics_) diagnostics_->row(row);
    if (!std::isfinite(s.kineticEnergy))
      throw std::runtime_error("the flow blew up at step " + std::to_string(step_) + " (non-finite velocity); reduce -time_cfl or -time_dt_max");
    if (cfg_.output.monitorEvery > 0 && step_ % cfg_.output.monitorEvery == 0) {
      monitor(dt);
      if (tracker_) tracker_->flush();  // a running case's particle_<id>.csv can be followed too
    }
    const bool due = (cfg_.output.every > 0 && step_ % cfg_.output.every == 0) ||
                     (cfg_.output.dt > 0 && time_ >= nextOutputTime_ * (1 - 1e-12));
    if (due) output();
    const bool checkpointDue = (cfg_.checkpoint.every > 0 && step_ % cfg_.checkpoint.every == 0) ||
                               (cfg_.checkpoint.dt > 0 && time_ >= nextCheckpointTime_ * (1 - 1e-12));
    if (checkpointDue) checkpoint();
  }
  loopWall_ = MPI_Wtime() - loopStart;
  if (snapshots && lastOutputStep_ != step_) output();
  if (lastCheckpointStep_ != step_) checkpoint();  // the end state, to continue the run later
  if (tracker_) tracker_->flush();
  printSummary();
}

void Simulation::output()
{
  if (!fields_) return;
  StageScope stage(Stage::IO);
  if (!cfg_.fluid.off)
    fields_->write(step_, time_, fluid_->velocityLocal(), fluid_->pressure(), penalization_ ? penalization_->chi() : nullptr);
  if (particleWriter_) particleWriter_->write(dem_->particles(), step_, time_);
  lastOutputStep_ = step_;
  if (cfg_.output.dt > 0)
    while (nextOutputTime_ <= time_ * (1 + 1e-12)) nextOutputTime_ += cfg_.output.dt;
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

void Simulation::printSummary() const
{
  const double wall = MPI_Wtime() - wallStart_;
  const int steps = step_ - firstStep_;  // of this run (a restart continues the count)
  if (!cfg_.fluid.off)
    PetscPrintf(grid_.comm(), "vpsolve: %d steps to t = %.6g s in %.2f s (%.4f s/step, %.3f us per cell and step); "
              "mean pressure iterations %.1f; kinetic energy %.6e J\n",
              steps, time_, wall, wall / std::max(steps, 1), wall / std::max(steps, 1) / grid_.cells() * 1e6,
              double(pressureIterationsTotal_) / std::max(steps, 1), cfg_.fluid.rho * fluid_->stats().kineticEnergy);
  if (dem_) {
    const DemDiagnostics d = dem_->diagnostics();
    const double particleSteps = double(d.particles) * steps * particleCfg_.substeps;
    PetscPrintf(grid_.comm(), "vpsolve: DEM %ld particles, %d x %d sub-steps, loop time %.3f s, %.4g particle-steps/s, "
                "%zu neighbour-list rebuilds; particle kinetic energy %.6e J\n",
                d.particles, steps, particleCfg_.substeps, loopWall_, particleSteps / loopWall_, dem_->rebuilds(),
                d.kineticEnergy);
  }
}

} // namespace vp
