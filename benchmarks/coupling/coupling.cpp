// Coupling benchmark: seconds per fluid step split by log stage for resolved spheres (d/dx = 8)
// settling in a closed 128^3 box (or -n), with the particles given by the options
// (-particle_position or -particles_lattice). 3 warm-up steps, then -steps timed steps.
// usage: bench_coupling -n 128 -steps 5 -particles_lattice ... [options]
// prints: ranks,n,particles,step_s,<stage>_s...
#include "vp/Simulation.hpp"
#include "vp/core/Logging.hpp"
#include <petscsys.h>

int main(int argc, char** argv)
{
  if (PetscInitialize(&argc, &argv, nullptr, "Coupling benchmark\n") != 0) return 1;
  try {
    PetscInt n = 128, steps = 5;
    PetscOptionsGetInt(nullptr, nullptr, "-n", &n, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-steps", &steps, nullptr);
    vp::Config c;
    c.grid.n = {int(n), int(n), int(n)};
    c.fluid.rho = 1000;
    c.fluid.mu = 1e-2;
    c.gravity = {0, 0, -9.81};
    c.output.files = false;
    c.output.monitorEvery = 0;
    PetscOptionsGetReal(nullptr, nullptr, "-time_dt", &c.time.dt, nullptr);
    vp::Simulation sim(PETSC_COMM_WORLD, c);
    for (int s = 0; s < 3; ++s) sim.advance(sim.nextDt());
    MPI_Barrier(PETSC_COMM_WORLD);
    vp::resetStageSeconds();
    const double t0 = MPI_Wtime();
    for (int s = 0; s < steps; ++s) sim.advance(sim.nextDt());
    MPI_Barrier(PETSC_COMM_WORLD);
    const double total = (MPI_Wtime() - t0) / steps;
    int size;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    PetscPrintf(PETSC_COMM_WORLD, "%d,%d,%ld,%.4f", size, int(n), sim.particles()->diagnostics().particles, total);
    for (vp::Stage st : {vp::Stage::Advection, vp::Stage::Diffusion, vp::Stage::Pressure, vp::Stage::Penalization,
                         vp::Stage::HydroForce, vp::Stage::DEM, vp::Stage::Exchange}) {
      double mine = vp::stageSeconds(st) / steps, slowest;
      MPI_Allreduce(&mine, &slowest, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
      PetscPrintf(PETSC_COMM_WORLD, ",%.4f", slowest);
    }
    PetscPrintf(PETSC_COMM_WORLD, "\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_coupling: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  PetscFinalize();
  return 0;
}
