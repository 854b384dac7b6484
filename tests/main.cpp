// Catch2 main for all vpsolve tests: initialises PETSc (options through PETSC_OPTIONS), lets only
// rank 0 report, and makes every rank return the worst exit code so mpirun fails as a whole.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <petscsys.h>
#include <cstdio>

int main(int argc, char** argv)
{
  if (PetscInitialize(nullptr, nullptr, nullptr, nullptr) != 0) return 1;
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank > 0 && !freopen("/dev/null", "w", stdout)) return 1;
  int result = Catch::Session().run(argc, argv);
  int worst = 0;
  MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  PetscFinalize();
  return worst;
}
