// -lub_coupling replace: the gap patches (coupling/LubricationPatches.hpp) and the whole open-edge
// LLCM squeeze of a replaced pair (interactions/LubricationModel.hpp, Llcm.hpp).
#include "../support/DemFixtures.hpp"
#include "vp/coupling/LubricationPatches.hpp"
#include "vp/interactions/Blcm.hpp"
#include "vp/interactions/Llcm.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using vp::test::sphere;

namespace {

// The LLCM replaced below one cell of 0.1 m and faded out over the next, patches of the default
// depth delta = a/5.
LubricationParams replacing()
{
  LubricationParams p;
  p.model = LubModel::Llcm;
  p.replace = true;
  p.activationCells = 1;
  p.patchBlendCells = 1;
  p.resolveDefaults(0.1, true, 4e-4);
  return p;
}

std::array<Wall, 6> floorOnly()
{
  std::array<Wall, 6> w;
  w[4].active = true;  // z low: face 4, normal +z
  w[4].axis = 2;
  return w;
}

} // namespace

TEST_CASE("Gap patches: each surface's disk facing a gap closer than h_act, ghosts included", "[lub]")
{
  ParticleStore s;
  s.append(sphere(0, {0, 0, 1.05}, 1, 1000));  // 0.05 above the floor
  s.append(sphere(2, {0, 4, 5}, 1, 1000));     // far from everything
  s.nOwned = 2;
  s.append(sphere(1, {2.08, 0, 1.05}, 1, 1000));  // a ghost, 0.08 from sphere 0 and 0.05 above the floor
  LubricationPatches patches(replacing(), floorOnly());
  patches.find(s);
  CHECK(patches.pairs() == 3);
  CHECK(patches.replaced(0, 1));
  CHECK(patches.replaced(1, 0));
  CHECK(patches.replaced(0, -5));
  CHECK(patches.replaced(1, -5));
  CHECK_FALSE(patches.replaced(0, 2));
  CHECK_FALSE(patches.replaced(2, -5));
  CHECK(patches.replacedAtWall(1));
  CHECK_FALSE(patches.replacedAtWall(2));
  CHECK_FALSE(patches.any(1));
  // Sphere 0 towards sphere 1: the disk r < sqrt(2 R delta) = 0.447 around +x (delta = a/5).
  CHECK(patches.patchAt(0, {0.99, 0, 0}) != nullptr);
  CHECK(patches.patchAt(0, {0.85, 0.4, 0.19}) != nullptr);  // 0.443 off the axis
  CHECK(patches.patchAt(0, {0.8, 0.41, 0.2}) == nullptr);  // 0.456 off it, above the floor's disk
  CHECK(patches.patchAt(0, {-0.99, 0, 0}) == nullptr);
  // Sphere 0 towards the floor: the disk r < sqrt(2 a delta) = 0.632 around -z.
  CHECK(patches.patchAt(0, {0, 0, -0.99}) != nullptr);
  CHECK(patches.patchAt(0, {0.45, 0.4, -0.7}) != nullptr);  // 0.602 off the axis
  CHECK(patches.patchAt(0, {0.45, 0.4, -0.7})->n.z == -1);
  CHECK(patches.patchAt(0, {0.45, 0.4, -0.7})->weight == 1);
  CHECK(patches.patchAt(0, {0.5, 0.4, -0.7}) == nullptr);  // 0.640 off it
  CHECK(patches.patchAt(0, {0.5, 0.4, 0.7}) == nullptr);
  // The ghost's patch towards sphere 0 (the rank holding its faces removes them too).
  CHECK(patches.patchAt(2, {-0.99, 0, 0}) != nullptr);
  CHECK(patches.patchAt(2, {0.99, 0, 0}) == nullptr);

  // Moved apart into the blend (0.12 apart, 0.15 above the floor): the replaced fraction falls from 1
  // at h_act = 0.1 to 0 at 0.2.
  s.x[0] = {0, 0, 1.15};
  s.x[2] = {2.12, 0, 1.15};
  patches.find(s);
  CHECK(patches.pairs() == 3);
  CHECK(patches.replaced(0, 1) == Approx(0.8).epsilon(1e-12));
  CHECK(patches.replaced(0, -5) == Approx(0.5).epsilon(1e-12));
  CHECK(patches.patchAt(0, {0.99, 0, 0})->weight == Approx(0.8).epsilon(1e-12));
  CHECK(patches.patchAt(2, {0, 0, -0.99})->weight == Approx(0.5).epsilon(1e-12));
  CHECK_FALSE(patches.replaced(0, 2));

  // Beyond the blend (0.21 apart, 0.22 above the floor): nothing replaced.
  s.x[0] = {0, 0, 1.22};
  s.x[2] = {2.21, 0, 1.22};
  patches.find(s);
  CHECK(patches.pairs() == 0);
  CHECK_FALSE(patches.any(0));
  CHECK(patches.patchAt(0, {0, 0, -0.99}) == nullptr);
}

TEST_CASE("A replaced pair takes the whole open-edge LLCM squeeze, at any gap until contact", "[lub]")
{
  LubricationParams p = replacing();
  for (double aj : {1.0, 0.5, kWallRadius}) {
    PairState s;
    s.normal = Vec3{0, 0, 1};
    s.radiusI = 1;
    s.radiusJ = aj;
    s.viscosity = 0.3;
    s.velocityI = {0, 0, 0.2};  // approaching: a pure squeeze
    for (double h : {0.01, 0.05, 0.3}) {  // below and above the activation gap (0.1)
      s.gap = h;
      const double H0 = h + 0.2 * std::min(1.0, aj);  // h + delta, delta = a/5 of the smaller sphere
      const Vec3 blcm = blcmForce(s).forceI;
      const Vec3 f = lubricationForce(p, s, 1e-3, 0, 1).forceI;
      CHECK(f.z == Approx(blcm.z * (1 - h / H0)).epsilon(1e-12));  // the inner pressure over the disk
      CHECK(f.z < 0);
      // Not replaced: the unresolved part below h_act, nothing above it.
      const Vec3 added = lubricationForce(p, s, 1e-3).forceI;
      if (h < 0.1) CHECK(std::fabs(added.z) < std::fabs(f.z));
      else CHECK(added.z == 0);
    }
    s.gap = 5e-4;  // within the contact gap: the contact law alone
    CHECK(norm(lubricationForce(p, s, 1e-3, 0, 1).forceI) == 0);
    // A pair replaced in part (in the blend at the step's start) takes that fraction of the patch's
    // squeeze and the rest of the unresolved part: the two mixed wherever its gap is then.
    for (double h : {0.01, 0.05, 0.3}) {
      s.gap = h;
      const double whole = lubricationForce(p, s, 1e-3, 0, 1).forceI.z, added = lubricationForce(p, s, 1e-3).forceI.z;
      CHECK(lubricationForce(p, s, 1e-3, 0, 0.3).forceI.z == Approx(0.3 * whole + 0.7 * added).epsilon(1e-12));
    }
  }
  // The tangential terms stay as without the replacement: added below their own activation gap.
  PairState w;
  w.normal = Vec3{0, 0, -1};
  w.radiusI = 1;
  w.radiusJ = kWallRadius;
  w.viscosity = 0.3;
  w.velocityI = {0.1, 0, -0.2};
  w.angularVelocityI = {0, 2, 0};
  for (double h : {0.002, 0.05}) {  // below and above the tangential activation gap (0.006)
    w.gap = h;
    const Vec3 replaced = lubricationForce(p, w, 1e-3, 0, 1).forceI, added = lubricationForce(p, w, 1e-3).forceI;
    CHECK(replaced.x == Approx(added.x).epsilon(1e-12));
    CHECK(replaced.z != Approx(added.z).epsilon(1e-6));
  }
}
