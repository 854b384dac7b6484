// vpsolve (particle branch): DEM-only runs (-fluid_off) until the Simulation from main drives both
// the fluid and the particles.
#include "vp/core/Config.hpp"
#include "vp/core/Error.hpp"
#include "vp/particles/DryRun.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include <cstdio>
#include <petscsys.h>

int main(int argc, char** argv)
{
  if (PetscInitialize(&argc, &argv, nullptr, "vpsolve: particle-resolved particle-laden flows\n") != 0) return 1;
  int rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  int status = 0;
  try {
    const vp::Config c = vp::Config::fromOptions(PETSC_COMM_WORLD);
    const vp::ParticleConfig pc = vp::ParticleConfig::fromOptions(PETSC_COMM_WORLD);
    if (!c.fluid.off) throw vp::InputError("option -fluid_off: this build runs DEM only; add -fluid_off");
    vp::runDryDem(PETSC_COMM_WORLD, c, pc);
  } catch (const vp::InputError& e) {
    if (rank == 0) std::fprintf(stderr, "vpsolve: error: %s\n", e.what());
    status = 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vpsolve: rank %d: %s\n", rank, e.what());
    status = 1;
  }
  PetscFinalize();
  return status;
}
