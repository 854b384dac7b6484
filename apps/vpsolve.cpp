// vpsolve: particle-resolved simulation of particle-laden flows (see README.md). The run lifecycle
// (docs/architecture.md): read and validate every option, build the solvers, refuse options
// nothing read, then run; nothing is written before the run starts.
#include "vp/RunConfig.hpp"
#include "vp/Simulation.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/HugePages.hpp"
#include "vp/core/OneRankTransport.hpp"
#include "vp/core/Options.hpp"
#include "vp/io/OutputDir.hpp"
#include "vp/io/RunRecord.hpp"
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <petscsys.h>

namespace {

const char* const kUsage =
  "vpsolve: incompressible Navier-Stokes on a staggered grid with resolved particles.\n"
  "usage: mpirun -n 2 vpsolve -options_file cases/dam_break.opts [options]\n"
  "Options below as -name <default>; vectors are comma-separated. Exit status: 0 done (or stopped by\n"
  "-time_wall_limit), 1 bad input, 2 internal error, 3 failed health check, solver or full disk,\n"
  "128+n stopped by signal n.\n";

const char* const kSolverNote =
  "\nPETSc options of the solver objects take the prefixes -pressure_ and -velocity_ (for example\n"
  "-pressure_ksp_monitor; the viscous KSP monitors need -velocity_operator shell); docs/fluid.md lists\n"
  "the useful ones.\n";

bool isRank0()
{
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  return !rank || std::strcmp(rank, "0") == 0;
}

// PETSc would fail on a missing options file with a long trace: say it in one line instead.
bool optionsFilesReadable(int argc, char** argv)
{
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "-options_file") != 0) continue;
    if (std::FILE* f = std::fopen(argv[i + 1], "r")) {
      std::fclose(f);
      continue;
    }
    if (isRank0()) std::fprintf(stderr, "vpsolve: error: option -options_file: cannot open '%s': %s\n", argv[i + 1], std::strerror(errno));
    return false;
  }
  return true;
}

// Removes -help, -h and --help from argv (vpsolve prints its own help, before PETSc's).
bool takeHelp(int& argc, char** argv)
{
  bool help = false;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "-help") || !std::strcmp(argv[i], "-h") || !std::strcmp(argv[i], "--help"))
      help = true;
    else
      argv[out++] = argv[i];
  }
  argc = out;
  argv[argc] = nullptr;
  return help;
}

int printHelp(MPI_Comm comm)
{
  int rank;
  MPI_Comm_rank(comm, &rank);
  vp::setOptionsHelpMode(true);
  vp::RunConfig::read();
  if (rank == 0) std::fputs(kUsage, stdout);
  vp::printOptionHelp(rank);
  if (rank == 0) std::fputs(kSolverNote, stdout);
  return 0;
}

int runCase(MPI_Comm comm)
{
  vp::RunConfig cfg = vp::RunConfig::read();
  cfg.validate(comm);
  cfg.resolveDefaults(comm);
  vp::Simulation sim(comm, cfg);
  vp::checkUnknownOptions(comm, cfg.allowUnknownOptions);
  vp::checkOutputDir(comm, cfg.main.output.dir, cfg.main.checkpoint.restart, cfg.main.output.overwrite);
  vp::installStopSignals();
  return sim.run();
}

} // namespace

int main(int argc, char** argv)
{
  if (!optionsFilesReadable(argc, argv)) return 1;
  vp::setCommandLine(argc, argv);
  const bool help = takeHelp(argc, argv);
  vp::allocateLargeOnHugePages();
  vp::useLocalTransportForOneRank();
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0) return 1;
  int rc = 0;
  try {
    PetscBool fileHelp = PETSC_FALSE;  // -help inside an options file
    PetscOptionsHasHelp(nullptr, &fileHelp);
    rc = help || fileHelp ? printHelp(PETSC_COMM_WORLD) : runCase(PETSC_COMM_WORLD);
  } catch (const vp::InputError& e) {
    PetscFPrintf(PETSC_COMM_WORLD, PETSC_STDERR, "vpsolve: error: %s\n", e.what());
    rc = 1;
  } catch (const vp::RunFailure& e) {
    PetscFPrintf(PETSC_COMM_WORLD, PETSC_STDERR, "vpsolve: error: %s\n", e.what());
    rc = 3;
  } catch (const std::exception& e) {
    // Not necessarily raised on every rank: abort the whole job rather than hang.
    std::fprintf(stderr, "vpsolve: error: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  PetscFinalize();
  return rc;
}
