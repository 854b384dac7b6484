#pragma once
// The fluid, grid, time and output part of the run configuration (the whole of it is RunConfig,
// include/vp/RunConfig.hpp). read() parses the options (vp/core/Options.hpp); validate() checks
// ranges and consistency and raises vp::InputError naming the option and the valid range.
#include "vp/core/Vec3.hpp"
#include <array>
#include <mpi.h>
#include <string>
#include <vector>

namespace vp {

enum class BcType { Wall, Slip, Periodic, Velocity };
const char* bcName(BcType t);

struct GridConfig {
  std::array<int, 3> n{32, 32, 32};        // cells per axis
  std::array<double, 3> lo{0, 0, 0};       // domain box [m]
  std::array<double, 3> hi{1, 1, 1};
  // Ranks per axis (-grid_ranks); 0,0,0: z slabs with the fft pressure solver (its own layout, so
  // the pressure needs no redistribution), else PETSc's split (RunConfig::resolveDefaults).
  std::array<int, 3> ranks{0, 0, 0};

  double spacing(int d) const { return (hi[d] - lo[d]) / n[d]; }  // uniform cell size along axis d [m]
};

// Boundary condition on each of the six faces, index 2*axis + side (side 0 = low, 1 = high).
struct BoundaryConfig {
  std::array<BcType, 6> type{BcType::Wall, BcType::Wall, BcType::Wall,
                             BcType::Wall, BcType::Wall, BcType::Wall};
  std::array<Vec3, 6> velocity{};          // wall velocity (only for BcType::Velocity) [m/s]
  bool periodic(int axis) const { return type[2 * axis] == BcType::Periodic; }
};

enum class InitFlow { Rest, TaylorGreen, Abc, Poiseuille, Couette };

struct FluidConfig {
  bool off = false;                        // -fluid_off: DEM only
  double rho = 1.0;                        // density [kg/m^3]
  double mu = 1e-3;                        // dynamic viscosity [Pa s]
  Vec3 bodyForce{};                        // acceleration acting on the fluid [m/s^2]
  InitFlow init = InitFlow::Rest;
  double initVelocity = 1.0;               // amplitude of the analytic initial flows [m/s]
  double nu() const { return mu / rho; }
};

struct TimeConfig {
  double final = 1.0;                      // end time [s]
  int maxSteps = 1000000;
  double cfl = 0.5;
  double dtMax = 0;                        // 0: min(h^2 / nu, final / 10)
  double dt = 0;                           // > 0: fixed step
  double wallLimit = 0;                    // -time_wall_limit: stop with a checkpoint after this wall time [s]
};

struct OutputConfig {
  std::string dir = "output";
  int every = 0;                           // steps between snapshots (0: none)
  double dt = 0;                           // simulated time between snapshots (0: none)
  int monitorEvery = 10;                   // steps between progress lines (0: none)
  int seriesEvery = 1;                     // steps between rows of the time series (and the last step)
  bool files = true;                       // false: no files at all (library use in tests)
  bool overwrite = false;                  // -output_overwrite: replace another run's outputs in dir
  std::vector<Vec3> probes;                // -probe x,y,z,...: pressure probes (probes.csv) [m]
};

// Checks after every step that stop a run going wrong (docs/robustness.md).
struct HealthConfig {
  double cflMax = 1.0;                     // -health_cfl_max: with a fixed -time_dt
  double overlapMax = 0.1;                 // -health_overlap_max: contact overlap / smaller diameter
};

// Checkpoint/restart (docs/outputs.md).
struct CheckpointConfig {
  std::string restart;                     // -restart: continue from this checkpoint file
  int every = 0;                           // steps between checkpoints (0: none)
  double dt = 0;                           // simulated time between checkpoints (0: none)
  int keep = 2;                            // checkpoints of this run kept on disk (older ones deleted)
  bool allowChanges = false;               // -restart_allow_changes: warn about changed set-up options
  bool on() const { return every > 0 || dt > 0; }
};

struct Config {
  Vec3 gravity{};                          // on particles; on the fluid it is hydrostatic
  GridConfig grid;
  BoundaryConfig bc;
  FluidConfig fluid;
  TimeConfig time;
  OutputConfig output;
  CheckpointConfig checkpoint;
  HealthConfig health;

  // Parses the options (throws InputError on a value that does not parse).
  static Config read();
  // Checks the values (also used for configurations built in code, e.g. by tests).
  void validate() const;
};

} // namespace vp
