// Coupling benchmark: seconds per fluid step split by log stage for resolved spheres (d/dx = 8)
// settling in a closed 128^3 box (or -n), with the particles given by the options
// (-particle_position or -particles_lattice). 3 warm-up steps, then -steps timed steps.
// usage: bench_coupling -n 128 -steps 5 -particles_lattice ... [options]
// prints: ranks,n,particles,step_s,<stage>_s...
#include "../common/TimedSteps.hpp"

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
    vp::Simulation sim(PETSC_COMM_WORLD, vp::RunConfig(c));
    const double total = vp::bench::timeSteps(sim, 3, int(steps));
    int size;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    PetscPrintf(PETSC_COMM_WORLD, "%d,%d,%ld,%.4f", size, int(n), sim.particles()->diagnostics().particles, total);
    vp::bench::printStages(PETSC_COMM_WORLD,
                           {vp::Stage::Advection, vp::Stage::Diffusion, vp::Stage::Pressure, vp::Stage::Penalization,
                            vp::Stage::HydroForce, vp::Stage::DEM, vp::Stage::Exchange},
                           int(steps));
    PetscPrintf(PETSC_COMM_WORLD, "\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_coupling: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  PetscFinalize();
  return 0;
}
