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
  s.addPair(PairStress::Contact, {1, 0, 0.5}, {0.5, 0, 0}, {2, 0, 0});
  // A sheared pair: d along z, F along x: xz = 0.5 (d_z F_x) = 0.5 * 0.2 * 3.
  s.addPair(PairStress::Lubrication, {0, 0, 0.6}, {0, 0, 0.2}, {3, 0, 0});
  // Midpoint z = 1.2 - 0.1 = 1.1: outside the core, not counted.
  s.addPair(PairStress::Contact, {0, 0, 1.2}, {0, 0, 0.2}, {5, 0, 0});
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
