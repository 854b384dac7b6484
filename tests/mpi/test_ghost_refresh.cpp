// GhostRefresh: the in-domain ghosts of a local face vector get the owners' values (across ranks
// and periodic boundaries), the ghosts beyond a wall and the owned values stay as they were.
#include "vp/core/Error.hpp"
#include "vp/grid/GhostRefresh.hpp"
#include "vp/grid/Grid.hpp"
#include <catch2/catch.hpp>

using namespace vp;

namespace {
// A value that names the point: global face indices (wrapped) and the component.
double tag(PetscInt i, PetscInt j, PetscInt k, int c) { return c + 10.0 * i + 1e3 * j + 1e5 * k; }
PetscInt wrap(PetscInt i, int n) { return (i + n) % n; }
} // namespace

TEST_CASE("the ghost refresh fills exactly the in-domain ghosts", "[mpi][grid]")
{
  Config cfg;
  cfg.grid.n = {7, 6, 5};
  // x and y periodic, z walls
  for (int f = 0; f < 4; ++f) cfg.bc.type[f] = BcType::Periodic;
  Grid g(PETSC_COMM_WORLD, cfg.grid, cfg.bc);
  DM da = g.faceSolveDM();
  GhostRefresh refresh(da);
  Vec loc;
  VP_CALL(DMCreateLocalVector(da, &loc));
  PetscInt gs[3], gm[3];
  VP_CALL(DMDAGetGhostCorners(da, &gs[0], &gs[1], &gs[2], &gm[0], &gm[1], &gm[2]));
  const double stale = -1;  // what a ghost holds before the refresh
  auto owned = [&](PetscInt i, PetscInt j, PetscInt k) {
    return i >= g.start(0) && i < g.end(0) && j >= g.start(1) && j < g.end(1) && k >= g.start(2) && k < g.end(2);
  };
  {
    PetscScalar**** a;
    VP_CALL(DMDAVecGetArrayDOF(da, loc, &a));
    for (PetscInt k = gs[2]; k < gs[2] + gm[2]; ++k)
      for (PetscInt j = gs[1]; j < gs[1] + gm[1]; ++j)
        for (PetscInt i = gs[0]; i < gs[0] + gm[0]; ++i)
          for (int c = 0; c < 3; ++c) a[k][j][i][c] = owned(i, j, k) ? tag(i, j, k, c) : stale;
    VP_CALL(DMDAVecRestoreArrayDOF(da, loc, &a));
  }
  refresh.apply(loc);
  long wrong = 0, refreshed = 0, wallGhosts = 0;
  {
    PetscScalar**** a;
    VP_CALL(DMDAVecGetArrayDOF(da, loc, &a));
    for (PetscInt k = gs[2]; k < gs[2] + gm[2]; ++k)
      for (PetscInt j = gs[1]; j < gs[1] + gm[1]; ++j)
        for (PetscInt i = gs[0]; i < gs[0] + gm[0]; ++i)
          for (int c = 0; c < 3; ++c) {
            const bool beyondWall = k < 0 || k >= g.n(2);
            double expected;
            if (beyondWall) {
              expected = stale;
              ++wallGhosts;
            } else {
              expected = tag(wrap(i, g.n(0)), wrap(j, g.n(1)), k, c);
              if (!owned(i, j, k)) ++refreshed;
            }
            if (a[k][j][i][c] != expected) ++wrong;
          }
    VP_CALL(DMDAVecRestoreArrayDOF(da, loc, &a));
  }
  VecDestroy(&loc);
  long leaves = refresh.ghostCount();
  MPI_Allreduce(MPI_IN_PLACE, &wrong, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  CHECK(wrong == 0);
  // The forest's leaves are exactly the in-domain ghosts (none beyond the walls).
  CHECK(leaves == refreshed);
  CHECK(leaves > 0);  // every rank has periodic or neighbour ghosts here
  CHECK(wallGhosts > 0);
}
