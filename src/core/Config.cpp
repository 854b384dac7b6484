#include "vp/core/Config.hpp"
#include "vp/core/Error.hpp"
#include <cmath>
#include <petscsys.h>
#include <sstream>

namespace vp {

namespace {

const char* const kFaceNames[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
const char* const kBcNames[4] = {"wall", "slip", "periodic", "velocity"};
const char* const kInitNames[4] = {"rest", "taylor_green", "abc", "poiseuille"};

[[noreturn]] void fail(const std::string& option, const std::string& what) { failOption(option, what); }

std::string str(double v) { return formatNumber(v); }

template <size_t N>
int lookup(const char* const (&names)[N], const std::string& value, const std::string& option)
{
  for (size_t i = 0; i < N; ++i)
    if (value == names[i]) return static_cast<int>(i);
  std::string valid;
  for (size_t i = 0; i < N; ++i) valid += std::string(i ? ", " : "") + names[i];
  fail(option, "unknown value '" + value + "' (valid: " + valid + ")");
}

void readVec3(PetscReal (&a)[3], PetscInt n, PetscBool set, const char* option)
{
  if (set && n != 3) fail(option, "needs 3 comma-separated values, got " + std::to_string(n));
}

// An int option inside an options block (PetscInt may be wider than int).
PetscErrorCode optionInt(PetscOptionItems* PetscOptionsObject, const char* name, const char* help, int& value)
{
  PetscInt v = value;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInt(name, help, "", v, &v, nullptr));
  value = static_cast<int>(v);
  PetscFunctionReturn(0);
}

// The options blocks; strings are returned raw and parsed in fromOptions for clear messages.
struct Raw {
  char bc[6][64];
  char init[64];
  char dir[PETSC_MAX_PATH_LEN];
  char restart[PETSC_MAX_PATH_LEN];
};

PetscErrorCode registerOptions(MPI_Comm comm, Config& c, Raw& raw)
{
  PetscInt n;
  PetscBool set;
  PetscFunctionBeginUser;

  PetscOptionsBegin(comm, nullptr, "Grid: uniform 3-D box", "vpsolve");
  {
    PetscInt cells[3] = {c.grid.n[0], c.grid.n[1], c.grid.n[2]};
    n = 3;
    PetscCall(PetscOptionsIntArray("-grid_n", "Cells per axis nx,ny,nz", "", cells, &n, &set));
    if (set && n != 3) fail("-grid_n", "needs 3 comma-separated values, got " + std::to_string(n));
    for (int d = 0; d < 3; ++d) c.grid.n[d] = cells[d];
    PetscReal lo[3] = {c.grid.lo[0], c.grid.lo[1], c.grid.lo[2]};
    PetscReal hi[3] = {c.grid.hi[0], c.grid.hi[1], c.grid.hi[2]};
    n = 3;
    PetscCall(PetscOptionsRealArray("-grid_lo", "Lower corner x,y,z of the domain (m)", "", lo, &n, &set));
    readVec3(lo, n, set, "-grid_lo");
    n = 3;
    PetscCall(PetscOptionsRealArray("-grid_hi", "Upper corner x,y,z of the domain (m)", "", hi, &n, &set));
    readVec3(hi, n, set, "-grid_hi");
    for (int d = 0; d < 3; ++d) { c.grid.lo[d] = lo[d]; c.grid.hi[d] = hi[d]; }
  }
  PetscOptionsEnd();

  PetscOptionsBegin(comm, nullptr, "Boundary conditions per face: wall|slip|periodic|velocity", "vpsolve");
  for (int f = 0; f < 6; ++f) {
    std::string opt = std::string("-bc_") + kFaceNames[f];
    std::string help = std::string("Boundary type of the ") + kFaceNames[f] + " face (wall, slip, periodic, velocity)";
    PetscCall(PetscStrcpy(raw.bc[f], bcName(c.bc.type[f])));
    PetscCall(PetscOptionsString(opt.c_str(), help.c_str(), "", raw.bc[f], raw.bc[f], sizeof raw.bc[f], &set));
    PetscReal v[3] = {c.bc.velocity[f].x, c.bc.velocity[f].y, c.bc.velocity[f].z};
    std::string vopt = opt + "_velocity";
    n = 3;
    PetscCall(PetscOptionsRealArray(vopt.c_str(), "Wall velocity u,v,w of a 'velocity' face (m/s)", "", v, &n, &set));
    readVec3(v, n, set, vopt.c_str());
    c.bc.velocity[f] = {v[0], v[1], v[2]};
  }
  PetscOptionsEnd();

  PetscOptionsBegin(comm, nullptr, "Fluid", "vpsolve");
  {
    PetscBool off = c.fluid.off ? PETSC_TRUE : PETSC_FALSE;
    PetscCall(PetscOptionsBool("-fluid_off", "Run without fluid (DEM only)", "", off, &off, nullptr));
    c.fluid.off = off;
    PetscCall(PetscOptionsReal("-fluid_rho", "Fluid density (kg/m^3)", "", c.fluid.rho, &c.fluid.rho, nullptr));
    PetscCall(PetscOptionsReal("-fluid_mu", "Fluid dynamic viscosity (Pa s)", "", c.fluid.mu, &c.fluid.mu, nullptr));
    PetscReal f[3] = {c.fluid.bodyForce.x, c.fluid.bodyForce.y, c.fluid.bodyForce.z};
    n = 3;
    PetscCall(PetscOptionsRealArray("-fluid_body_force", "Body force per unit mass on the fluid ax,ay,az (m/s^2)", "", f, &n, &set));
    readVec3(f, n, set, "-fluid_body_force");
    c.fluid.bodyForce = {f[0], f[1], f[2]};
    PetscReal g[3] = {c.gravity.x, c.gravity.y, c.gravity.z};
    n = 3;
    PetscCall(PetscOptionsRealArray("-gravity", "Gravity gx,gy,gz (m/s^2); balanced by hydrostatic pressure in the fluid", "", g, &n, &set));
    readVec3(g, n, set, "-gravity");
    c.gravity = {g[0], g[1], g[2]};
    PetscCall(PetscStrcpy(raw.init, kInitNames[static_cast<int>(c.fluid.init)]));
    PetscCall(PetscOptionsString("-init_flow", "Initial flow: rest, taylor_green, abc, poiseuille", "", raw.init, raw.init, sizeof raw.init, &set));
    PetscCall(PetscOptionsReal("-init_velocity", "Velocity amplitude of the analytic initial flows (m/s)", "", c.fluid.initVelocity, &c.fluid.initVelocity, nullptr));
  }
  PetscOptionsEnd();

  PetscOptionsBegin(comm, nullptr, "Time stepping", "vpsolve");
  PetscCall(PetscOptionsReal("-time_final", "End time (s)", "", c.time.final, &c.time.final, nullptr));
  PetscCall(optionInt(PetscOptionsObject, "-time_max_steps", "Maximum number of fluid steps", c.time.maxSteps));
  PetscCall(PetscOptionsReal("-time_cfl", "Target CFL number, dt = cfl * min(h / |u_max|)", "", c.time.cfl, &c.time.cfl, nullptr));
  PetscCall(PetscOptionsReal("-time_dt_max", "Largest time step (s); 0: min(h)^2 / nu", "", c.time.dtMax, &c.time.dtMax, nullptr));
  PetscCall(PetscOptionsReal("-time_dt", "Fixed time step (s); 0: CFL-adaptive", "", c.time.dt, &c.time.dt, nullptr));
  PetscOptionsEnd();

  PetscOptionsBegin(comm, nullptr, "Output", "vpsolve");
  {
    PetscCall(PetscStrcpy(raw.dir, c.output.dir.c_str()));
    PetscCall(PetscOptionsString("-output_dir", "Directory for fields, particles, diagnostics", "", raw.dir, raw.dir, sizeof raw.dir, nullptr));
    PetscCall(optionInt(PetscOptionsObject, "-output_every", "Steps between field snapshots (0: none)", c.output.every));
    PetscCall(PetscOptionsReal("-output_dt", "Simulated time between field snapshots (s; 0: none)", "", c.output.dt, &c.output.dt, nullptr));
    PetscCall(optionInt(PetscOptionsObject, "-monitor_every", "Steps between progress lines (0: none)", c.output.monitorEvery));
  }
  PetscOptionsEnd();

  PetscOptionsBegin(comm, nullptr, "Checkpoint/restart", "vpsolve");
  {
    PetscCall(PetscOptionsString("-restart", "Continue from this checkpoint (checkpoint_<step>.h5 or checkpoint_latest.h5); "
                                 "particles come from it, grid and boundaries must match", "", raw.restart, raw.restart,
                                 sizeof raw.restart, nullptr));
    PetscCall(optionInt(PetscOptionsObject, "-checkpoint_every", "Steps between checkpoints (0: none)", c.checkpoint.every));
    PetscCall(PetscOptionsReal("-checkpoint_dt", "Simulated time between checkpoints (s; 0: none)", "", c.checkpoint.dt, &c.checkpoint.dt, nullptr));
    PetscCall(optionInt(PetscOptionsObject, "-checkpoint_keep", "Checkpoints of this run kept on disk, newest first", c.checkpoint.keep));
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

} // namespace

const char* bcName(BcType t) { return kBcNames[static_cast<int>(t)]; }

Config Config::fromOptions(MPI_Comm comm)
{
  Config c;
  Raw raw{};
  VP_CALL(registerOptions(comm, c, raw));
  for (int f = 0; f < 6; ++f)
    c.bc.type[f] = static_cast<BcType>(lookup(kBcNames, raw.bc[f], std::string("-bc_") + kFaceNames[f]));
  c.fluid.init = static_cast<InitFlow>(lookup(kInitNames, raw.init, "-init_flow"));
  c.output.dir = raw.dir;
  c.checkpoint.restart = raw.restart;
  c.validate();
  return c;
}

void Config::validate() const
{
  const char* axis = "xyz";
  for (int d = 0; d < 3; ++d) {
    if (grid.n[d] < 1) fail("-grid_n", std::string("cells along ") + axis[d] + " must be >= 1, got " + std::to_string(grid.n[d]));
    if (!(grid.hi[d] > grid.lo[d]))
      fail("-grid_hi", std::string("upper corner must exceed -grid_lo along ") + axis[d] + " (" + str(grid.hi[d]) + " <= " + str(grid.lo[d]) + ")");
    if (!bc.periodic(d) && grid.n[d] < 2)
      fail("-grid_n", std::string("a wall-bounded axis needs >= 2 cells, ") + axis[d] + " has " + std::to_string(grid.n[d]));
    bool plo = bc.type[2 * d] == BcType::Periodic, phi = bc.type[2 * d + 1] == BcType::Periodic;
    if (plo != phi)
      fail(std::string("-bc_") + kFaceNames[2 * d + (plo ? 1 : 0)],
           std::string("periodic must be set on both ") + axis[d] + " faces (-bc_" + kFaceNames[2 * d] + " and -bc_" + kFaceNames[2 * d + 1] + ")");
  }
  for (int f = 0; f < 6; ++f) {
    const Vec3& v = bc.velocity[f];
    if (bc.type[f] != BcType::Velocity && (v.x != 0 || v.y != 0 || v.z != 0))
      fail(std::string("-bc_") + kFaceNames[f] + "_velocity", std::string("only allowed when -bc_") + kFaceNames[f] + " velocity");
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      fail(std::string("-bc_") + kFaceNames[f] + "_velocity", "must be finite");
  }
  if (!(fluid.rho > 0) || !std::isfinite(fluid.rho)) fail("-fluid_rho", "must be > 0, got " + str(fluid.rho));
  if (!(fluid.mu > 0) || !std::isfinite(fluid.mu)) fail("-fluid_mu", "must be > 0, got " + str(fluid.mu));
  if (!(time.final > 0)) fail("-time_final", "must be > 0, got " + str(time.final));
  if (time.maxSteps < 0) fail("-time_max_steps", "must be >= 0, got " + std::to_string(time.maxSteps));
  if (!(time.cfl > 0 && time.cfl <= 1)) fail("-time_cfl", "must be in (0, 1], got " + str(time.cfl));
  if (!(time.dtMax >= 0)) fail("-time_dt_max", "must be >= 0, got " + str(time.dtMax));
  if (!(time.dt >= 0)) fail("-time_dt", "must be >= 0, got " + str(time.dt));
  if (output.every < 0) fail("-output_every", "must be >= 0 (0: no snapshots), got " + std::to_string(output.every));
  if (!(output.dt >= 0)) fail("-output_dt", "must be >= 0 (0: no snapshots), got " + str(output.dt));
  if (output.monitorEvery < 0) fail("-monitor_every", "must be >= 0, got " + std::to_string(output.monitorEvery));
  if (output.dir.empty()) fail("-output_dir", "must not be empty");
  if (checkpoint.every < 0) fail("-checkpoint_every", "must be >= 0 (0: no checkpoints), got " + std::to_string(checkpoint.every));
  if (!(checkpoint.dt >= 0)) fail("-checkpoint_dt", "must be >= 0 (0: no checkpoints), got " + str(checkpoint.dt));
  if (checkpoint.keep < 1) fail("-checkpoint_keep", "must be >= 1, got " + std::to_string(checkpoint.keep));
  if (fluid.init == InitFlow::TaylorGreen || fluid.init == InitFlow::Abc) {
    bool needZ = fluid.init == InitFlow::Abc;
    if (!bc.periodic(0) || !bc.periodic(1) || (needZ && !bc.periodic(2)))
      fail("-init_flow", std::string(fluid.init == InitFlow::Abc ? "abc needs periodic x, y and z" : "taylor_green needs periodic x and y"));
  }
  if (fluid.init == InitFlow::Poiseuille && (bc.periodic(1) || !bc.periodic(0)))
    fail("-init_flow", "poiseuille needs periodic x and walls in y");
}

} // namespace vp
