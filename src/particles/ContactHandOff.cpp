#include "vp/particles/ContactHandOff.hpp"
#include <algorithm>
#include <cmath>

namespace vp {

ContactHandOff::ContactHandOff(ContactHydro hydro, double departureGap, bool history, double rhoFluid, double mu,
                               const Vec3& gravity)
  : mode_(hydro), departureGap_(hydro == ContactHydro::Limit ? departureGap : 0),
    history_(hydro != ContactHydro::Keep && history), rhoFluid_(rhoFluid), gravity_(gravity),
    bassetScale_(6 * std::sqrt(M_PI * rhoFluid * mu))
{
}

void ContactHandOff::dropStale(ParticleStore& s) const
{
  const std::uint8_t stale = mode_ == ContactHydro::Keep ? kHandOffFlags
                             : departureGap_ == 0        ? (kDeparting | kWallImpact | kPairDeparting) : 0;
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    s.flags[i] &= ~stale;
    if (!history_) s.windowHistory[i] = WindowModes{};
    if (departureGap_ == 0)
      for (ContactSpring& c : s.history[i]) c.departure = 0;
  }
}

void ContactHandOff::startForces(ParticleStore& s) const
{
  if (mode_ == ContactHydro::Keep) return;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const bool candidate = departureGap_ > 0 && (s.flags[i] & (kWallImpact | kDeparting));
    s.flags[i] = (s.flags[i] & ~kHandOffFlags) | (candidate ? kDeparting : 0);
  }
}

bool ContactHandOff::excludes(const ParticleStore& s, std::size_t i, double overlap, double kn) const
{
  switch (mode_) {
  case ContactHydro::Exclude: return true;
  case ContactHydro::Limit: {
    // Beyond the overlap the particle's buoyant weight alone would press into this contact: an
    // impact, not a particle resting on its support (which keeps its drag and pressure).
    const double buoyantWeight = std::fabs(1 - rhoFluid_ / s.density[i]) * s.mass[i] * norm(gravity_);
    return overlap * kn > buoyantWeight;
  }
  default: return false;
  }
}

std::uint8_t ContactHandOff::touchPair(ParticleStore& s, std::size_t i, std::size_t j, double overlap, double kn) const
{
  if (mode_ == ContactHydro::Keep) return 0;
  s.flags[i] |= kTouching;
  s.flags[j] |= kTouching;
  if (excludes(s, i, overlap, kn)) s.flags[i] |= kResolvedForceOff;
  if (excludes(s, j, overlap, kn)) s.flags[j] |= kResolvedForceOff;
  // An impact presses beyond twice the buoyant-weight overlap of either sphere.
  const bool impact = departureGap_ > 0 && (excludes(s, i, overlap / 2, kn) || excludes(s, j, overlap / 2, kn));
  return impact ? kPairImpact : 0;
}

std::uint8_t ContactHandOff::pairState(ParticleStore& s, std::size_t i, std::size_t j, std::uint8_t impact, bool leaving) const
{
  if (impact || !leaving) return impact;  // a new impact ends a departure
  s.flags[i] |= kPairDeparting;
  s.flags[j] |= kPairDeparting;
  return kPairLeaving;
}

void ContactHandOff::touchWall(ParticleStore& s, std::size_t i, double overlap, double kn) const
{
  if (mode_ == ContactHydro::Keep) return;
  s.flags[i] |= kTouching;
  if (excludes(s, i, overlap, kn)) s.flags[i] |= kResolvedForceOff;
  if (departureGap_ > 0 && excludes(s, i, overlap / 2, kn)) s.flags[i] |= kWallImpact;
}

void ContactHandOff::endWalls(ParticleStore& s, std::size_t i, bool departing) const
{
  if (!departing || (s.flags[i] & kWallImpact)) s.flags[i] &= ~kDeparting;
}

LubricationParams ContactHandOff::departureFilm(const LubricationParams& lub, double a) const
{
  LubricationParams film = lub;
  film.activation = std::max(departureGap_, lub.activationGap(a)) / a;  // an activation in radii
  return film;
}

void ContactHandOff::startSubsteps(double dtp)
{
  if (history_) kernel_.emplace(0.5 * dtp);
}

Vec3 ContactHandOff::historyKick(ParticleStore& s, std::size_t i, double half, const Vec3& dv) const
{
  WindowModes& window = s.windowHistory[i];
  if (!resolvedOff(s, i)) {
    if (!window.empty()) window = WindowModes{};
    return dv;
  }
  if (window.empty()) window.resize(1);
  WindowHistory& w = window.front();
  const BassetKernel& kernel = *kernel_;
  if (s.flags[i] & kTouching) {
    kernel.advance(w.modes, Vec3{});  // older changes fade meanwhile
    w.contactChange += dv;
    return dv;
  }
  const double c = half * s.invMass[i] * bassetScale_ * s.radius[i] * s.radius[i], nw = kernel.newestWeight();
  const Vec3 dvH = (1 / (1 + c * nw)) * (dv - c * (kernel.lagged(w.modes) + nw * w.contactChange));
  kernel.advance(w.modes, dvH + w.contactChange);
  w.contactChange = Vec3{};
  return dvH;
}

} // namespace vp
