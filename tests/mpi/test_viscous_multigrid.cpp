// The viscous multigrid: its grids, its transfers and the CG it preconditions (1-3 ranks).
#include "vp/core/Error.hpp"
#include "vp/core/VecValues.hpp"
#include "vp/fluid/DiffusionSolver.hpp"
#include "vp/fluid/ViscousMultigrid.hpp"
#include "vp/grid/FieldArray.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

using namespace vp;

namespace {

// Walls of every kind and one periodic axis (y, or x with periodicX), split along one axis so
// that 1, 2 and 3 ranks can halve it twice.
Config multigridBox(int splitAxis = 2, bool periodicX = false)
{
  Config c;
  c.grid.n = {24, 8, 24};
  c.grid.hi = {1.5, 0.5, 1.5};
  c.bc.type = {BcType::Wall, BcType::Velocity, BcType::Periodic, BcType::Periodic, BcType::Slip, BcType::Wall};
  if (periodicX) c.bc.type = {BcType::Periodic, BcType::Periodic, BcType::Wall, BcType::Velocity, BcType::Slip, BcType::Wall};
  int size;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  c.grid.ranks = {1, 1, 1};
  c.grid.ranks[splitAxis] = size;
  return c;
}

// Sets every owned face of a local vector to its position along its own normal (face index times
// h; the staggering's coordinate), or checks the owned faces away from the boundaries against it.
// Interior: a face whose neighbours along the normal both exist and are not wrapped or fixed.
void normalCoordinate(const Grid& g, Vec local, bool set, double& worst)
{
  FaceArray a(g.faceSolveDM(), local);
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i)
        for (int c = 0; c < 3; ++c) {
          const PetscInt q[3] = {i, j, k};
          const double x = q[c] * g.h(c);
          if (set) {
            a.a[k][j][i][c] = x;
          } else if (q[c] >= 1 && q[c] <= g.n(c) - 2) {
            worst = std::max(worst, std::abs(a.a[k][j][i][c] - x));
          }
        }
}

double dot(Vec a, Vec b)
{
  PetscScalar d;
  VP_CALL(VecDot(a, b, &d));
  return d;
}

// A random local vector of solver `op`'s grid, its ghosts refreshed (fixed wall faces zero).
void randomLocal(const DiffusionSolver& op, DM da, Vec local, PetscRandom rnd)
{
  Vec g;
  VP_CALL(DMGetGlobalVector(da, &g));
  VP_CALL(VecSetRandom(g, rnd));
  VP_CALL(DMGlobalToLocal(da, g, INSERT_VALUES, local));
  VP_CALL(DMRestoreGlobalVector(da, &g));
  op.refreshGhosts(local);
}

// The owned values of a local vector into a global one (DMLocalToGlobal would also insert
// periodic ghosts that this rank holds itself).
void ownedValues(const DiffusionSolver& op, Vec local, Vec global)
{
  ReadValues l(local);
  WriteValues g(global);
  op.forRows([&](PetscInt o, PetscInt lo, PetscInt len) {
    for (PetscInt i = 0; i < len; ++i) g[o + i] = l[lo + i];
  });
}

} // namespace

TEST_CASE("the multigrid's transfers: the restriction is the prolongation's transpose over 8, both exact "
          "for a field linear along each face's normal", "[mpi][multigrid]")
{
  const int variant = GENERATE(0, 1, 2);  // split in z; split in x; split in x with x periodic
  Config c = multigridBox(variant == 0 ? 2 : 0, variant == 2);
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  DiffusionSolver ds(g, c.bc, ViscousOperator::Fused, 3);
  REQUIRE(ds.multigrid());
  const ViscousMultigrid& mg = *ds.multigrid();
  CHECK(mg.levels() == 3);
  CHECK(mg.grid(1).n(0) == 12);
  CHECK(mg.grid(2).n(2) == 6);
  CHECK(mg.grid(2).h(1) == Approx(4 * g.h(1)));
  PetscRandom rnd;
  VP_CALL(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  for (size_t l = 0; l + 1 < static_cast<size_t>(mg.levels()); ++l) {
    DM fd = mg.grid(l).faceSolveDM(), cd = mg.grid(l + 1).faceSolveDM();
    Vec uL, vL, Ru, Pv, u;
    VP_CALL(DMCreateLocalVector(fd, &uL));
    VP_CALL(DMCreateLocalVector(cd, &vL));
    VP_CALL(DMCreateGlobalVector(cd, &Ru));
    VP_CALL(DMCreateGlobalVector(fd, &u));
    VP_CALL(DMCreateGlobalVector(fd, &Pv));
    randomLocal(mg.op(l), fd, uL, rnd);
    randomLocal(mg.op(l + 1), cd, vL, rnd);
    mg.restrictTo(l, uL, Ru);
    Vec v;  // the coarse owned values of vL
    VP_CALL(DMCreateGlobalVector(cd, &v));
    ownedValues(mg.op(l + 1), vL, v);
    // P v: prolong onto a zero fine vector.
    Vec pL;
    VP_CALL(DMCreateLocalVector(fd, &pL));
    VP_CALL(VecZeroEntries(pL));
    mg.prolongAdd(l, vL, pL);
    ownedValues(mg.op(l), pL, Pv);
    ownedValues(mg.op(l), uL, u);
    const double lhs = 8 * dot(Ru, v), rhs = dot(u, Pv);
    INFO("level " << l << ": 8 <R u, v> = " << lhs << ", <u, P v> = " << rhs);
    CHECK(lhs == Approx(rhs).epsilon(1e-12));
    // Linear along the normal, whatever across: full weighting and linear interpolation are exact
    // away from the boundaries (a transfer that used another component's staggering is not).
    double worst = 0;
    normalCoordinate(mg.grid(l), uL, true, worst);
    mg.op(l).refreshGhosts(uL);
    mg.restrictTo(l, uL, Ru);
    VP_CALL(VecZeroEntries(vL));
    {  // R u's owned values into the local layout
      WriteValues vv(vL);
      ReadValues rv(Ru);
      mg.op(l + 1).forRows([&](PetscInt o, PetscInt lo, PetscInt len) {
        for (PetscInt i = 0; i < len; ++i) vv[lo + i] = rv[o + i];
      });
    }
    normalCoordinate(mg.grid(l + 1), vL, false, worst);
    CHECK(worst <= 1e-12);
    normalCoordinate(mg.grid(l + 1), vL, true, worst);
    mg.op(l + 1).refreshGhosts(vL);
    VP_CALL(VecZeroEntries(pL));
    mg.prolongAdd(l, vL, pL);
    normalCoordinate(mg.grid(l), pL, false, worst);
    CHECK(worst <= 1e-12);
    for (Vec* w : {&uL, &vL, &Ru, &Pv, &u, &v, &pL}) VecDestroy(w);
  }
  PetscRandomDestroy(&rnd);
}

TEST_CASE("the multigrid-preconditioned CG solves what CG + Jacobi solves, in a third of the iterations",
          "[mpi][multigrid]")
{
  // A stiff step (a / h^2 = 128 per axis) with a penalization that varies by 1000 between
  // neighbouring faces, as at a particle's surface: the V-cycle is a symmetric positive definite
  // preconditioner (CG converges) and the grids remove the smooth error Jacobi leaves.
  Config c = multigridBox();
  Grid g(PETSC_COMM_WORLD, c.grid, c.bc);
  Vec r, theta, x[2];
  VP_CALL(DMCreateGlobalVector(g.faceSolveDM(), &r));
  VP_CALL(VecDuplicate(r, &theta));
  PetscRandom rnd;
  VP_CALL(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  VP_CALL(PetscRandomSetSeed(rnd, 5));
  VP_CALL(PetscRandomSeed(rnd));
  VP_CALL(VecSetRandom(r, rnd));
  {
    // theta 1000 inside a sphere of radius 0.3 at the box centre, 0 outside.
    PetscScalar**** t;
    VP_CALL(DMDAVecGetArrayDOF(g.faceSolveDM(), theta, &t));
    for (PetscInt k = g.start(2); k < g.end(2); ++k)
      for (PetscInt j = g.start(1); j < g.end(1); ++j)
        for (PetscInt i = g.start(0); i < g.end(0); ++i)
          for (int comp = 0; comp < 3; ++comp) {
            const double p[3] = {(i + 0.5 * (comp != 0)) * g.h(0) - 0.5, (j + 0.5 * (comp != 1)) * g.h(1) - 0.25,
                                 (k + 0.5 * (comp != 2)) * g.h(2) - 0.75};
            t[k][j][i][comp] = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] < 0.09 ? 1000 : 0;
          }
    VP_CALL(DMDAVecRestoreArrayDOF(g.faceSolveDM(), theta, &t));
  }
  const double a = 128 * g.h(0) * g.h(0);
  int its[2];
  for (int k = 0; k < 2; ++k) {
    DiffusionSolver ds(g, c.bc, ViscousOperator::Fused, k == 0 ? 1 : 3);
    CHECK((ds.multigrid() != nullptr) == (k == 1));
    VP_CALL(VecDuplicate(r, &x[k]));
    VP_CALL(VecSet(x[k], 0.0));
    Vec rk;  // solve() overwrites its right-hand side
    VP_CALL(VecDuplicate(r, &rk));
    VP_CALL(VecCopy(r, rk));
    its[k] = ds.solve(a, rk, x[k], 0, theta);
    VecDestroy(&rk);
  }
  INFO("iterations Jacobi " << its[0] << ", multigrid " << its[1]);
  CHECK(its[0] > 20);
  CHECK(3 * its[1] <= its[0]);
  PetscReal diff, scale;
  VP_CALL(VecNorm(x[0], NORM_INFINITY, &scale));
  VP_CALL(VecAXPY(x[1], -1.0, x[0]));
  VP_CALL(VecNorm(x[1], NORM_INFINITY, &diff));
  CHECK(diff <= 1e-5 * scale);  // both stop at rtol 1e-6 on the residual
  PetscRandomDestroy(&rnd);
  for (Vec* v : {&r, &theta, &x[0], &x[1]}) VecDestroy(v);
}
