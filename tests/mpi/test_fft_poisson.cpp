// The FFT pressure solver (-pressure_pc_type fft): exact on the discrete eigenfunctions for every
// mix of wall and periodic axes, equal to BoomerAMG's solution, refused beyond one z slab per rank.
#include "vp/core/Error.hpp"
#include "vp/fluid/PressureSolver.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace vp;

namespace {

// Options for the solver built inside; removed again on destruction, with the KSP type the
// solver chose for them.
struct PressureOptions {
  explicit PressureOptions(const char* pc) { PetscOptionsSetValue(nullptr, "-pressure_pc_type", pc); }
  ~PressureOptions()
  {
    PetscOptionsClearValue(nullptr, "-pressure_pc_type");
    PetscOptionsClearValue(nullptr, "-pressure_ksp_type");
  }
};

GridConfig box(PetscInt nx, PetscInt ny, PetscInt nz)
{
  GridConfig g;
  g.n = {nx, ny, nz};
  g.hi = {1.2, 0.7, 0.9};  // unequal spacings
  return g;
}

BoundaryConfig axes(bool px, bool py, bool pz)
{
  BoundaryConfig bc;
  const bool periodic[3] = {px, py, pz};
  for (int d = 0; d < 3; ++d)
    bc.type[2 * d] = bc.type[2 * d + 1] = periodic[d] ? BcType::Periodic : BcType::Wall;
  return bc;
}

// The discrete eigenfunction of lap_h with wave numbers m per axis: cos(pi m (i + 1/2) / N) on a
// wall axis, cos(2 pi m i / N + 0.3) on a periodic one; returns its eigenvalue of -lap_h.
double fillEigenfunction(const Grid& g, const int m[3], Vec v)
{
  PetscScalar*** a;
  VP_CALL(DMDAVecGetArray(g.cellDM(), v, &a));
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i) {
        const PetscInt q[3] = {i, j, k};
        double f = 1;
        for (int d = 0; d < 3; ++d)
          f *= g.periodic(d) ? std::cos(2 * M_PI * m[d] * q[d] / g.n(d) + 0.3) : std::cos(M_PI * m[d] * (q[d] + 0.5) / g.n(d));
        a[k][j][i] = f;
      }
  VP_CALL(DMDAVecRestoreArray(g.cellDM(), v, &a));
  double lambda = 0;
  for (int d = 0; d < 3; ++d) {
    const double theta = (g.periodic(d) ? 2 : 1) * M_PI * m[d] / g.n(d);
    lambda += (2 - 2 * std::cos(theta)) / (g.h(d) * g.h(d));
  }
  return lambda;
}

double maxNorm(Vec v)
{
  PetscReal n;
  VP_CALL(VecNorm(v, NORM_INFINITY, &n));
  return n;
}

} // namespace

TEST_CASE("fft solves the 7-point Poisson problem exactly on its eigenfunctions", "[mpi][fft]")
{
  const auto [px, py, pz] = GENERATE(std::make_tuple(false, false, false), std::make_tuple(true, true, true),
                                     std::make_tuple(false, true, false), std::make_tuple(true, false, true));
  BoundaryConfig bc = axes(px, py, pz);
  Grid g(PETSC_COMM_WORLD, box(12, 10, 6), bc);
  PressureOptions opts("fft");
  PressureSolver ps(g, readSolverOptions());
  Vec phi, b, x;
  VP_CALL(DMCreateGlobalVector(g.cellDM(), &phi));
  VP_CALL(VecDuplicate(phi, &b));
  VP_CALL(VecDuplicate(phi, &x));
  for (const auto& m : {std::array<int, 3>{1, 0, 0}, std::array<int, 3>{0, 0, 3}, std::array<int, 3>{3, 2, 1},
                        std::array<int, 3>{11, 5, 4}}) {
    const double lambda = fillEigenfunction(g, m.data(), phi);
    VP_CALL(VecCopy(phi, b));
    VP_CALL(VecScale(b, lambda));  // b = -lap_h phi
    VP_CALL(VecSet(x, 0));
    CHECK(ps.solve(b, x, 0) == 1);  // one direct application
    VP_CALL(VecAXPY(x, -1.0, phi));
    CHECK(maxNorm(x) <= 1e-12);
  }
  for (Vec* v : {&phi, &b, &x}) VecDestroy(v);
}

TEST_CASE("fft and BoomerAMG give the same pressure", "[mpi][fft]")
{
  BoundaryConfig bc = axes(false, true, false);
  Grid g(PETSC_COMM_WORLD, box(16, 12, 10), bc);
  Vec b, b2, xFft, xAmg;
  VP_CALL(DMCreateGlobalVector(g.cellDM(), &b));
  VP_CALL(VecSetRandom(b, nullptr));
  for (Vec* v : {&b2, &xFft, &xAmg}) VP_CALL(VecDuplicate(b, v));
  VP_CALL(VecCopy(b, b2));
  VP_CALL(VecSet(xFft, 0));
  VP_CALL(VecSet(xAmg, 0));
  {
    PressureOptions opts("fft");
    PressureSolver(g, readSolverOptions()).solve(b, xFft, 0);
  }
  PetscOptionsSetValue(nullptr, "-pressure_ksp_rtol", "1e-12");
  PressureSolver(g, readSolverOptions()).solve(b2, xAmg, 0);  // the default, CG + BoomerAMG, to near round-off
  PetscOptionsClearValue(nullptr, "-pressure_ksp_rtol");
  // Both have the constant mode removed: compare after subtracting the means.
  PetscScalar mean[2];
  VP_CALL(VecSum(xFft, &mean[0]));
  VP_CALL(VecSum(xAmg, &mean[1]));
  VP_CALL(VecShift(xFft, -mean[0] / g.cells()));
  VP_CALL(VecShift(xAmg, -mean[1] / g.cells()));
  const double scale = maxNorm(xFft);
  VP_CALL(VecAXPY(xAmg, -1.0, xFft));
  CHECK(maxNorm(xAmg) <= 1e-8 * scale);
  for (Vec* v : {&b, &b2, &xFft, &xAmg}) VecDestroy(v);
}

TEST_CASE("fft with more ranks than z slabs is refused, naming the option", "[mpi][fft]")
{
  int size;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size < 2) return;
  Grid g(PETSC_COMM_WORLD, box(12, 12, 1), axes(false, false, true));
  PressureOptions opts("fft");
  try {
    PressureSolver ps(g, readSolverOptions());
    FAIL("accepted " << size << " ranks for 1 z slab");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("-pressure_pc_type") != std::string::npos);
  }
}
