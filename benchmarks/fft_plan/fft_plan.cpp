// The fft pressure solve against FFTW's own time for the same plans: the Pressure solve of
// vpsolve (-pressure_pc_type fft, KSP preonly, z slabs) per solve, next to fftw_execute of the plans
// it uses alone on the same slab (the x-y plane transforms forward and back, and on several ranks
// the two transposes to whole z lines and back). Walls in x and z, periodic y (the immersed
// collapse's box). The difference is the solve's own work: the scatters between the grid and the
// slab, the tridiagonal z lines, the KSP and null-space bookkeeping.
// usage: bench_fft_plan -nx 512 -ny 32 -nz 160 -solves 20
// prints: ranks,nx,ny,nz,solve_ms,transforms_ms,transposes_ms
#include "vp/core/Error.hpp"
#include "vp/fluid/PressureSolver.hpp"
#include <algorithm>
#include <fftw3-mpi.h>
#include <petscsys.h>
#include <vector>

namespace {

double medianMs(std::vector<double> t)
{
  std::sort(t.begin(), t.end());
  return 1e3 * t[t.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  if (PetscInitialize(&argc, &argv, nullptr, "fft pressure solve against FFTW's plans\n") != 0) return 1;
  try {
    PetscInt nx = 512, ny = 32, nz = 160, solves = 20;
    PetscOptionsGetInt(nullptr, nullptr, "-nx", &nx, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-ny", &ny, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-nz", &nz, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-solves", &solves, nullptr);
    int size;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    vp::Config cfg;
    cfg.grid.n = {int(nx), int(ny), int(nz)};
    cfg.grid.ranks = {1, 1, size};
    cfg.bc.type[2] = cfg.bc.type[3] = vp::BcType::Periodic;
    vp::Grid grid(PETSC_COMM_WORLD, cfg.grid, cfg.bc);
    PetscOptionsSetValue(nullptr, "-pressure_pc_type", "fft");
    vp::PressureSolver solver(grid, vp::readSolverOptions());
    Vec b, x;
    VP_CALL(DMCreateGlobalVector(grid.cellDM(), &b));
    VP_CALL(VecDuplicate(b, &x));
    PetscRandom rnd;
    VP_CALL(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
    std::vector<double> solve, transforms, transposes;
    for (int s = 0; s < solves; ++s) {
      VP_CALL(VecSetRandom(b, rnd));
      MPI_Barrier(PETSC_COMM_WORLD);
      const double t0 = MPI_Wtime();
      solver.solve(b, x, 0.0);
      MPI_Barrier(PETSC_COMM_WORLD);
      solve.push_back(MPI_Wtime() - t0);
    }
    // The same plans as FftPoisson's, on this rank's slab of the same size.
    fftw_mpi_init();
    ptrdiff_t localZ, startZ, localY, startY;
    const ptrdiff_t zy[2] = {nz, ny};
    const ptrdiff_t alloc = fftw_mpi_local_size_many_transposed(2, zy, nx, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK,
                                                                PETSC_COMM_WORLD, &localZ, &startZ, &localY, &startY);
    double* data = fftw_alloc_real(std::max<ptrdiff_t>(alloc, 1));
    const int dims[2] = {int(ny), int(nx)};
    const fftw_r2r_kind fwd[2] = {FFTW_DHT, FFTW_REDFT10}, bwd[2] = {FFTW_DHT, FFTW_REDFT01};
    const int plane = int(nx * ny);
    fftw_plan f = fftw_plan_many_r2r(2, dims, int(localZ), data, nullptr, 1, plane, data, nullptr, 1, plane, fwd, FFTW_ESTIMATE);
    fftw_plan g = fftw_plan_many_r2r(2, dims, int(localZ), data, nullptr, 1, plane, data, nullptr, 1, plane, bwd, FFTW_ESTIMATE);
    fftw_plan to = nullptr, from = nullptr;
    if (size > 1) {
      to = fftw_mpi_plan_many_transpose(nz, ny, nx, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, data, data, PETSC_COMM_WORLD, FFTW_ESTIMATE);
      from = fftw_mpi_plan_many_transpose(ny, nz, nx, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, data, data, PETSC_COMM_WORLD, FFTW_ESTIMATE);
    }
    for (ptrdiff_t i = 0; i < alloc; ++i) data[i] = double(i % 97) / 97;
    for (int s = 0; s < solves; ++s) {
      MPI_Barrier(PETSC_COMM_WORLD);
      double t0 = MPI_Wtime();
      fftw_execute(f);
      fftw_execute(g);
      MPI_Barrier(PETSC_COMM_WORLD);
      transforms.push_back(MPI_Wtime() - t0);
      if (size > 1) {
        t0 = MPI_Wtime();
        fftw_execute(to);
        fftw_execute(from);
        MPI_Barrier(PETSC_COMM_WORLD);
        transposes.push_back(MPI_Wtime() - t0);
      }
    }
    PetscPrintf(PETSC_COMM_WORLD, "%d,%d,%d,%d,%.2f,%.2f,%.2f\n", size, int(nx), int(ny), int(nz), medianMs(solve),
                medianMs(transforms), size > 1 ? medianMs(transposes) : 0.0);
    for (fftw_plan* p : {&f, &g, &to, &from})
      if (*p) fftw_destroy_plan(*p);
    fftw_free(data);
    PetscRandomDestroy(&rnd);
    VecDestroy(&b);
    VecDestroy(&x);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_fft_plan: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  PetscFinalize();
  return 0;
}
