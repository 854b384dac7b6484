#include "vp/particles/ParticleStore.hpp"
#include <algorithm>
#include <cmath>

namespace vp {

void ParticleStore::resize(std::size_t n)
{
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto, const ParticleFieldInfo&, auto) { (this->*field).resize(n); });
  for (auto* v : {&mass, &invMass, &invInertia, &bound}) v->resize(n);
  invInertiaBody.resize(n);
  xRebuild.resize(n);
  wallTouch.resize(n);
}

void ParticleStore::append(const ParticleRecord& r)
{
  const std::size_t i = size();
  resize(i + 1);
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto value, const ParticleFieldInfo&, auto) { (this->*field)[i] = r.*value; });
  // A fixed particle has zero inverse mass: its velocity and spin are kept, constant, a prescribed
  // motion (at rest when none is given) that the fluid and the lubrication see.
  const Shape g = shape(i);
  const double m = g.mass(density[i]);
  bound[i] = g.boundingRadius();
  mass[i] = m;
  invMass[i] = (r.flags & kFixed) ? 0 : 1 / m;
  if (g.sphere()) {
    invInertia[i] = (r.flags & kFixed) ? 0 : 1 / (0.4 * m * radius[i] * radius[i]);
    invInertiaBody[i] = {invInertia[i], invInertia[i], invInertia[i]};
  } else {
    const Vec3 I = m * g.inertiaOverMass();
    invInertiaBody[i] = (r.flags & kFixed) ? Vec3{} : Vec3{1 / I.x, 1 / I.y, 1 / I.z};
    invInertia[i] = std::max({invInertiaBody[i].x, invInertiaBody[i].y, invInertiaBody[i].z});
  }
  xRebuild[i] = r.x;
  wallTouch[i] = 0;
  for (int f = 0; f < 6; ++f)
    if (r.wallSpring[f].x != 0 || r.wallSpring[f].y != 0 || r.wallSpring[f].z != 0) wallTouch[i] |= 1 << f;
}

namespace {

// I^-1 J for the inverse principal moments k in the body frame and orientation q.
Vec3 inverseInertiaTimes(const Quaternion& q, const Vec3& k, const Vec3& J)
{
  const Vec3 b = toBody(q, J);
  return toSpace(q, Vec3{k.x * b.x, k.y * b.y, k.z * b.z});
}

} // namespace

Vec3 ParticleStore::spinChange(std::size_t i, const Vec3& J) const { return inverseInertiaTimes(q[i], invInertiaBody[i], J); }

Vec3 ParticleStore::carriedSpin(std::size_t i, const Quaternion& from, const Quaternion& to, const Vec3& w) const
{
  if (fixed(i)) return w;
  const Vec3 k = invInertiaBody[i], b = toBody(from, w);
  return inverseInertiaTimes(to, k, toSpace(from, Vec3{b.x / k.x, b.y / k.y, b.z / k.z}));
}

ParticleRecord ParticleStore::record(std::size_t i) const
{
  ParticleRecord r;
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto value, const ParticleFieldInfo&, auto) { r.*value = (this->*field)[i]; });
  return r;
}

void ParticleStore::compactOwned(const std::vector<char>& keep)
{
  std::size_t k = 0;
  for (std::size_t i = 0; i < nOwned; ++i) {
    if (!keep[i]) continue;
    if (k != i) {
      forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto, const ParticleFieldInfo&, auto) {
        (this->*field)[k] = std::move((this->*field)[i]);
      });
      mass[k] = mass[i]; invMass[k] = invMass[i]; invInertia[k] = invInertia[i]; invInertiaBody[k] = invInertiaBody[i]; bound[k] = bound[i];
      xRebuild[k] = xRebuild[i]; wallTouch[k] = wallTouch[i];
    }
    ++k;
  }
  nOwned = k;
  resize(k);
}

} // namespace vp
