#include "vp/particles/ParticleStore.hpp"
#include <cmath>

namespace vp {

void ParticleStore::resize(std::size_t n)
{
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto, const ParticleFieldInfo&, auto) { (this->*field).resize(n); });
  for (auto* v : {&mass, &invMass, &invInertia}) v->resize(n);
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
  const double m = density[i] * 4.0 / 3.0 * M_PI * radius[i] * radius[i] * radius[i];
  mass[i] = m;
  invMass[i] = (r.flags & kFixed) ? 0 : 1 / m;
  invInertia[i] = (r.flags & kFixed) ? 0 : 1 / (0.4 * m * radius[i] * radius[i]);
  xRebuild[i] = r.x;
  wallTouch[i] = 0;
  for (int f = 0; f < 6; ++f)
    if (r.wallSpring[f].x != 0 || r.wallSpring[f].y != 0 || r.wallSpring[f].z != 0) wallTouch[i] |= 1 << f;
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
      mass[k] = mass[i]; invMass[k] = invMass[i]; invInertia[k] = invInertia[i];
      xRebuild[k] = xRebuild[i]; wallTouch[k] = wallTouch[i];
    }
    ++k;
  }
  nOwned = k;
  resize(k);
}

} // namespace vp
