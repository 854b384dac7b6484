// Fluid step benchmark: seconds per step split by log stage for the 3-D lid-driven cavity
// (Re 400) on an N^3 grid, after warm-up steps (the flow is developing, so the pressure solve is
// not trivially warm-started).
// usage: bench_fluid_step -n 128 -warmup 5 -steps 10 [solver options]
// prints: ranks,n,steps,total_s_per_step,<stage>_s_per_step...,us_per_cell_step
#include "../common/TimedSteps.hpp"

int main(int argc, char** argv)
{
  if (PetscInitialize(&argc, &argv, nullptr, "Fluid step benchmark\n") != 0) return 1;
  try {
    PetscInt n = 64, warmup = 5, steps = 10;
    PetscOptionsGetInt(nullptr, nullptr, "-n", &n, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-warmup", &warmup, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-steps", &steps, nullptr);
    vp::Config c;
    c.grid.n = {int(n), int(n), int(n)};
    c.bc.type[3] = vp::BcType::Velocity;
    c.bc.velocity[3] = {1, 0, 0};
    c.fluid.rho = 1;
    c.fluid.mu = 1.0 / 400;
    c.output.files = false;
    c.output.monitorEvery = 0;
    vp::Simulation sim(PETSC_COMM_WORLD, vp::RunConfig(c));
    const double total = vp::bench::timeSteps(sim, int(warmup), int(steps));
    int size;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    PetscPrintf(PETSC_COMM_WORLD, "%d,%d,%d,%.4f", size, int(n), int(steps), total);
    vp::bench::printStages(PETSC_COMM_WORLD, {vp::Stage::Advection, vp::Stage::Diffusion, vp::Stage::Pressure},
                           int(steps));
    PetscPrintf(PETSC_COMM_WORLD, ",%.4f\n", total / sim.grid().cells() * 1e6 * size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_fluid_step: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  PetscFinalize();
  return 0;
}
