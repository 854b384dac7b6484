// Fluid core: discrete operators, projection, convergence to exact solutions, rank invariance.
#include "vp/Simulation.hpp"
#include "vp/core/Error.hpp"
#include "vp/fluid/AnalyticFlow.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/grid/FieldArray.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace vp;

namespace {

Config periodicBox(int nx, int ny, int nz, double lz)
{
  Config c;
  c.grid.n = {nx, ny, nz};
  c.grid.hi = {2 * M_PI, 2 * M_PI, lz};
  for (auto& t : c.bc.type) t = BcType::Periodic;
  c.fluid.rho = 1;
  c.fluid.mu = 0.05;
  c.output.files = false;
  c.output.monitorEvery = 0;
  return c;
}

// Max over owned free faces of |u - exact| (collective).
double maxError(Simulation& sim, const AnalyticFlow& flow)
{
  const Grid& g = sim.grid();
  Vec exact;
  VP_CALL(VecDuplicate(sim.fluid().velocity(), &exact));
  sampleVelocity(g, flow, sim.time(), exact);
  VP_CALL(VecAXPY(exact, -1.0, sim.fluid().velocity()));
  PetscReal e;
  VP_CALL(VecNorm(exact, NORM_INFINITY, &e));
  VecDestroy(&exact);
  return e;
}

// Solver options for tests that compare to round-off; removed again on destruction.
struct TightSolvers {
  TightSolvers()
  {
    PetscOptionsSetValue(nullptr, "-pressure_ksp_rtol", "1e-13");
    PetscOptionsSetValue(nullptr, "-velocity_ksp_rtol", "1e-13");
  }
  ~TightSolvers()
  {
    PetscOptionsClearValue(nullptr, "-pressure_ksp_rtol");
    PetscOptionsClearValue(nullptr, "-velocity_ksp_rtol");
  }
};

bool allRanks(MPI_Comm comm, bool ok)
{
  int in = ok ? 1 : 0, out;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MIN, comm);
  return out == 1;
}

Config mixedBox()
{
  Config c;
  c.grid.n = {9, 7, 6};
  c.grid.hi = {1.0, 0.7, 0.9};
  c.bc.type = {BcType::Wall, BcType::Velocity, BcType::Periodic, BcType::Periodic, BcType::Slip, BcType::Wall};
  c.bc.velocity[1] = {0, 0.3, -0.2};
  c.output.files = false;
  c.output.monitorEvery = 0;
  return c;
}

// Zeroes a face vector outside a ball about the box's centre (radius a third of its smallest side):
// rows that cross it, rows that do not.
void zeroOutsideBall(const Grid& g, Vec v)
{
  PetscScalar**** a;
  VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), v, &a));
  const double R = std::min({g.hi(0) - g.lo(0), g.hi(1) - g.lo(1), g.hi(2) - g.lo(2)}) / 3;
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i) {
        double r2 = 0;
        const PetscInt q[3] = {i, j, k};
        for (int d = 0; d < 3; ++d) r2 += std::pow(g.cellCentre(d, q[d]) - 0.5 * (g.lo(d) + g.hi(d)), 2);
        if (r2 > R * R)
          for (int c = 0; c < 3; ++c) a[k][j][i][c] = 0;
      }
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), v, &a));
}

} // namespace

TEST_CASE("div of grad equals minus the assembled Poisson matrix", "[mpi][operators]")
{
  Config c = mixedBox();
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  PressureSolver ps(g, readSolverOptions());
  Vec phi, phiL, grad, gradL, div, Aphi;
  VP_CALL(DMCreateGlobalVector(g.cellDM(), &phi));
  VP_CALL(VecSetRandom(phi, nullptr));
  VP_CALL(DMCreateLocalVector(g.cellDM(), &phiL));
  VP_CALL(DMGlobalToLocal(g.cellDM(), phi, INSERT_VALUES, phiL));
  VP_CALL(DMCreateGlobalVector(g.faceDM(), &grad));
  VP_CALL(VecSet(grad, 0));
  PetscScalar ***p, ****gr, ***dv;
  VP_CALL(DMDAVecGetArray(g.cellDM(), phiL, &p));
  fillCellGhosts(g, p);
  VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), grad, &gr));
  ops::addGradient(g, p, 1.0, gr);
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), grad, &gr));
  VP_CALL(DMDAVecRestoreArray(g.cellDM(), phiL, &p));
  // The gradient of a pressure never changes a wall's normal velocity: homogeneous ghosts.
  VP_CALL(DMCreateLocalVector(g.faceDM(), &gradL));
  VP_CALL(DMGlobalToLocal(g.faceDM(), grad, INSERT_VALUES, gradL));
  BoundaryConfig zero = c.bc;
  VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), gradL, &gr));
  fillFaceGhosts(g, zero, gr, true);
  VP_CALL(DMCreateGlobalVector(g.cellDM(), &div));
  VP_CALL(DMDAVecGetArray(g.cellDM(), div, &dv));
  ops::divergence(g, gr, dv);
  VP_CALL(DMDAVecRestoreArray(g.cellDM(), div, &dv));
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), gradL, &gr));
  VP_CALL(VecDuplicate(phi, &Aphi));
  VP_CALL(MatMult(ps.matrix(), phi, Aphi));
  VP_CALL(VecAXPY(Aphi, g.cellVolume(), div));  // A phi + V div grad phi
  PetscReal diff, scale;
  VP_CALL(VecNorm(Aphi, NORM_INFINITY, &diff));
  VP_CALL(VecNorm(div, NORM_INFINITY, &scale));
  REQUIRE(scale > 1);
  CHECK(diff <= 1e-13 * scale * g.cellVolume());
  for (Vec* v : {&phi, &phiL, &grad, &gradL, &div, &Aphi}) VecDestroy(v);
}

TEST_CASE("the advection sweep is exact for a linear flow, its Laplacian for a quadratic one", "[mpi][operators]")
{
  // The MAC scheme's midpoint averages and central differences are exact for these fields, so every
  // owned free face must match the formula to round-off. Linear and divergence-free, u_x = a.(1, y, z),
  // u_y = b.(1, x, z), u_z = e.(1, x, y): N_c = u . grad u_c, and the distinct coefficients tell
  // apart every neighbour the sweep reads for each (component, direction). Quadratic, u_c =
  // sum_d Q_cd x_d^2: L_c = 2 sum_d Q_cd, on a grid with three different spacings. The ghosts are
  // filled from the formula as well, so only the sweep is tested; fixed faces get N = L = 0.
  const Config c = mixedBox();
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  const double a[3] = {0.3, 1.7, -0.6}, b[3] = {-0.2, 0.9, 1.3}, e[3] = {0.5, -1.1, 0.4};
  const double Q[3][3] = {{0.7, -1.2, 2.1}, {1.4, 0.3, -0.8}, {-0.5, 1.9, 0.6}};
  auto linear = [&](int comp, const double x[3]) {
    return comp == 0 ? a[0] + a[1] * x[1] + a[2] * x[2] : comp == 1 ? b[0] + b[1] * x[0] + b[2] * x[2]
                                                                    : e[0] + e[1] * x[0] + e[2] * x[1];
  };
  auto quadratic = [&](int comp, const double x[3]) {
    return Q[comp][0] * x[0] * x[0] + Q[comp][1] * x[1] * x[1] + Q[comp][2] * x[2] * x[2];
  };
  // Position of face (i, j, k) of component comp: on the cell's low side along comp, mid-cell otherwise.
  auto position = [&](int comp, const PetscInt idx[3], double x[3]) {
    for (int d = 0; d < 3; ++d) x[d] = g.lo(d) + (double(idx[d]) + (d == comp ? 0.0 : 0.5)) * g.h(d);
  };
  Vec uL, N, L;
  VP_CALL(DMCreateLocalVector(g.faceDM(), &uL));
  VP_CALL(DMCreateGlobalVector(g.faceDM(), &N));
  VP_CALL(VecDuplicate(N, &L));
  PetscInt s[3], m[3];
  VP_CALL(DMDAGetGhostCorners(g.faceDM(), &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  for (const bool isLinear : {true, false}) {
    {
      FaceArray u(g.faceDM(), uL);
      for (PetscInt k = s[2]; k < s[2] + m[2]; ++k)
        for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
          for (PetscInt i = s[0]; i < s[0] + m[0]; ++i)
            for (int comp = 0; comp < 3; ++comp) {
              const PetscInt idx[3] = {i, j, k};
              double x[3];
              position(comp, idx, x);
              u.a[k][j][i][comp] = isLinear ? linear(comp, x) : quadratic(comp, x);
            }
    }
    double worst = 0;
    {
      FaceArray u(g.faceDM(), uL, true), n(g.faceDM(), N), l(g.faceDM(), L);
      ops::advectionAndLaplacian(g, u.a, n.a, l.a);
      for (PetscInt k = g.start(2); k < g.end(2); ++k)
        for (PetscInt j = g.start(1); j < g.end(1); ++j)
          for (PetscInt i = g.start(0); i < g.end(0); ++i)
            for (int comp = 0; comp < 3; ++comp) {
              const PetscInt idx[3] = {i, j, k};
              double x[3], v[3];
              position(comp, idx, x);
              for (int d = 0; d < 3; ++d) v[d] = linear(d, x);
              const double* grad = comp == 0 ? a : comp == 1 ? b : e;  // d u_comp / d x_d, skipping d = comp
              const int d1 = comp == 0 ? 1 : 0, d2 = comp == 2 ? 1 : 2;
              double expect = isLinear ? v[d1] * grad[1] + v[d2] * grad[2]
                                       : 2 * (Q[comp][0] + Q[comp][1] + Q[comp][2]);
              if (isFixedFace(g, comp, idx[comp])) expect = 0;
              const double got = isLinear ? n.a[k][j][i][comp] : l.a[k][j][i][comp];
              worst = std::max(worst, std::fabs(got - expect));
            }
    }
    INFO((isLinear ? "N of the linear flow" : "L of the quadratic flow") << ": largest error " << worst);
    CHECK(allRanks(PETSC_COMM_WORLD, worst < 1e-12));
  }
  for (Vec* v : {&uL, &N, &L}) VecDestroy(v);
}

TEST_CASE("the viscous operator equals the face Laplacian with its wall ghost rules", "[mpi][operators]")
{
  Config c = mixedBox();
  c.bc.type[4] = BcType::Wall;  // no-slip at z low as well: edges next to two walls
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  const std::string kind = GENERATE(std::string("fused"), std::string("shell"), std::string("assembled"));
  VP_CALL(PetscOptionsSetValue(nullptr, "-velocity_operator", kind.c_str()));
  DiffusionSolver ds(g, c.bc, readSolverOptions().viscousOperator);
  VP_CALL(PetscOptionsClearValue(nullptr, "-velocity_operator"));
  CHECK(ds.assembled() == (kind == "assembled"));
  Vec u, uL, N, L, theta, Au, expect;
  VP_CALL(DMCreateGlobalVector(g.faceDM(), &u));
  VP_CALL(VecSetRandom(u, nullptr));
  {
    // Fixed wall faces hold zero (homogeneous problem).
    PetscScalar**** a;
    VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), u, &a));
    for (PetscInt k = g.start(2); k < g.end(2); ++k)
      for (PetscInt j = g.start(1); j < g.end(1); ++j)
        for (PetscInt i = g.start(0); i < g.end(0); ++i) {
          const PetscInt q[3] = {i, j, k};
          for (int d = 0; d < 3; ++d)
            if (isFixedFace(g, d, q[d])) a[k][j][i][d] = 0;
        }
    VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), u, &a));
  }
  VP_CALL(DMCreateLocalVector(g.faceDM(), &uL));
  VP_CALL(DMGlobalToLocal(g.faceDM(), u, INSERT_VALUES, uL));
  for (Vec* v : {&N, &L, &theta, &Au, &expect}) {
    VP_CALL(VecDuplicate(u, v));
    VP_CALL(VecSet(*v, 0));
  }
  PetscScalar ****a, ****n, ****l;
  VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), uL, &a));
  fillFaceGhosts(g, c.bc, a, true);
  VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), N, &n));
  VP_CALL(DMDAVecGetArrayDOF(g.faceDM(), L, &l));
  ops::advectionAndLaplacian(g, a, n, l);
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), L, &l));
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), N, &n));
  VP_CALL(DMDAVecRestoreArrayDOF(g.faceDM(), uL, &a));
  // A u = S (1 + theta) u - a S L u with a random penalization theta >= 0, everywhere or (as
  // particles make it) over a part of the grid only: the product skips theta outside each row's
  // particles and S where it is 1, which must not change it.
  const double alpha = 0.3;
  VP_CALL(VecSetRandom(theta, nullptr));
  if (GENERATE(false, true)) zeroOutsideBall(g, theta);
  ds.setOperator(alpha, theta);
  VP_CALL(MatMult(ds.operatorMatrix(), u, Au));
  VP_CALL(VecPointwiseMult(expect, theta, u));
  VP_CALL(VecAXPY(expect, 1.0, u));
  VP_CALL(VecAXPY(expect, -alpha, L));
  VP_CALL(VecPointwiseMult(expect, expect, ds.weights()));
  VP_CALL(VecAXPY(Au, -1.0, expect));
  PetscReal diff, scale;
  VP_CALL(VecNorm(Au, NORM_INFINITY, &diff));
  VP_CALL(VecNorm(L, NORM_INFINITY, &scale));
  CHECK(diff <= 1e-12 * alpha * scale);
  // The operator is symmetric (what lets CG solve the Crank-Nicolson system), and the diagonal the
  // Jacobi preconditioner uses is its true diagonal.
  Mat explicitA;
  VP_CALL(MatComputeOperator(ds.operatorMatrix(), MATAIJ, &explicitA));
  PetscBool symmetric;
  VP_CALL(MatIsSymmetric(explicitA, 1e-12, &symmetric));
  CHECK(symmetric);
  Vec d0, d1;
  VP_CALL(VecDuplicate(u, &d0));
  VP_CALL(VecDuplicate(u, &d1));
  VP_CALL(MatGetDiagonal(explicitA, d0));
  VP_CALL(MatGetDiagonal(ds.operatorMatrix(), d1));
  VP_CALL(VecAXPY(d1, -1.0, d0));
  VP_CALL(VecNorm(d1, NORM_INFINITY, &diff));
  VP_CALL(VecNorm(d0, NORM_INFINITY, &scale));
  CHECK(diff <= 1e-13 * scale);
  MatDestroy(&explicitA);
  for (Vec* v : {&u, &uL, &N, &L, &theta, &Au, &expect, &d0, &d1}) VecDestroy(v);
}

TEST_CASE("the fused viscous CG solves what PETSc's CG + Jacobi solves", "[mpi][operators]")
{
  // Same operator (random penalization theta, walls of every kind), same right-hand side and
  // initial guess: the hand-fused CG and PETSc's KSPCG + PCJACOBI converge to the same solution in
  // about the same number of iterations (the sums differ only in their rounding order).
  Config c = mixedBox();
  c.bc.type[4] = BcType::Wall;
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  Vec r, theta, x[2];
  VP_CALL(DMCreateGlobalVector(g.faceDM(), &r));
  VP_CALL(VecDuplicate(r, &theta));
  PetscRandom rnd;
  VP_CALL(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  VP_CALL(PetscRandomSetSeed(rnd, 3));
  VP_CALL(PetscRandomSeed(rnd));
  VP_CALL(VecSetRandom(r, rnd));
  VP_CALL(VecSetRandom(theta, rnd));
  VP_CALL(VecScale(theta, 100));  // inside and outside particles: a diagonal varying by 100
  if (GENERATE(false, true)) zeroOutsideBall(g, theta);
  int its[2];
  const char* kinds[2] = {"fused", "shell"};
  for (int k = 0; k < 2; ++k) {
    VP_CALL(PetscOptionsSetValue(nullptr, "-velocity_operator", kinds[k]));
    DiffusionSolver ds(g, c.bc, readSolverOptions().viscousOperator);
    VP_CALL(PetscOptionsClearValue(nullptr, "-velocity_operator"));
    CHECK(ds.fused() == (k == 0));
    VP_CALL(VecDuplicate(r, &x[k]));
    VP_CALL(VecSet(x[k], 0.01));
    Vec rk;  // solve() overwrites its right-hand side
    VP_CALL(VecDuplicate(r, &rk));
    VP_CALL(VecCopy(r, rk));
    its[k] = ds.solve(2.0, rk, x[k], 0, theta);
    VecDestroy(&rk);  // a = nu dt / 2 = 2: a / h^2 about 100 per axis, a stiff step
  }
  INFO("iterations fused " << its[0] << ", PETSc " << its[1]);
  CHECK(its[0] > 5);
  CHECK(std::abs(its[0] - its[1]) <= 1);
  PetscReal diff, scale;
  VP_CALL(VecNorm(x[1], NORM_INFINITY, &scale));
  VP_CALL(VecAXPY(x[0], -1.0, x[1]));
  VP_CALL(VecNorm(x[0], NORM_INFINITY, &diff));
  CHECK(diff <= 1e-5 * scale);  // both stop at rtol 1e-6 on the residual
  PetscRandomDestroy(&rnd);
  for (Vec* v : {&r, &theta, &x[0], &x[1]}) VecDestroy(v);
}

TEST_CASE("every projection leaves max |div u| below 1e-6 |u|/dx", "[mpi][projection]")
{
  // A 3-D cavity: moving lid, walls, slip: every boundary kind at once.
  Config c = mixedBox();
  c.bc.type = {BcType::Wall, BcType::Wall, BcType::Slip, BcType::Velocity, BcType::Wall, BcType::Wall};
  c.bc.velocity = {};
  c.bc.velocity[3] = {1.0, 0, 0.5};
  c.fluid.mu = 0.01;
  c.time.maxSteps = 15;
  Simulation sim(PETSC_COMM_WORLD, RunConfig(c));
  double worst = 0;
  for (int s = 0; s < 15; ++s) {
    sim.advance(sim.nextDt());
    const auto& st = sim.fluid().stats();
    const double hmin = std::min({c.grid.hi[0] / 9, 0.7 / 7, 0.9 / 6});
    const double umax = st.maxRate * hmin;  // a lower bound of max|u|: conservative
    worst = std::max(worst, st.maxDivergence * hmin / umax);
  }
  INFO("worst relative divergence " << worst);
  CHECK(worst <= 1e-6);  // the default tolerances' contract (docs/fluid.md)
  CHECK(sim.fluid().stats().kineticEnergy > 0);
}

TEST_CASE("Taylor-Green 2-D: second order in space and time, energy decays at 4 nu", "[mpi][convergence]")
{
  TightSolvers tight;
  std::vector<double> err;
  double rate64 = 0;
  for (int n : {16, 32, 64}) {
    Config c = periodicBox(n, n, 2, 2 * M_PI / n * 2);
    c.fluid.init = InitFlow::TaylorGreen;
    c.time.final = 1.0;
    Simulation sim(PETSC_COMM_WORLD, RunConfig(c));
    const double ke0 = sim.fluid().stats().kineticEnergy;
    while (sim.time() < c.time.final * (1 - 1e-12)) sim.advance(sim.nextDt());
    err.push_back(maxError(sim, AnalyticFlow(c)));
    if (n == 64) rate64 = std::log(ke0 / sim.fluid().stats().kineticEnergy) / sim.time();
  }
  const double order1 = std::log2(err[0] / err[1]), order2 = std::log2(err[1] / err[2]);
  INFO("max errors " << err[0] << " " << err[1] << " " << err[2] << ", orders " << order1 << " " << order2);
  CHECK(order1 >= 1.9);
  CHECK(order2 >= 1.9);
  const double expected = 4 * 0.05;  // 4 nu
  INFO("energy decay rate " << rate64 << " vs 4 nu = " << expected);
  CHECK(std::fabs(rate64 / expected - 1) <= 0.01);
}

TEST_CASE("ABC flow 3-D: second order in all three components", "[mpi][convergence]")
{
  TightSolvers tight;
  std::vector<double> err;
  for (int n : {16, 32, 64}) {
    Config c = periodicBox(n, n, n, 2 * M_PI);
    c.fluid.init = InitFlow::Abc;
    c.time.final = 0.25;
    Simulation sim(PETSC_COMM_WORLD, RunConfig(c));
    while (sim.time() < c.time.final * (1 - 1e-12)) sim.advance(sim.nextDt());
    err.push_back(maxError(sim, AnalyticFlow(c)));
  }
  const double order1 = std::log2(err[0] / err[1]), order2 = std::log2(err[1] / err[2]);
  INFO("max errors " << err[0] << " " << err[1] << " " << err[2] << ", orders " << order1 << " " << order2);
  CHECK(order1 >= 1.9);
  CHECK(order2 >= 1.9);
}

TEST_CASE("plane Poiseuille flow from rest reaches the exact parabola", "[mpi][channel]")
{
  TightSolvers tight;
  Config c;
  c.grid.n = {4, 16, 3};
  c.grid.hi = {0.5, 1.0, 0.4};
  c.bc.type = {BcType::Periodic, BcType::Periodic, BcType::Wall, BcType::Wall, BcType::Periodic, BcType::Periodic};
  c.fluid.rho = 1;
  c.fluid.mu = 1;
  c.fluid.bodyForce = {1, 0, 0};
  c.time.dt = 0.01;
  c.time.final = 3.0;
  c.output.files = false;
  c.output.monitorEvery = 0;
  Simulation sim(PETSC_COMM_WORLD, RunConfig(c));
  while (sim.time() < c.time.final * (1 - 1e-12)) sim.advance(sim.nextDt());
  Config exact = c;
  exact.fluid.init = InitFlow::Poiseuille;
  const double umax = 1.0 / (2 * 1.0) * 0.25;  // f/(2 nu) (H/2)^2
  const double rel = maxError(sim, AnalyticFlow(exact)) / umax;
  INFO("max relative deviation from the parabola " << rel);
  CHECK(rel <= 1e-8);
}

TEST_CASE("the same run on 1, 2 and 3 ranks gives the same fields", "[mpi][invariance]")
{
  TightSolvers tight;
  int size, rank;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  Config c = mixedBox();
  c.grid.n = {12, 10, 9};
  c.bc.type = {BcType::Wall, BcType::Wall, BcType::Periodic, BcType::Periodic, BcType::Wall, BcType::Velocity};
  c.bc.velocity = {};
  c.bc.velocity[5] = {1, 0.5, 0};
  c.fluid.mu = 0.02;
  c.fluid.bodyForce = {0, 0.3, 0};
  // Fields in natural ordering on world rank 0, for every communicator size up to the world's.
  std::vector<std::vector<double>> fields;
  for (int s = 1; s <= size; ++s) {
    MPI_Comm sub;
    MPI_Comm_split(PETSC_COMM_WORLD, rank < s ? 0 : MPI_UNDEFINED, rank, &sub);
    if (sub != MPI_COMM_NULL) {
      Simulation sim(sub, RunConfig(c));
      for (int k = 0; k < 8; ++k) sim.advance(sim.nextDt());
      std::vector<double> all;
      for (auto [dm, v] : {std::pair{sim.grid().faceDM(), sim.fluid().velocity()},
                           std::pair{sim.grid().cellDM(), sim.fluid().pressure()}}) {
        Vec natural, seq;
        VecScatter toZero;
        VP_CALL(DMDACreateNaturalVector(dm, &natural));
        VP_CALL(DMDAGlobalToNaturalBegin(dm, v, INSERT_VALUES, natural));
        VP_CALL(DMDAGlobalToNaturalEnd(dm, v, INSERT_VALUES, natural));
        VP_CALL(VecScatterCreateToZero(natural, &toZero, &seq));
        VP_CALL(VecScatterBegin(toZero, natural, seq, INSERT_VALUES, SCATTER_FORWARD));
        VP_CALL(VecScatterEnd(toZero, natural, seq, INSERT_VALUES, SCATTER_FORWARD));
        if (rank == 0) {
          const PetscScalar* a;
          PetscInt n;
          VP_CALL(VecGetLocalSize(seq, &n));
          VP_CALL(VecGetArrayRead(seq, &a));
          all.insert(all.end(), a, a + n);
          VP_CALL(VecRestoreArrayRead(seq, &a));
        }
        VecScatterDestroy(&toZero);
        VecDestroy(&seq);
        VecDestroy(&natural);
      }
      if (rank == 0) fields.push_back(all);
      MPI_Comm_free(&sub);
    }
  }
  bool ok = true;
  if (rank == 0) {
    double scale = 0;
    for (double v : fields[0]) scale = std::max(scale, std::fabs(v));
    for (size_t s = 1; s < fields.size(); ++s) {
      double diff = 0;
      for (size_t i = 0; i < fields[0].size(); ++i) diff = std::max(diff, std::fabs(fields[s][i] - fields[0][i]));
      INFO("ranks " << s + 1 << " vs 1: max difference " << diff << " of " << scale);
      ok = ok && diff <= 1e-8 * scale;
      CHECK(diff <= 1e-8 * scale);
    }
  }
  REQUIRE(allRanks(PETSC_COMM_WORLD, ok));
}

TEST_CASE("the pressure start fitted from earlier solutions", "[mpi][projection]")
{
  Config c = mixedBox();
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  PressureSolver ps(g, readSolverOptions());
  Mat A = ps.matrix();
  Vec x[4], b, start, want;
  PetscRandom random;  // one generator: VecSetRandom(v, nullptr) would repeat the same values
  VP_CALL(PetscRandomCreate(PETSC_COMM_WORLD, &random));
  VP_CALL(PetscRandomSetFromOptions(random));
  for (Vec& v : x) {
    VP_CALL(DMCreateGlobalVector(g.cellDM(), &v));
    VP_CALL(VecSetRandom(v, random));
  }
  for (Vec* v : {&b, &start, &want}) VP_CALL(DMCreateGlobalVector(g.cellDM(), v));
  auto residual = [&](Vec guess) {  // |b - A guess|
    VP_CALL(MatMult(A, guess, want));
    VP_CALL(VecAYPX(want, -1.0, b));
    PetscReal r;
    VP_CALL(VecNorm(want, NORM_2, &r));
    return r;
  };
  PetscReal bn;
  SolutionHistory h(A, x[0], 3);
  h.start(x[0], start);  // empty: a zero start
  PetscReal s0;
  VP_CALL(VecNorm(start, NORM_2, &s0));
  CHECK(s0 == 0);
  for (int i = 0; i < 3; ++i) h.add(x[i]);
  h.add(x[2]);  // a repeated solution: left out of the fit, no singular system
  REQUIRE(h.size() == 3);

  SECTION("a right-hand side in the span is fitted exactly")
  {
    VP_CALL(VecAXPBYPCZ(want, 2.0, -1.0, 0.0, x[1], x[2]));  // want = 2 x1 - x2
    VP_CALL(MatMult(A, want, b));
    VP_CALL(VecNorm(b, NORM_2, &bn));
    h.start(b, start);
    CHECK(residual(start) <= 1e-10 * bn);
  }
  SECTION("never worse than the last solution alone, and the oldest goes when full")
  {
    VP_CALL(VecSetRandom(b, random));
    VP_CALL(VecNorm(b, NORM_2, &bn));
    h.start(b, start);
    const PetscReal fitted = residual(start);
    CHECK(fitted <= residual(x[2]) * (1 + 1e-12));
    CHECK(fitted <= bn * (1 + 1e-12));
    // The repeat took a place (x1, x2, x2 are stored): x0, the oldest, went.
    VP_CALL(MatMult(A, x[0], b));
    VP_CALL(VecNorm(b, NORM_2, &bn));
    h.start(b, start);
    CHECK(residual(start) > 1e-3 * bn);
    h.add(x[3]);
    VP_CALL(MatMult(A, x[3], b));
    VP_CALL(VecNorm(b, NORM_2, &bn));
    h.start(b, start);
    CHECK(residual(start) <= 1e-10 * bn);
  }
  for (Vec& v : x) VecDestroy(&v);
  for (Vec* v : {&b, &start, &want}) VecDestroy(v);
  PetscRandomDestroy(&random);
}

namespace {

// theta on the faces: c everywhere, or big inside a ball of radius r about the box centre.
void fillTheta(const Grid& g, Vec theta, double c, double big = 0, double r = 0)
{
  FaceArray t(g.faceDM(), theta);
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i)
        for (int comp = 0; comp < 3; ++comp) {
          const PetscInt p[3] = {i, j, k};
          double d2 = 0;
          for (int d = 0; d < 3; ++d) {
            const double x = d == comp ? g.faceCoord(d, p[d]) : g.cellCentre(d, p[d]);
            const double m = 0.5 * (g.lo(d) + g.hi(d));
            d2 += (x - m) * (x - m);
          }
          t.a[k][j][i][comp] = d2 < r * r ? big : c;
        }
}

// One predictor + projection from the same lid-driven state; returns the velocity and the pressure.
std::pair<Vec, Vec> penalizedStep(const Grid& g, const Config& c, bool weighted, Vec theta, Vec thetaUs, int steps)
{
  Projection fluid(g, c, readSolverOptions(), weighted);
  fluid.applyBoundaryConditions();
  for (int s = 0; s < steps; ++s) {
    fluid.predict(0.01, theta, thetaUs);
    fluid.project(0.01);
    fluid.finishStep();
  }
  Vec u, p;
  VP_CALL(VecDuplicate(fluid.velocity(), &u));
  VP_CALL(VecCopy(fluid.velocity(), u));
  VP_CALL(VecDuplicate(fluid.pressure(), &p));
  VP_CALL(VecCopy(fluid.pressure(), p));
  return {u, p};
}

} // namespace

TEST_CASE("the weighted projection completes the implicit penalized step", "[mpi][projection]")
{
  TightSolvers tight;
  Config c;
  c.grid.n = {12, 10, 8};
  c.grid.hi = {1.2, 1.0, 0.8};
  c.bc.type = {BcType::Wall, BcType::Wall, BcType::Periodic, BcType::Periodic, BcType::Wall, BcType::Velocity};
  c.bc.velocity[5] = {1.0, 0, 0};
  c.fluid.mu = 0.02;
  c.output.files = false;
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  Vec theta, thetaUs;
  VP_CALL(DMCreateGlobalVector(g.faceDM(), &theta));
  VP_CALL(DMCreateGlobalVector(g.faceDM(), &thetaUs));
  VP_CALL(VecSet(thetaUs, 0));  // a solid at rest

  SECTION("a uniform theta: the same velocity as the plain projection, the pressure times 1 + theta")
  {
    // beta = 1/(1 + theta) uniform: psi_weighted = (1 + theta) psi, the correction beta grad psi
    // unchanged. One step: the next predictor's viscous solve turns the larger pressure gradient into
    // a field that is no longer a pure gradient near the walls, and the schemes part.
    fillTheta(g, theta, 2.0);
    auto [u0, p0] = penalizedStep(g, c, false, theta, thetaUs, 1);
    auto [u1, p1] = penalizedStep(g, c, true, theta, thetaUs, 1);
    PetscReal un, pn, du, dp;
    VP_CALL(VecNorm(u0, NORM_INFINITY, &un));
    VP_CALL(VecAXPY(u1, -1.0, u0));
    VP_CALL(VecNorm(u1, NORM_INFINITY, &du));
    // Pressure: defined up to a constant; compare after removing the means.
    for (Vec p : {p0, p1}) {
      PetscScalar s;
      PetscInt n;
      VP_CALL(VecSum(p, &s));
      VP_CALL(VecGetSize(p, &n));
      VP_CALL(VecShift(p, -s / n));
    }
    VP_CALL(VecNorm(p0, NORM_INFINITY, &pn));
    VP_CALL(VecAXPY(p1, -3.0, p0));
    VP_CALL(VecNorm(p1, NORM_INFINITY, &dp));
    INFO("velocity difference " << du / un << ", pressure difference " << dp / (3 * pn));
    CHECK(un > 1e-3);
    CHECK(du <= 1e-9 * un);
    CHECK(dp <= 1e-9 * 3 * pn);
    for (Vec v : {u0, u1, p0, p1}) VecDestroy(&v);
  }

  SECTION("a solid ball at rest: divergence-free, and the correction does not leak into the ball")
  {
    const double big = 1e4, r = 0.3;
    fillTheta(g, theta, 0.0, big, r);
    auto [u0, p0] = penalizedStep(g, c, false, theta, thetaUs, 3);
    auto [u1, p1] = penalizedStep(g, c, true, theta, thetaUs, 3);
    // The largest speed on faces inside the ball (the solid's velocity is zero), and div u.
    auto inside = [&](Vec u) {
      Vec mask;
      VP_CALL(VecDuplicate(u, &mask));
      fillTheta(g, mask, 0.0, 1.0, r);
      VP_CALL(VecPointwiseMult(mask, mask, u));
      PetscReal m;
      VP_CALL(VecNorm(mask, NORM_INFINITY, &m));
      VecDestroy(&mask);
      return m;
    };
    const double leak0 = inside(u0), leak1 = inside(u1);
    PetscReal un;
    VP_CALL(VecNorm(u1, NORM_INFINITY, &un));
    INFO("speed inside the ball: plain " << leak0 << ", weighted " << leak1 << " (max |u| " << un << ")");
    // The plain projection moves the solid's faces by the full pressure correction; the weighted
    // one by 1/(1 + theta) of it: the ball stays at rest to the penalization's own error.
    CHECK(leak0 > 1e-3 * un);
    CHECK(leak1 < 1e-2 * leak0);
    Projection probe(g, c, readSolverOptions(), true);  // divergence of the weighted result, through the stats of a copy
    VP_CALL(VecCopy(u1, probe.velocity()));
    const auto& st = probe.finishStep();
    const double h = 0.1;
    CHECK(st.maxDivergence * h <= 1e-9 * un);
    for (Vec v : {u0, u1, p0, p1}) VecDestroy(&v);
  }
  VecDestroy(&theta);
  VecDestroy(&thetaUs);
}
