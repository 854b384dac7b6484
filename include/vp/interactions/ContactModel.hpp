#pragma once
// Soft-sphere contact law (docs/particles.md) as pure kernels: linear spring-dashpot in the normal
// direction, a tangential spring with history capped by Coulomb friction, for sphere-sphere and
// sphere-wall contacts. No grid, no MPI; the caller supplies geometry and kinematics.
#include "vp/core/Vec3.hpp"
#include "vp/interactions/ContactConfig.hpp"
#include <algorithm>
#include <cmath>

namespace vp {

// Coefficients of one contact: F_n = k_n delta - g_n v_n, F_t = -k_t s - g_t v_t, |F_t| <= mu |F_n|;
// rolling resistance |T_r| <= muR R* k_n delta; with criticalLoad > 0 the contact is frictionless
// while F_n <= criticalLoad (the critical load model of Seto, Mari, Morris & Denn 2013).
struct ContactCoefficients {
  double kn = 0, gn = 0, kt = 0, gt = 0, mu = 0, muR = 0, criticalLoad = 0;
};

// Turns the options into per-contact coefficients for an effective mass m* (wall: m* = m_i).
class ContactLaw {
public:
  ContactLaw() = default;
  // dtFluid is only used for -contact_tc_steps.
  ContactLaw(const ContactConfig& c, double dtFluid);
  ContactCoefficients coefficients(double meff, bool wall) const;
  // Contact duration of a pair of effective mass m* (exact for the linear law).
  double contactTime(double meff, bool wall) const;
  // Surface gap at which contact starts for radii ai, aj (aj = 0 for a wall: gap = roughness * 2 ai).
  double roughnessGap(double ai, double aj) const { return roughness_ * (aj > 0 ? ai + aj : 2 * ai); }
  double roughness() const { return roughness_; }

private:
  // Half period of the damped normal oscillator (k_n, gamma_n) of mass m*.
  static double duration(const ContactCoefficients& k, double meff);
  double tc_ = 0, kn_ = 0, knWall_ = 0, lnE_ = 0, mu_ = 0, ktRatio_ = 0, gtRatio_ = 0, roughness_ = 0;
  double lnEt_ = 0;  // ln xi_t; 0 with xi_t unset (the ratios apply)
  bool tangentialRestitution_ = false;
  double muR_ = 0, criticalLoad_ = 0;
};

struct ContactForce {
  Vec3 normal;      // on the particle, along n
  Vec3 tangential;  // on the particle, in the tangent plane
};

// One contact step. n: unit normal from the partner (or wall) to the particle; overlap: a_i + a_j +
// roughness gap - distance (> 0 in contact); vc: velocity of the particle's contact point relative
// to the partner's; spring: the tangential spring s (history), updated in place over dt.
// The old spring is first brought onto the current tangent plane by projection (a rotation to
// first order in the normal's turn theta per step; its length shrinks by theta^2 / 2), then
// stretched by v_t dt; if the trial force exceeds mu |F_n| the force is capped and the spring reset to the
// length that gives exactly the capped force (gross sliding). Below a critical load the contact has
// no tangential force and keeps no spring.
inline ContactForce contactForce(const Vec3& n, double overlap, const Vec3& vc, const ContactCoefficients& c,
                                 Vec3& spring, double dt)
{
  const double vn = dot(vc, n);
  const double fnMag = c.kn * overlap - c.gn * vn;
  if (c.criticalLoad > 0 && fnMag <= c.criticalLoad) {
    spring = Vec3{};
    return {fnMag * n, Vec3{}};
  }
  const Vec3 vt = vc - vn * n;
  spring -= dot(spring, n) * n;
  spring += dt * vt;
  Vec3 ft = -c.kt * spring - c.gt * vt;
  const double cap = c.mu * std::fabs(fnMag);
  const double ft2 = dot(ft, ft);
  if (ft2 > cap * cap) {
    ft *= cap / std::sqrt(ft2);
    spring = c.kt > 0 ? -(ft + c.gt * vt) / c.kt : Vec3{};
  }
  return {fnMag * n, ft};
}

// Rolling resistance of one contact (no history): a torque on the particle of magnitude
// muR R* k_n delta (R* = a_i a_j / (a_i + a_j); aj = 0 for a wall: R* = a_i; the elastic load, so
// the dashpot's pull at release does not count) against the relative rolling w_rel = w_i - w_j in
// the tangent plane, the partner getting the opposite. A constant torque would reverse a nearly
// stopped rolling at every step and make it chatter, so it is capped, |T| <= |w_rel| / (2 dt (1/I_i + 1/I_j)): a damper that
// halves w_rel per step. (Capped at a full stop per step, the Verlet step's predicted velocities
// and the tangential spring kept a stopped sphere creeping backwards at 7e-7 m/s, measured.) A
// sphere rolling on a plane decelerates at (5/7) muR g and then rests (test_contact.cpp).
inline Vec3 rollingTorque(const Vec3& n, const Vec3& wRel, double load, double muR, double ai, double aj,
                          double invInertiaSum, double dt)
{
  if (muR == 0) return {};
  const double reducedRadius = aj > 0 ? ai * aj / (ai + aj) : ai;
  const Vec3 wt = wRel - dot(wRel, n) * n;
  const double w = std::sqrt(dot(wt, wt));
  if (w == 0) return {};
  const double torque = std::min(muR * reducedRadius * load, 0.5 * w / (dt * invInertiaSum));
  return (-torque / w) * wt;
}

// Velocity of sphere i's contact point relative to sphere j's, n pointing from j to i; li, lj are
// the distances from the centres to the contact point.
inline Vec3 contactVelocity(const Vec3& vi, const Vec3& wi, double li, const Vec3& vj, const Vec3& wj, double lj,
                            const Vec3& n)
{
  return vi - vj - cross(li * wi + lj * wj, n);
}

} // namespace vp
