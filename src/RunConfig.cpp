#include "vp/RunConfig.hpp"
#include "vp/TimeStepControl.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include <cmath>
#include <fstream>
#include <petscsys.h>
#include <string>

namespace vp {

namespace {

// Measured peak resident memory (docs/robustness.md): about 45 MB per rank plus 0.95 kB per cell
// with BoomerAMG (0.74 kB with fft) on the 32^3 and 64^3 cavities.
constexpr double kBytesPerRank = 50e6, kBytesPerCell = 1000;

double availableBytes()
{
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kb;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return 0;  // unknown: no check
}

std::string gigabytes(double b)
{
  char s[32];
  std::snprintf(s, sizeof s, "%.2f GB", b / 1e9);
  return s;
}

} // namespace

RunConfig::RunConfig(const Config& c) : RunConfig(read())
{
  main = c;
  resolveDefaults();
}

RunConfig RunConfig::read()
{
  RunConfig r;
  r.main = Config::read();
  r.collapse = CollapseConfig::read();
  r.rheology = RheologyConfig::read();
  r.particles = ParticleConfig::read();
  r.penalization = PenalizationConfig::read();
  r.solvers = readSolverOptions();
  OptionGroup o("Run control", false);
  r.allowUnknownOptions = o.flag("-options_allow_unknown", false, "Only warn about options nothing reads (misspelt ones)");
  r.memoryCheck = o.flag("-memory_check", true, "Refuse a run whose estimated memory exceeds what the nodes have available");
  return r;
}

void RunConfig::validate(MPI_Comm comm) const
{
  main.validate();
  collapse.validate(particles.any());
  rheology.validate(main, particles);
  particles.validate();
  penalization.validate();
  int ranks;
  MPI_Comm_size(comm, &ranks);
  solvers.validate(ranks, main.grid.n[2], penalization.weightedProjection && particles.any() && !main.fluid.off);
  const std::array<int, 3>& split = main.grid.ranks;
  if (split != std::array<int, 3>{0, 0, 0}) {
    if (split[0] * split[1] * split[2] != ranks)
      failOption("-grid_ranks", "the ranks per axis must multiply to the number of ranks, " + std::to_string(ranks) + ", got " +
                                    std::to_string(split[0]) + "," + std::to_string(split[1]) + "," + std::to_string(split[2]));
    for (int d = 0; d < 3; ++d)
      if (split[d] > main.grid.n[d])
        failOption("-grid_ranks", std::string("at most one rank per cell along ") + "xyz"[d] + " (" + std::to_string(main.grid.n[d]) +
                                      " cells), got " + std::to_string(split[d]));
  }
  if (main.fluid.off && !particles.any())
    failOption("-fluid_off", "a DEM-only run needs particles (-particles_file, -particles_lattice, -particles_random, -particles_packed or -particle_position)");
  if (main.fluid.off && particles.any() && !particles.contact.stiffnessGiven())
    failOption("-contact_tc", "a DEM-only run needs a contact stiffness: set -contact_tc, -contact_tc_steps or -contact_kn");
  if (!(particles.dragViscosity >= 0) || !std::isfinite(particles.dragViscosity))
    failOption("-dem_drag_viscosity", "must be >= 0 (Pa s)", particles.dragViscosity);
  if (!main.fluid.off && particles.dragViscosity > 0)
    failOption("-dem_drag_viscosity", "is for DEM-only runs (-fluid_off); with the fluid on the resolved flow exerts the drag");
  if (main.fluid.off && !main.output.probes.empty()) failOption("-probe", "pressure probes need the fluid (not with -fluid_off)");
  if (memoryCheck) checkMemory(comm);
}

void RunConfig::resolveDefaults(MPI_Comm comm)
{
  if (particles.any() && !particles.contact.stiffnessGiven()) {
    // Only coupled runs get here (DEM-only runs must give one): a contact resolved over ten steps.
    particles.contact.tc = 10 * TimeStepControl(main, true).bound(0);
    if (comm != MPI_COMM_NULL)
      PetscPrintf(comm, "vpsolve: no contact stiffness given: -contact_tc %g s, ten times the first fluid step (docs/particles.md)\n",
                  particles.contact.tc);
  }
  particles.resolveDefaults(main);
  // The fft pressure solver works on slabs along z: a grid split the same way hands it its slab
  // without redistribution (and splits a column of particles across ranks by height).
  int ranks = 1;
  if (comm != MPI_COMM_NULL) MPI_Comm_size(comm, &ranks);
  if (main.grid.ranks == std::array<int, 3>{0, 0, 0} && solvers.pressurePc == "fft" && !main.fluid.off && ranks > 1 &&
      ranks <= main.grid.n[2])
    main.grid.ranks = {1, 1, ranks};
}

void RunConfig::checkMemory(MPI_Comm comm) const
{
  int size, nodeRank, nodeSize;
  MPI_Comm_size(comm, &size);
  MPI_Comm node;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  MPI_Comm_rank(node, &nodeRank);
  MPI_Comm_size(node, &nodeSize);
  MPI_Comm_free(&node);
  const GridConfig& g = main.grid;
  const double cells = double(g.n[0]) * g.n[1] * g.n[2];
  const double perRank = kBytesPerRank + kBytesPerCell * cells / size;
  const double need = perRank * nodeSize, have = availableBytes();
  int bad = have > 0 && need > 0.9 * have ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_INT, MPI_MAX, comm);
  if (bad)
    failOption("-grid_n", "the run needs about " + gigabytes(need) + " per node (" + std::to_string(nodeSize) + " ranks), " +
                              "the node has " + gigabytes(have) + " available; use more nodes, a coarser grid or larger "
                              "particles (-memory_check 0 to try anyway)");
}

void checkUnknownOptions(MPI_Comm comm, bool allow)
{
  const std::vector<std::string> unknown = unusedOptions();
  if (unknown.empty()) return;
  std::string list;
  for (const auto& name : unknown) {
    const std::string near = nearestOption(name);
    list += "\n  " + name + (near.empty() ? "" : "  (did you mean " + near + "?)");
  }
  if (allow) {
    PetscPrintf(comm, "vpsolve: warning: options nothing reads (-options_allow_unknown):%s\n", list.c_str());
    return;
  }
  throw InputError("unknown option(s), not read by vpsolve or its solvers:" + list +
                   "\n(vpsolve -help lists the options; -options_allow_unknown accepts them)");
}

} // namespace vp
