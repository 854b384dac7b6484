#include "vp/core/Config.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include <cmath>
#include <petscsys.h>
#include <vector>

namespace vp {

namespace {

const char* const kFaceNames[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
const char* const kBcNames[4] = {"wall", "slip", "periodic", "velocity"};
const char* const kInitNames[5] = {"rest", "taylor_green", "abc", "poiseuille", "couette"};

std::vector<std::string> names(const char* const* v, int n) { return {v, v + n}; }

} // namespace

const char* bcName(BcType t) { return kBcNames[static_cast<int>(t)]; }

Config Config::read()
{
  Config c;
  {
    OptionGroup o("Grid: uniform 3-D box");
    const Vec3 n = o.vec3("-grid_n", {32, 32, 32}, "Cells per axis nx,ny,nz");
    for (int d = 0; d < 3; ++d) {
      if (!optionsHelpMode() && (n[d] != std::floor(n[d]) || std::fabs(n[d]) > 1e9)) failOption("-grid_n", "needs whole numbers of cells, got " + formatNumber(n[d]));
      c.grid.n[d] = static_cast<int>(n[d]);
    }
    const Vec3 lo = o.vec3("-grid_lo", {0, 0, 0}, "Lower corner x,y,z of the domain (m)");
    const Vec3 hi = o.vec3("-grid_hi", {1, 1, 1}, "Upper corner x,y,z of the domain (m)");
    for (int d = 0; d < 3; ++d) {
      c.grid.lo[d] = lo[d];
      c.grid.hi[d] = hi[d];
    }
  }
  {
    OptionGroup o("Parallel decomposition", false);
    const Vec3 ranks = o.vec3("-grid_ranks", {0, 0, 0},
                              "Ranks per axis px,py,pz, their product the number of ranks; 0,0,0: slabs along z with "
                              "-pressure_pc_type fft (the solver's own layout), else PETSc's split");
    for (int d = 0; d < 3; ++d) {
      if (!optionsHelpMode() && (ranks[d] != std::floor(ranks[d]) || ranks[d] < 0 || ranks[d] > 1e6))
        failOption("-grid_ranks", "needs whole numbers >= 0, got " + formatNumber(ranks[d]));
      c.grid.ranks[d] = static_cast<int>(ranks[d]);
    }
  }
  {
    OptionGroup o("Boundary conditions per face: wall|slip|periodic|velocity");
    for (int f = 0; f < 6; ++f) {
      const std::string opt = std::string("-bc_") + kFaceNames[f];
      const std::string help = std::string("Boundary type of the ") + kFaceNames[f] + " face";
      c.bc.type[f] = static_cast<BcType>(o.choice(opt.c_str(), names(kBcNames, 4), 0, help.c_str()));
      c.bc.velocity[f] = o.vec3((opt + "_velocity").c_str(), {}, "Wall velocity u,v,w of a 'velocity' face (m/s)");
    }
  }
  {
    OptionGroup o("Fluid");
    c.fluid.off = o.flag("-fluid_off", false, "Run without fluid (DEM only)");
    c.fluid.rho = o.real("-fluid_rho", c.fluid.rho, "Fluid density (kg/m^3)");
    c.fluid.mu = o.real("-fluid_mu", c.fluid.mu, "Fluid dynamic viscosity (Pa s)");
    c.fluid.bodyForce = o.vec3("-fluid_body_force", {}, "Body force per unit mass on the fluid ax,ay,az (m/s^2)");
    c.gravity = o.vec3("-gravity", {}, "Gravity gx,gy,gz (m/s^2); balanced by hydrostatic pressure in the fluid");
    c.fluid.init = static_cast<InitFlow>(o.choice("-init_flow", names(kInitNames, 5), 0, "Initial flow"));
    c.fluid.initVelocity = o.real("-init_velocity", c.fluid.initVelocity, "Velocity amplitude of the analytic initial flows (m/s)");
  }
  {
    OptionGroup o("Time stepping", false);
    c.time.final = o.real("-time_final", c.time.final, "End time (s)");
    c.time.maxSteps = o.integer("-time_max_steps", c.time.maxSteps, "Maximum number of fluid steps");
    c.time.cfl = o.real("-time_cfl", c.time.cfl, "Target CFL number, dt = cfl * min(h / |u_max|)");
    c.time.dtMax = o.real("-time_dt_max", c.time.dtMax, "Largest time step (s); 0: min(h)^2 / nu or -time_final / 10, the smaller");
    c.time.dt = o.real("-time_dt", c.time.dt, "Fixed time step (s); 0: CFL-adaptive");
    c.time.wallLimit = o.real("-time_wall_limit", 0, "Wall-clock limit (s; 0: none): the run stops with a checkpoint at the step "
                                                     "boundary before it (leave a margin for the checkpoint)");
  }
  {
    OptionGroup o("Health checks after every step (a failed check stops the run with a snapshot)", false);
    c.health.cflMax = o.real("-health_cfl_max", c.health.cflMax, "Largest CFL number accepted with a fixed -time_dt");
    c.health.overlapMax = o.real("-health_overlap_max", c.health.overlapMax, "Largest contact overlap, fraction of the smaller diameter");
  }
  {
    OptionGroup o("Output", false);
    c.output.dir = o.text("-output_dir", c.output.dir, "Directory for fields, particles, diagnostics");
    c.output.every = o.integer("-output_every", c.output.every, "Steps between field snapshots (0: none)");
    c.output.dt = o.real("-output_dt", c.output.dt, "Simulated time between field snapshots (s; 0: none)");
    c.output.monitorEvery = o.integer("-monitor_every", c.output.monitorEvery, "Steps between progress lines (0: none)");
    c.output.seriesEvery = o.integer("-series_every", c.output.seriesEvery,
                                     "Steps between rows of diagnostics.csv, probes.csv and particle_<id>.csv (the last step always)");
    c.output.overwrite = o.flag("-output_overwrite", false, "Replace the outputs of another run found in -output_dir");
    const std::vector<double> probes = o.realList("-probe", "Pressure probes x,y,z[,x,y,z...] (m): probes.csv, one row per step");
    if (probes.size() % 3 && !optionsHelpMode()) failOption("-probe", "needs x,y,z per probe (a multiple of 3 values), got " + std::to_string(probes.size()));
    for (std::size_t k = 0; k + 2 < probes.size(); k += 3) c.output.probes.push_back({probes[k], probes[k + 1], probes[k + 2]});
  }
  {
    OptionGroup o("Checkpoint/restart", false);
    c.checkpoint.restart = o.text("-restart", "", "Continue from this checkpoint (checkpoint_<step>.h5 or checkpoint_latest.h5); "
                                                 "particles come from it, grid and boundaries must match");
    c.checkpoint.every = o.integer("-checkpoint_every", c.checkpoint.every, "Steps between checkpoints (0: none)");
    c.checkpoint.dt = o.real("-checkpoint_dt", c.checkpoint.dt, "Simulated time between checkpoints (s; 0: none)");
    c.checkpoint.keep = o.integer("-checkpoint_keep", c.checkpoint.keep, "Checkpoints kept in the output directory, newest first (with those of a restarted run's earlier pieces)");
    c.checkpoint.allowChanges = o.flag("-restart_allow_changes", false, "Continue a checkpoint whose set-up options differ "
                                                                        "(physics, particles) with a warning instead of an error");
  }
  return c;
}

void Config::validate() const
{
  const char* axis = "xyz";
  for (int d = 0; d < 3; ++d) {
    if (grid.n[d] < 1) failOption("-grid_n", std::string("cells along ") + axis[d] + " must be >= 1, got " + std::to_string(grid.n[d]));
    if (!(grid.hi[d] > grid.lo[d]))
      failOption("-grid_hi", std::string("upper corner must exceed -grid_lo along ") + axis[d] + " (" + formatNumber(grid.hi[d]) + " <= " + formatNumber(grid.lo[d]) + ")");
    if (!bc.periodic(d) && grid.n[d] < 2)
      failOption("-grid_n", std::string("a wall-bounded axis needs >= 2 cells, ") + axis[d] + " has " + std::to_string(grid.n[d]));
    bool plo = bc.type[2 * d] == BcType::Periodic, phi = bc.type[2 * d + 1] == BcType::Periodic;
    if (plo != phi)
      failOption(std::string("-bc_") + kFaceNames[2 * d + (plo ? 1 : 0)],
           std::string("periodic must be set on both ") + axis[d] + " faces (-bc_" + kFaceNames[2 * d] + " and -bc_" + kFaceNames[2 * d + 1] + ")");
  }
  // Face vectors have 3 (n+1)^3 entries: they must fit PETSc's index type.
  const double faces = 3.0 * (grid.n[0] + 1.0) * (grid.n[1] + 1.0) * (grid.n[2] + 1.0);
  if (faces > double(PETSC_MAX_INT))
    failOption("-grid_n", std::to_string(grid.n[0]) + "," + std::to_string(grid.n[1]) + "," + std::to_string(grid.n[2]) +
                        " needs " + formatNumber(faces) + " face unknowns, more than this PETSc build indexes (" +
                        std::to_string(PETSC_MAX_INT) + "; a 64-bit-index PETSc would be needed)");
  for (int f = 0; f < 6; ++f) {
    const Vec3& v = bc.velocity[f];
    if (bc.type[f] != BcType::Velocity && (v.x != 0 || v.y != 0 || v.z != 0))
      failOption(std::string("-bc_") + kFaceNames[f] + "_velocity", std::string("only allowed when -bc_") + kFaceNames[f] + " velocity");
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      failOption(std::string("-bc_") + kFaceNames[f] + "_velocity", "must be finite");
  }
  if (!(fluid.rho > 0) || !std::isfinite(fluid.rho)) failOption("-fluid_rho", "must be > 0, got " + formatNumber(fluid.rho));
  if (!(fluid.mu > 0) || !std::isfinite(fluid.mu)) failOption("-fluid_mu", "must be > 0, got " + formatNumber(fluid.mu));
  if (!(time.final > 0)) failOption("-time_final", "must be > 0, got " + formatNumber(time.final));
  if (time.maxSteps < 0) failOption("-time_max_steps", "must be >= 0, got " + std::to_string(time.maxSteps));
  if (!(time.cfl > 0 && time.cfl <= 1)) failOption("-time_cfl", "must be in (0, 1], got " + formatNumber(time.cfl));
  if (!(time.dtMax >= 0)) failOption("-time_dt_max", "must be >= 0, got " + formatNumber(time.dtMax));
  if (!(time.dt >= 0)) failOption("-time_dt", "must be >= 0, got " + formatNumber(time.dt));
  if (output.every < 0) failOption("-output_every", "must be >= 0 (0: no snapshots), got " + std::to_string(output.every));
  if (!(output.dt >= 0)) failOption("-output_dt", "must be >= 0 (0: no snapshots), got " + formatNumber(output.dt));
  if (output.monitorEvery < 0) failOption("-monitor_every", "must be >= 0, got " + std::to_string(output.monitorEvery));
  if (output.seriesEvery < 1) failOption("-series_every", "must be >= 1, got " + std::to_string(output.seriesEvery));
  if (output.dir.empty()) failOption("-output_dir", "must not be empty");
  for (std::size_t p = 0; p < output.probes.size(); ++p)
    for (int d = 0; d < 3; ++d)
      if (!(output.probes[p][d] >= grid.lo[d] && output.probes[p][d] <= grid.hi[d]))
        failOption("-probe", "probe " + std::to_string(p) + " at " + std::string("xyz").substr(d, 1) + " = " +
                                 formatNumber(output.probes[p][d]) + " lies outside the domain [" + formatNumber(grid.lo[d]) +
                                 ", " + formatNumber(grid.hi[d]) + "]");
  if (checkpoint.every < 0) failOption("-checkpoint_every", "must be >= 0 (0: no checkpoints), got " + std::to_string(checkpoint.every));
  if (!(checkpoint.dt >= 0)) failOption("-checkpoint_dt", "must be >= 0 (0: no checkpoints), got " + formatNumber(checkpoint.dt));
  if (!(time.wallLimit >= 0)) failOption("-time_wall_limit", "must be >= 0 (0: none), got " + formatNumber(time.wallLimit));
  if (!(health.cflMax > 0)) failOption("-health_cfl_max", "must be > 0, got " + formatNumber(health.cflMax));
  if (!(health.overlapMax > 0 && health.overlapMax <= 1)) failOption("-health_overlap_max", "must be in (0, 1], got " + formatNumber(health.overlapMax));
  if (checkpoint.keep < 1) failOption("-checkpoint_keep", "must be >= 1, got " + std::to_string(checkpoint.keep));
  if (fluid.init == InitFlow::TaylorGreen || fluid.init == InitFlow::Abc) {
    bool needZ = fluid.init == InitFlow::Abc;
    if (!bc.periodic(0) || !bc.periodic(1) || (needZ && !bc.periodic(2)))
      failOption("-init_flow", std::string(fluid.init == InitFlow::Abc ? "abc needs periodic x, y and z" : "taylor_green needs periodic x and y"));
  }
  if (fluid.init == InitFlow::Poiseuille && (bc.periodic(1) || !bc.periodic(0)))
    failOption("-init_flow", "poiseuille needs periodic x and walls in y");
  if (fluid.init == InitFlow::Couette && (bc.type[4] != BcType::Velocity || bc.type[5] != BcType::Velocity))
    failOption("-init_flow", "couette needs moving walls in z (-bc_zlo velocity, -bc_zhi velocity)");
}

} // namespace vp
