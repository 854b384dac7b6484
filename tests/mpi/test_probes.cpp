// Pressure probes: trilinear interpolation is exact for a linear pressure between the first and
// last cell centres, beyond them a wall's mirror holds the first cell's value, a periodic axis
// wraps, and the values do not depend on the rank count (each cell's owner adds it).
#include "vp/core/Error.hpp"
#include "vp/io/Probes.hpp"
#include <catch2/catch.hpp>
#include <random>

using namespace vp;

namespace {

double linear(const Vec3& x) { return 1 + 2 * x.x - 3 * x.y + 0.5 * x.z; }

} // namespace

TEST_CASE("pressure probes interpolate the cell-centred pressure", "[mpi][probes]")
{
  GridConfig gc;
  gc.n = {12, 10, 8};
  gc.hi = {1.2, 1.0, 0.8};
  BoundaryConfig bc;  // walls, z periodic
  bc.type[4] = bc.type[5] = BcType::Periodic;
  Grid g(PETSC_COMM_WORLD, gc, bc);
  Vec p;
  VP_CALL(DMCreateGlobalVector(g.cellDM(), &p));
  PetscScalar*** a;
  VP_CALL(DMDAVecGetArray(g.cellDM(), p, &a));
  for (PetscInt k = g.start(2); k < g.end(2); ++k)
    for (PetscInt j = g.start(1); j < g.end(1); ++j)
      for (PetscInt i = g.start(0); i < g.end(0); ++i)
        a[k][j][i] = linear({g.cellCentre(0, i), g.cellCentre(1, j), 0.35});  // constant along the periodic z
  VP_CALL(DMDAVecRestoreArray(g.cellDM(), p, &a));

  std::mt19937_64 rng(3);
  std::vector<Vec3> points;
  std::vector<double> expected;
  for (int n = 0; n < 50; ++n) {
    // Between the first and last cell centres in x and y; anywhere (wrapping) in z.
    const Vec3 x{0.05 + 1.1 * std::uniform_real_distribution<double>(0, 1)(rng),
                 0.05 + 0.9 * std::uniform_real_distribution<double>(0, 1)(rng),
                 0.8 * std::uniform_real_distribution<double>(0, 1)(rng)};
    points.push_back(x);
    expected.push_back(linear({x.x, x.y, 0.35}));
  }
  points.push_back({0.01, 0.5, 0.4});  // within half a cell of the x wall: the first cell's value
  expected.push_back(linear({0.05, 0.5, 0.35}));
  Probes probes(g, points, "");
  const std::vector<double> v = probes.sample(p);
  for (std::size_t n = 0; n < points.size(); ++n) CHECK(v[n] == Approx(expected[n]).epsilon(1e-12));
  VecDestroy(&p);
}
