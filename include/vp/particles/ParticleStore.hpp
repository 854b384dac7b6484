#pragma once
// Particle storage: struct of arrays, owned particles first ([0, nOwned)), then ghosts (copies of
// neighbours' particles, periodic images shifted). Global ids are unique and stable.
#include "vp/particles/ParticleFields.hpp"
#include <vector>

namespace vp {

// kFixed: infinite mass and inertia; moves with its given constant velocity and spin (a prescribed
// motion; held in place when they are zero). The other bits of `flags` belong to the hand-off of the
// resolved force, lubrication and contact (particles/ContactHandOff.hpp).
enum ParticleFlag : std::uint8_t { kFixed = 1 };

// Everything one particle carries when it changes owner (docs/particles.md, parallel decomposition):
// the fields of ParticleFields.hpp.
struct ParticleRecord {
#define VP_RECORD_MEMBER(T, m, cols, snap, sync) T m{};
  VP_PARTICLE_FIELDS(VP_RECORD_MEMBER)
#undef VP_RECORD_MEMBER
};

// Owned particles first, then ghosts; one vector per field of ParticleFields.hpp (ghost entries
// hold the kCreate/kStep fields only) and the derived ones.
struct ParticleStore {
#define VP_STORE_MEMBER(T, m, cols, snap, sync) std::vector<T> m;
  VP_PARTICLE_FIELDS(VP_STORE_MEMBER)
#undef VP_STORE_MEMBER
  // Derived on append: inverse mass and moment of inertia (0 when fixed; a non-sphere's largest
  // principal one, its three in the body frame in invInertiaBody), position at the last rebuild,
  // bit f of wallTouch: wallSpring[f] may be non-zero.
  std::vector<double> mass, invMass, invInertia;
  std::vector<Vec3> invInertiaBody;
  std::vector<double> bound;  // the bounding radius (Shape::boundingRadius)
  std::vector<Vec3> xRebuild;
  std::vector<std::uint8_t> wallTouch;

  std::size_t nOwned = 0;

  std::size_t size() const { return id.size(); }
  bool fixed(std::size_t i) const { return flags[i] & kFixed; }
  bool sphere(std::size_t i) const { return aspect[i].value == 1; }
  Shape shape(std::size_t i) const { return {radius[i], aspect[i].value}; }
  // The change of a non-sphere's angular velocity under the angular impulse J (space frame), at
  // its present orientation: I^-1 J, I = R I_body R^T.
  Vec3 spinChange(std::size_t i, const Vec3& J) const;
  // Its angular velocity w after its orientation turned from `from` to `to` at constant angular
  // momentum (torque-free rotation between the kicks): I(to)^-1 I(from) w.
  Vec3 carriedSpin(std::size_t i, const Quaternion& from, const Quaternion& to, const Vec3& w) const;

  // Appends a particle (at the end: call only when there are no ghosts, or for ghosts).
  void append(const ParticleRecord& r);
  ParticleRecord record(std::size_t i) const;
  void resize(std::size_t n);
  // Keeps the owned particles with keep[i] != 0 (in order); requires no ghosts.
  void compactOwned(const std::vector<char>& keep);
  void dropGhosts() { resize(nOwned); }
};

} // namespace vp
