#pragma once
// The hand-off between the resolved hydrodynamic force, the lubrication correction and the contact
// law (docs/collisions.md, "The model of a collision"): which particles feel their resolved force
// (-contact_hydro), the departure after an impact (-contact_hydro_departure: the correction from a
// larger gap while the resolved force stays off) and the Basset history force that stands in for the
// excluded resolved force meanwhile (-contact_hydro_history). The DEM's force loop reports contacts
// and asks who is leaving; the kicks ask for the force each particle feels.
#include "vp/core/Vec3.hpp"
#include "vp/interactions/BassetModes.hpp"
#include "vp/interactions/ContactConfig.hpp"
#include "vp/interactions/ContactHistory.hpp"
#include "vp/interactions/LubricationModel.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <cstdint>
#include <optional>

namespace vp {

// The per-particle flags of the hand-off (ParticleStore::flags, beside kFixed; they travel with the
// particle and its checkpoint). kResolvedForceOff: in a contact whose resolved force is excluded.
// kWallImpact: that contact is a wall's, pressed beyond twice the buoyant-weight overlap (an impact,
// not a sphere resting on it). kDeparting: leaving a wall after a wall impact, closer than the
// departure gap. kPairDeparting: the same, leaving another sphere (the pair's own state lives with
// the pair list, PairList::departure). kTouching: in contact with a wall or another particle.
// All are set anew by every force loop (unless the resolved force is kept).
enum HandOffFlag : std::uint8_t { kResolvedForceOff = 2, kDeparting = 4, kWallImpact = 8, kPairDeparting = 16, kTouching = 32 };
constexpr std::uint8_t kHandOffFlags = kResolvedForceOff | kDeparting | kWallImpact | kPairDeparting | kTouching;

class ContactHandOff {
public:
  // hydro: -contact_hydro (keep without a fluid); departureGap: -contact_hydro_departure in metres
  // (used with limit only; 0: off); history: -contact_hydro_history.
  ContactHandOff(ContactHydro hydro, double departureGap, bool history, double rhoFluid, double mu, const Vec3& gravity);

  double departureGap() const { return departureGap_; }
  bool history() const { return history_; }
  // Flags and pair states a checkpoint written with other options left: cleared.
  void dropStale(ParticleStore& s) const;

  // --- The force loop ---
  // Before it: the flags cleared; a particle that was in a wall impact or leaving one stays a
  // candidate for the departure, confirmed or dropped by endWalls.
  void startForces(ParticleStore& s) const;
  // A contact of overlap [m] and normal stiffness kn between i and j: their flags; returns the
  // pair's departure state (kPairImpact for an impact, else 0).
  std::uint8_t touchPair(ParticleStore& s, std::size_t i, std::size_t j, double overlap, double kn) const;
  // i against a wall.
  void touchWall(ParticleStore& s, std::size_t i, double overlap, double kn) const;
  // Spheres i and j with this departure state, normal n from j to i, at gap: leaving each other
  // after an impact, closer than the departure gap.
  bool pairLeaving(const ParticleStore& s, std::size_t i, std::size_t j, const Vec3& n, double gap, std::uint8_t departure) const
  {
    return departureGap_ > 0 && (departure & (kPairImpact | kPairLeaving)) && dot(s.v[i] - s.v[j], n) > 0 && gap < departureGap_;
  }
  // The pair's state after the force loop saw it (impact: touchPair's answer), and both flags.
  std::uint8_t pairState(ParticleStore& s, std::size_t i, std::size_t j, std::uint8_t impact, bool leaving) const;
  // A departure candidate moving away from a wall (its velocity, its normal n into the domain) at gap.
  bool wallLeaving(const ParticleStore& s, std::size_t i, const Vec3& wallVelocity, const Vec3& n, double gap) const
  {
    return (s.flags[i] & kDeparting) && dot(s.v[i] - wallVelocity, n) > 0 && gap < departureGap_;
  }
  // After i's walls: departing from one of them, or the departure ends (no wall left to leave, or a
  // new impact).
  void endWalls(ParticleStore& s, std::size_t i, bool departing) const;
  // The lubrication of a sphere of radius a (the smaller of a pair) leaving after an impact: the
  // squeeze and the tangential terms both from the departure gap (at least lub's activation), since
  // the resolved force and torque are both off.
  LubricationParams departureFilm(const LubricationParams& lub, double a) const;

  // --- The kicks ---
  // Before the sub-steps of a fluid step: the history modes' factors for half a sub-step.
  void startSubsteps(double dtp);
  bool resolvedOff(const ParticleStore& s, std::size_t i) const
  {
    return s.flags[i] & (kResolvedForceOff | kDeparting | kPairDeparting);
  }
  // The resolved force and torque particle i feels: while excluded, the buoyancy alone (which the
  // fluid's pressure does not carry).
  Vec3 resolvedForce(const ParticleStore& s, std::size_t i) const
  {
    return resolvedOff(s, i) ? (-rhoFluid_ / s.density[i] * s.mass[i]) * gravity_ : s.fhyd[i];
  }
  Vec3 resolvedTorque(const ParticleStore& s, std::size_t i) const { return resolvedOff(s, i) ? Vec3{} : s.thyd[i]; }
  // The velocity change of a half kick of particle i with the force F, with the history force
  // -6 a^2 sqrt(pi rho mu) I of its velocity changes since its resolved force was excluded, the
  // kick's own change implicit (explicit, it is unstable once 2 K sqrt(dt) / m nears 1: small, light
  // spheres in a viscous liquid). Not in contact: over a contact stretched to fluid steps the force
  // would press the sphere into its partner, swelling the contact's impulse and the friction's, and
  // keep acting on a sphere held at the wall, where a real contact is over before the force has
  // acted; the contact's velocity change enters the history as one change when it ends, as that of
  // a real, short contact. The modes are dropped (their storage freed) once the resolved force acts.
  Vec3 halfKick(ParticleStore& s, std::size_t i, double half, const Vec3& F) const
  {
    const Vec3 dv = (half * s.invMass[i]) * F;
    return history_ ? historyKick(s, i, half, dv) : dv;
  }

private:
  // -contact_hydro: whether a contact of this overlap and stiffness switches i's resolved force off.
  bool excludes(const ParticleStore& s, std::size_t i, double overlap, double kn) const;
  Vec3 historyKick(ParticleStore& s, std::size_t i, double half, const Vec3& dv) const;

  ContactHydro mode_;
  double departureGap_;
  bool history_;
  double rhoFluid_;
  Vec3 gravity_;
  double bassetScale_;  // 6 sqrt(pi rho mu): the Basset force is -bassetScale a^2 I
  std::optional<BassetKernel> kernel_;  // the modes' factors for half a DEM sub-step
};

} // namespace vp
