// vpsolve: particle-resolved simulation of particle-laden flows (see README.md).
#include "vp/Simulation.hpp"
#include "vp/core/Error.hpp"
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <petscsys.h>

static const char help[] =
  "vpsolve: incompressible Navier-Stokes on a staggered grid with resolved particles.\n"
  "usage: mpirun -n 2 vpsolve -options_file cases/taylor_green.opts [options]\n\n";

// PETSc would fail on a missing options file with a long trace: say it in one line instead.
static bool optionsFilesReadable(int argc, char** argv)
{
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "-options_file") != 0) continue;
    if (std::FILE* f = std::fopen(argv[i + 1], "r")) {
      std::fclose(f);
      continue;
    }
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (!rank || std::strcmp(rank, "0") == 0)
      std::fprintf(stderr, "vpsolve: error: option -options_file: cannot open '%s': %s\n", argv[i + 1], std::strerror(errno));
    return false;
  }
  return true;
}

int main(int argc, char** argv)
{
  if (!optionsFilesReadable(argc, argv)) return 1;
  if (PetscInitialize(&argc, &argv, nullptr, help) != 0) return 1;
  PetscBool userLeft;
  PetscOptionsHasName(nullptr, nullptr, "-options_left", &userLeft);
  int rc = 0;
  try {
    vp::Config cfg = vp::Config::fromOptions(PETSC_COMM_WORLD);
    vp::Simulation sim(PETSC_COMM_WORLD, cfg);
    PetscBool help = PETSC_FALSE;
    PetscOptionsHasHelp(nullptr, &help);
    if (!help) sim.run();
  } catch (const vp::InputError& e) {
    PetscFPrintf(PETSC_COMM_WORLD, PETSC_STDERR, "vpsolve: error: %s\n", e.what());
    rc = 1;
  } catch (const std::exception& e) {
    // Not necessarily raised on every rank: abort the whole job rather than hang.
    std::fprintf(stderr, "vpsolve: error: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  // Misspelt options would otherwise be ignored silently by this (non-debug) PETSc build.
  PetscInt unused = 0;
  PetscOptionsAllUsed(nullptr, &unused);
  if (!userLeft && unused > 0) PetscOptionsLeft(nullptr);
  PetscFinalize();
  return rc;
}
