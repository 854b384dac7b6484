#include "vp/interactions/ContactModel.hpp"

namespace vp {

ContactLaw::ContactLaw(const ContactConfig& c, double dtFluid)
  : tc_(c.tc > 0 ? c.tc : c.tcSteps * dtFluid),
    kn_(c.kn),
    knWall_(c.knWall > 0 ? c.knWall : c.kn),
    lnE_(std::log(c.restitution)),
    mu_(c.friction),
    ktRatio_(c.ktRatio),
    gtRatio_(c.gtRatio),
    roughness_(c.roughness),
    lnEt_(c.restitutionT > 0 ? std::log(c.restitutionT) : 0),
    tangentialRestitution_(c.restitutionT > 0),
    muR_(c.rollingFriction),
    criticalLoad_(c.criticalLoad)
{
}

ContactCoefficients ContactLaw::coefficients(double meff, bool wall) const
{
  const double pi2 = M_PI * M_PI;
  ContactCoefficients k;
  if (kn_ > 0) {
    // Given stiffness: damping chosen so that this pair mass rebounds with the set restitution.
    k.kn = wall ? knWall_ : kn_;
    k.gn = -2 * lnE_ * std::sqrt(k.kn * meff / (pi2 + lnE_ * lnE_));
  } else {
    // Given duration: k_n = m* (pi^2 + ln^2 e) / t_c^2, g_n = -2 m* ln e / t_c.
    k.kn = meff * (pi2 + lnE_ * lnE_) / (tc_ * tc_);
    k.gn = -2 * meff * lnE_ / tc_;
  }
  if (tangentialRestitution_) {
    // A sticking contact point moves as an oscillator of mass (2/7) m* (solid spheres: the force
    // accelerates the centres and spins them, 1/m + a^2/I = 7/(2m)); over the same duration as the
    // normal contact it reverses its tangential velocity with the factor xi_t.
    const double mt = 2.0 / 7.0 * meff, tc = duration(k, meff);
    k.kt = mt * (pi2 + lnEt_ * lnEt_) / (tc * tc);
    k.gt = -2 * mt * lnEt_ / tc;
  } else {
    k.kt = ktRatio_ * k.kn;
    k.gt = gtRatio_ * k.gn;
  }
  k.mu = mu_;
  k.muR = muR_;
  k.criticalLoad = criticalLoad_;
  return k;
}

double ContactLaw::contactTime(double meff, bool wall) const
{
  return kn_ > 0 ? duration(coefficients(meff, wall), meff) : tc_;
}

double ContactLaw::duration(const ContactCoefficients& k, double meff)
{
  const double w0 = std::sqrt(k.kn / meff), zeta = k.gn / (2 * std::sqrt(k.kn * meff));
  return M_PI / (w0 * std::sqrt(1 - zeta * zeta));
}

} // namespace vp
