// Stencil kernels against the memory bandwidth: each sweep of the fluid step timed alone on an
// N^3 grid (median of repetitions) and turned into the bandwidth of its minimal traffic (every
// array it reads and writes passed once), next to a STREAM-like copy (VecCopy) of a face vector.
// usage: bench_kernels -n 128 -reps 20
// prints: kernel,ms,bytes_per_cell,GB_per_s,percent_of_copy
#include "vp/core/Config.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/VectorClones.hpp"
#include "vp/fluid/DiffusionSolver.hpp"
#include "vp/fluid/Operators.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/grid/FieldArray.hpp"
#include "vp/grid/Grid.hpp"
#include <algorithm>
#include <cstddef>
#include <functional>
#include <petscsys.h>
#include <vector>

namespace {

double medianSeconds(int reps, const std::function<void()>& f)
{
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const double t0 = MPI_Wtime();
    f();
    t.push_back(MPI_Wtime() - t0);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// The advection sweep's reads without its arithmetic: the 25 neighbour values that every element of
// ops::advectionAndLaplacian loads (the same offsets, rows addressed the same way), added in a tree
// (no long chain of dependent adds) into one output. Its time is what the sweep's unaligned loads
// alone cost (benchmarks/RESULTS.md).
VP_VECTOR_CLONES void advectionLoadsOnly(const vp::Grid& g, PetscScalar**** u, PetscScalar**** N)
{
  const PetscInt i0 = g.start(0), j0 = g.start(1), k0 = g.start(2), ny = g.end(1) - j0;
  const PetscScalar* u0 = &u[k0][j0][i0][0];
  const std::ptrdiff_t oy = &u[k0][j0 + 1][i0][0] - u0, oz = &u[k0 + 1][j0][i0][0] - u0, count = 3 * (g.end(0) - i0);
  PetscScalar* n0 = &N[k0][j0][i0][0];
  for (PetscInt k = k0; k < g.end(2); ++k)
    for (PetscInt j = j0; j < g.end(1); ++j) {
      const PetscScalar* __restrict q = u0 + (j - j0) * oy + (k - k0) * oz;
      PetscScalar* __restrict n = n0 + count * ((k - k0) * ny + (j - j0));
#pragma omp simd
      for (std::ptrdiff_t m = 0; m < count; ++m) {
        const PetscScalar* p = q + m;
        const double row = ((p[0] + p[3]) + (p[-3] + p[2])) + ((p[-1] + p[1]) + p[-2]);
        const double y = ((p[oy] + p[-oy]) + (p[1 + oy] + p[oy - 2])) + ((p[oy - 1] + p[2 - oy]) + (p[-1 - oy] + p[1 - oy]));
        const double z = ((p[oz] + p[-oz]) + (p[1 - oz] + p[-2 - oz])) + ((p[-1 - oz] + p[2 + oz]) + (p[oz - 1] + p[1 + oz]));
        const double yz = p[oy - 1 - oz] + p[1 + oz - oy];
        n[m] = (row + yz) + (y + z);
      }
    }
}

} // namespace

int main(int argc, char** argv)
{
  if (PetscInitialize(&argc, &argv, nullptr, "Kernel bandwidth benchmark\n") != 0) return 1;
  try {
    PetscInt n = 128, reps = 20;
    PetscOptionsGetInt(nullptr, nullptr, "-n", &n, nullptr);
    PetscOptionsGetInt(nullptr, nullptr, "-reps", &reps, nullptr);
    vp::Config c;
    c.grid.n = {int(n), int(n), int(n)};
    vp::Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
    Vec uL, N, L, a, b, div, phiL;
    VP_CALL(DMCreateLocalVector(g.faceDM(), &uL));
    for (Vec* v : {&N, &L, &a, &b}) VP_CALL(DMCreateGlobalVector(g.faceDM(), v));
    VP_CALL(DMCreateGlobalVector(g.cellDM(), &div));
    VP_CALL(DMCreateLocalVector(g.cellDM(), &phiL));
    PetscRandom rnd;
    VP_CALL(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
    for (Vec v : {uL, N, L, a, b, div, phiL}) VP_CALL(VecSetRandom(v, rnd));
    const double cells = double(g.cells());
    vp::DiffusionSolver helmholtz(g, c.bc, vp::readSolverOptions().viscousOperator);
    helmholtz.setOperator(0.1 * g.h(0) * g.h(0), nullptr);
    struct Row {
      const char* name;
      double bytesPerCell;
      std::function<void()> f;
    };
    const std::vector<Row> rows{
      {"copy (VecCopy, face vector)", 48, [&] { VP_CALL(VecCopy(a, b)); }},
      {"advection + Laplacian", 72, [&] {
         vp::FaceArray u(g.faceDM(), uL), Na(g.faceDM(), N), La(g.faceDM(), L);
         vp::ops::advectionAndLaplacian(g, u.a, Na.a, La.a);
       }},
      {"advection's loads alone (probe: its 25 reads summed)", 48, [&] {
         vp::FaceArray u(g.faceDM(), uL), Na(g.faceDM(), N);
         advectionLoadsOnly(g, u.a, Na.a);
       }},
      {"divergence", 32, [&] {
         vp::FaceArray u(g.faceDM(), uL);
         vp::CellArray d(g.cellDM(), div);
         vp::ops::divergence(g, u.a, d.a);
       }},
      {"gradient (added to a face vector)", 56, [&] {
         vp::CellArray p(g.cellDM(), phiL);
         vp::FaceArray o(g.faceDM(), a);
         vp::ops::addGradient(g, p.a, 1e-3, o.a);
       }},
      {"face -> cell centre", 48, [&] {
         vp::FaceArray u(g.faceDM(), uL), o(g.faceDM(), b);
         vp::ops::faceToCentre(g, u.a, o.a);
       }},
      {"viscous operator product (ghost update + Helmholtz sweep)", 72, [&] {
         VP_CALL(MatMult(helmholtz.operatorMatrix(), a, b));
       }},
      // The product as the fused CG applies it: the direction already in the ghosted layout, so
      // only its ghosts are refreshed; p.Ap formed in the same pass.
      {"viscous product in the fused CG (ghost refresh + sweep + dot)", 72, [&] {
         helmholtz.apply(uL, b, true, true);
       }},
      {"ghost update (DMGlobalToLocal, face)", 48, [&] { VP_CALL(DMGlobalToLocal(g.faceDM(), a, INSERT_VALUES, uL)); }},
    };
    double copy = 0;
    PetscPrintf(PETSC_COMM_WORLD, "kernel,ms,bytes_per_cell,GB_per_s,percent_of_copy\n");
    for (const Row& r : rows) {
      r.f();  // first touch
      const double s = medianSeconds(int(reps), r.f);
      const double gbs = r.bytesPerCell * cells / s / 1e9;
      if (copy == 0) copy = gbs;
      PetscPrintf(PETSC_COMM_WORLD, "%s,%.3f,%.0f,%.2f,%.0f\n", r.name, 1e3 * s, r.bytesPerCell, gbs, 100 * gbs / copy);
    }
    PetscRandomDestroy(&rnd);
    for (Vec* v : {&uL, &N, &L, &a, &b, &div, &phiL}) VecDestroy(v);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_kernels: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 2);
  }
  PetscFinalize();
  return 0;
}
