// particles/ContactHandOff on its own (docs/collisions.md, "The model of a collision"): which contacts
// switch a particle's resolved force off (`limit`: beyond the buoyant-weight overlap), which count as
// an impact (beyond twice it), how a departure starts and ends, and what force the kicks see.
#include "../support/DemFixtures.hpp"
#include "vp/particles/ContactHandOff.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using namespace vp::test;

namespace {

constexpr double kA = 1.5e-3, kSteel = 7800, kRho = 935, kMu = 0.01, kG = 9.81, kKn = 1e4;

ParticleStore twoSpheres()
{
  ParticleStore s;
  s.append(sphere(0, {0, 0, 0}, kA, kSteel, {0, 0, -0.5}));
  s.append(sphere(1, {0, 0, 3 * kA}, kA, kSteel, {0, 0, 0.5}));
  s.nOwned = 2;
  s.fhyd[0] = {1, 2, 3};
  s.thyd[0] = {4, 5, 6};
  return s;
}

// The overlap at which the sphere's buoyant weight alone presses into a contact of stiffness kKn.
double restingOverlap(const ParticleStore& s) { return (1 - kRho / kSteel) * s.mass[0] * kG / kKn; }

} // namespace

TEST_CASE("hand-off: limit excludes the resolved force beyond the buoyant-weight overlap, an impact beyond twice it", "[handoff]")
{
  const ContactHandOff h(ContactHydro::Limit, 2.5e-4, false, kRho, kMu, {0, 0, -kG});
  ParticleStore s = twoSpheres();
  const double rest = restingOverlap(s);
  h.startForces(s);
  h.touchWall(s, 0, 0.9 * rest, kKn);  // a sphere resting on the floor keeps its drag and pressure
  CHECK(s.flags[0] == kTouching);
  CHECK(h.resolvedForce(s, 0).x == 1);
  h.startForces(s);
  h.touchWall(s, 0, 1.5 * rest, kKn);  // pressed harder: excluded, not yet an impact
  CHECK(s.flags[0] == (kTouching | kResolvedForceOff));
  const Vec3 buoyancy = h.resolvedForce(s, 0);  // -rho V g: what the fluid's pressure does not carry
  CHECK(buoyancy.z == Approx(kRho / kSteel * s.mass[0] * kG).epsilon(1e-12));
  CHECK(h.resolvedTorque(s, 0).x == 0);
  h.startForces(s);
  h.touchWall(s, 0, 2.5 * rest, kKn);  // an impact: a departure candidate for the next force loop
  CHECK(s.flags[0] == (kTouching | kResolvedForceOff | kWallImpact));
  CHECK(h.touchPair(s, 0, 1, 2.5 * rest, kKn) == kPairImpact);
  CHECK(h.touchPair(s, 0, 1, 1.5 * rest, kKn) == 0);
}

TEST_CASE("hand-off: a departure starts after an impact, holds while leaving below the gap and ends above it", "[handoff]")
{
  const double gap = 2.5e-4;
  const ContactHandOff h(ContactHydro::Limit, gap, false, kRho, kMu, {0, 0, -kG});
  ParticleStore s = twoSpheres();
  h.startForces(s);
  h.touchWall(s, 0, 3 * restingOverlap(s), kKn);
  h.startForces(s);  // the next loop: out of contact, a candidate
  CHECK(s.flags[0] == kDeparting);
  const Vec3 up{0, 0, 1};
  s.v[0] = {0, 0, 0.3};
  CHECK(h.wallLeaving(s, 0, {}, up, 0.5 * gap));
  CHECK_FALSE(h.wallLeaving(s, 0, {}, up, 1.5 * gap));  // beyond the departure gap
  s.v[0] = {0, 0, -0.3};
  CHECK_FALSE(h.wallLeaving(s, 0, {}, up, 0.5 * gap));  // turned back
  h.endWalls(s, 0, true);
  CHECK(h.resolvedOff(s, 0));
  h.endWalls(s, 0, false);
  CHECK_FALSE(h.resolvedOff(s, 0));
  // Pairs: the state travels with the pair; a new impact ends a departure.
  s.v[0] = {0, 0, -0.3};  // sphere 0 below sphere 1, moving apart along n from 1 to 0
  const Vec3 n{0, 0, -1};
  CHECK(h.pairLeaving(s, 0, 1, n, 0.5 * gap, kPairImpact));
  CHECK_FALSE(h.pairLeaving(s, 0, 1, n, 0.5 * gap, 0));
  CHECK(h.pairState(s, 0, 1, 0, true) == kPairLeaving);
  CHECK((s.flags[1] & kPairDeparting));
  CHECK(h.pairState(s, 0, 1, kPairImpact, true) == kPairImpact);
  // The departure's film: the correction from the departure gap, or the activation if larger.
  LubricationParams lub;
  lub.activation = 0.1;
  CHECK(h.departureFilm(lub, kA).activation == Approx(gap / kA));
  CHECK(h.departureFilm(lub, 10 * kA).activation == Approx(0.1));
}

TEST_CASE("hand-off: keep leaves every flag alone, and no departure without limit", "[handoff]")
{
  const ContactHandOff keep(ContactHydro::Keep, 2.5e-4, true, kRho, kMu, {0, 0, -kG});
  CHECK(keep.departureGap() == 0);
  CHECK_FALSE(keep.history());
  ParticleStore s = twoSpheres();
  s.flags[0] = kDeparting | kWallImpact;
  keep.startForces(s);
  keep.touchWall(s, 0, 1, kKn);
  CHECK(keep.touchPair(s, 0, 1, 1, kKn) == 0);
  CHECK(s.flags[0] == (kDeparting | kWallImpact));  // a checkpoint's flags: dropStale clears them
  keep.dropStale(s);
  CHECK(s.flags[0] == 0);
  const ContactHandOff exclude(ContactHydro::Exclude, 2.5e-4, false, kRho, kMu, {0, 0, -kG});
  CHECK(exclude.departureGap() == 0);
  exclude.startForces(s);
  exclude.touchWall(s, 0, 1e-12, kKn);  // any contact
  CHECK(exclude.resolvedOff(s, 0));
}
