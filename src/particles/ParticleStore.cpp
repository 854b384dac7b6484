#include "vp/particles/ParticleStore.hpp"
#include <cmath>

namespace vp {

void ParticleStore::resize(std::size_t n)
{
  id.resize(n);
  radius.resize(n);
  density.resize(n);
  flags.resize(n);
  mass.resize(n);
  invMass.resize(n);
  invInertia.resize(n);
  x.resize(n);
  v.resize(n);
  w.resize(n);
  q.resize(n);
  force.resize(n);
  torque.resize(n);
  fhyd.resize(n);
  thyd.resize(n);
  xRebuild.resize(n);
  vHalf.resize(n);
  wHalf.resize(n);
  vSeen.resize(n);
  wSeen.resize(n);
  fluidMomentum.resize(n);
  fluidAngularMomentum.resize(n);
  wallSpring.resize(n);
  wallTouch.resize(n);
  history.resize(n);
}

void ParticleStore::append(const ParticleRecord& r)
{
  const std::size_t i = size();
  resize(i + 1);
  id[i] = r.id;
  radius[i] = r.radius;
  density[i] = r.density;
  flags[i] = r.flags;
  const double m = density[i] * 4.0 / 3.0 * M_PI * radius[i] * radius[i] * radius[i];
  mass[i] = m;
  invMass[i] = (r.flags & kFixed) ? 0 : 1 / m;
  invInertia[i] = (r.flags & kFixed) ? 0 : 1 / (0.4 * m * radius[i] * radius[i]);
  x[i] = r.x;
  // A fixed particle has zero inverse mass: its velocity and spin are kept, constant, a prescribed
  // motion (at rest when none is given) that the fluid and the lubrication see.
  v[i] = r.v;
  w[i] = r.w;
  q[i] = r.q;
  force[i] = r.force;
  torque[i] = r.torque;
  fhyd[i] = r.fhyd;
  thyd[i] = r.thyd;
  xRebuild[i] = r.x;
  vHalf[i] = r.vHalf;
  wHalf[i] = r.wHalf;
  vSeen[i] = r.vSeen;
  wSeen[i] = r.wSeen;
  fluidMomentum[i] = r.fluidMomentum;
  fluidAngularMomentum[i] = r.fluidAngularMomentum;
  wallSpring[i] = r.wallSpring;
  wallTouch[i] = 0;
  for (int f = 0; f < 6; ++f)
    if (r.wallSpring[f].x != 0 || r.wallSpring[f].y != 0 || r.wallSpring[f].z != 0) wallTouch[i] |= 1 << f;
  history[i] = r.history;
}

ParticleRecord ParticleStore::record(std::size_t i) const
{
  ParticleRecord r;
  r.id = id[i];
  r.radius = radius[i];
  r.density = density[i];
  r.flags = flags[i];
  r.x = x[i];
  r.v = v[i];
  r.w = w[i];
  r.q = q[i];
  r.force = force[i];
  r.torque = torque[i];
  r.fhyd = fhyd[i];
  r.thyd = thyd[i];
  r.vHalf = vHalf[i];
  r.wHalf = wHalf[i];
  r.vSeen = vSeen[i];
  r.wSeen = wSeen[i];
  r.fluidMomentum = fluidMomentum[i];
  r.fluidAngularMomentum = fluidAngularMomentum[i];
  r.wallSpring = wallSpring[i];
  r.history = history[i];
  return r;
}

void ParticleStore::compactOwned(const std::vector<char>& keep)
{
  std::size_t k = 0;
  for (std::size_t i = 0; i < nOwned; ++i) {
    if (!keep[i]) continue;
    if (k != i) {
      id[k] = id[i]; radius[k] = radius[i]; density[k] = density[i]; flags[k] = flags[i];
      mass[k] = mass[i]; invMass[k] = invMass[i]; invInertia[k] = invInertia[i];
      x[k] = x[i]; v[k] = v[i]; w[k] = w[i]; q[k] = q[i];
      force[k] = force[i]; torque[k] = torque[i]; fhyd[k] = fhyd[i]; thyd[k] = thyd[i];
      xRebuild[k] = xRebuild[i]; vHalf[k] = vHalf[i]; wHalf[k] = wHalf[i];
      vSeen[k] = vSeen[i]; wSeen[k] = wSeen[i];
      fluidMomentum[k] = fluidMomentum[i]; fluidAngularMomentum[k] = fluidAngularMomentum[i]; wallSpring[k] = wallSpring[i]; wallTouch[k] = wallTouch[i]; history[k] = std::move(history[i]);
    }
    ++k;
  }
  nOwned = k;
  resize(k);
}

} // namespace vp
