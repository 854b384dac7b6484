// The pair share of the suspension stress (particles/PairStress.hpp): sum of sym(r_ij F_ij) over
// the pairs whose midpoint lies in the core, the walls' forces, means over the sub-steps.
#include "vp/particles/PairStress.hpp"
#include <catch2/catch.hpp>

using namespace vp;

TEST_CASE("Pair stress: symmetric moments of the pairs in the core, means over the sub-steps", "[dem]")
{
  PairStress s;
  s.enable(0.0, 1.0);
  // Two spheres pushed apart along x (F on i along +d): a compressive xx moment d F = 0.5 * 2.
  s.addPair(PairStress::Contact, {1, 0, 0.5}, {0.5, 0, 0}, {2, 0, 0}, false, false);
  // A sheared pair: d along z, F along x: xz = 0.5 (d_z F_x) = 0.5 * 0.2 * 3.
  s.addPair(PairStress::Lubrication, {0, 0, 0.6}, {0, 0, 0.2}, {3, 0, 0}, false, false);
  // Midpoint z = 1.2 - 0.1 = 1.1: outside the core, not counted.
  s.addPair(PairStress::Contact, {0, 0, 1.2}, {0, 0, 0.2}, {5, 0, 0}, false, false);
  s.addWall(PairStress::Contact, 4, {0.5, 0, 1});
  s.endSubstep();
  s.endSubstep();
  const PairStress::Mean m = s.take(MPI_COMM_SELF);
  CHECK(m.pairs[PairStress::Contact][0] == Approx(0.5));  // (0.5 * 2) over two sub-steps
  CHECK(m.pairs[PairStress::Contact][4] == 0);
  CHECK(m.pairs[PairStress::Lubrication][4] == Approx(0.15));
  CHECK(m.walls[PairStress::Contact][4].x == Approx(0.25));
  CHECK(m.walls[PairStress::Contact][4].z == Approx(0.5));
  // Taken: the sums start again.
  s.endSubstep();
  CHECK(s.take(MPI_COMM_SELF).pairs[PairStress::Contact][0] == 0);
}

TEST_CASE("Pair stress: a fixed particle's pairs are the force of the wall on its side", "[dem]")
{
  PairStress s;
  s.enable(0.2, 0.8);
  // Free i at z 0.5 in the core above fixed j at z 0.1 (bottom wall): the force on i is the wall's.
  s.addPair(PairStress::Lubrication, {0, 0, 0.5}, {0, 0, 0.4}, {-1, 0, 0.5}, false, true);
  // Fixed i at z 0.95 (top wall), free j below: the wall's force on j is minus the force on i.
  s.addPair(PairStress::Contact, {0, 0, 0.95}, {0, 0, 0.1}, {-2, 0, 0}, true, false);
  s.endSubstep();
  const PairStress::Mean m = s.take(MPI_COMM_SELF);
  CHECK(m.walls[PairStress::Lubrication][4].x == Approx(-1));
  CHECK(m.walls[PairStress::Lubrication][4].z == Approx(0.5));
  CHECK(m.walls[PairStress::Contact][5].x == Approx(2));
  // Neither is a pair of the core (the first's midpoint, z 0.3, lies in it).
  for (int k = 0; k < 2; ++k)
    for (double v : m.pairs[k]) CHECK(v == 0);
}
