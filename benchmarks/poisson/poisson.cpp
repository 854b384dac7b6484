// Pressure Poisson benchmark: set-up time, time per solve and iterations of the pressure solver
// (KSP prefix -pressure_, so any PETSc solver options apply) on an N^3 closed box (walls: the
// singular Neumann problem), from a zero initial guess to the tolerance given by the options.
// usage: bench_poisson -n 128 -solves 3 -label boomeramg [-pressure_* options]
// prints: label,ranks,n,setup_s,solve_s,iterations
#include "vp/core/Error.hpp"
#include "vp/fluid/PressureSolver.hpp"
#include <petscsys.h>

int main(int argc, char** argv)
{
  if (PetscInitialize(&argc, &argv, nullptr, "Pressure Poisson benchmark\n") != 0) return 1;
  try {
    PetscInt n = 64, solves = 3;
    char label[64] = "default";
    PetscOptionsGetInt(nullptr, nullptr, "-n", &n, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-solves", &solves, nullptr);
    PetscOptionsGetString(nullptr, nullptr, "-label", label, sizeof label, nullptr);
    vp::Config cfg;
    cfg.grid.n = {int(n), int(n), int(n)};
    vp::Grid grid(PETSC_COMM_WORLD, cfg.grid, cfg.bc);
    MPI_Barrier(PETSC_COMM_WORLD);
    double t0 = MPI_Wtime();
    vp::PressureSolver solver(grid, vp::readSolverOptions());  // assembles A and sets up the preconditioner
    MPI_Barrier(PETSC_COMM_WORLD);
    const double setup = MPI_Wtime() - t0;
    Vec b, rhs, x;
    VP_CALL(DMCreateGlobalVector(grid.cellDM(), &b));
    VP_CALL(VecDuplicate(b, &rhs));
    VP_CALL(VecDuplicate(b, &x));
    PetscRandom rnd;
    VP_CALL(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
    VP_CALL(PetscRandomSetSeed(rnd, 7));
    VP_CALL(PetscRandomSeed(rnd));
    double solveTime = 0;
    int its = 0;
    for (int s = 0; s < solves; ++s) {
      VP_CALL(VecSetRandom(b, rnd));
      VP_CALL(VecCopy(b, rhs));
      VP_CALL(VecSet(x, 0));
      MPI_Barrier(PETSC_COMM_WORLD);
      t0 = MPI_Wtime();
      its += solver.solve(rhs, x, 0.0);
      MPI_Barrier(PETSC_COMM_WORLD);
      solveTime += MPI_Wtime() - t0;
    }
    int size;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    PetscPrintf(PETSC_COMM_WORLD, "%s,%d,%d,%.4f,%.4f,%.1f\n", label, size, int(n), setup, solveTime / solves,
                double(its) / solves);
    PetscRandomDestroy(&rnd);
    for (Vec* v : {&b, &rhs, &x}) VecDestroy(v);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_poisson: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  PetscFinalize();
  return 0;
}
