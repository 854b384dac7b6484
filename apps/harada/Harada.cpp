#include "harada/Harada.hpp"
#include "harada/SchillerNaumann.hpp"
#include "harada/WallAddedMass.hpp"
#include <algorithm>
#include <cmath>

namespace vp {

HaradaModel::HaradaModel(const HaradaParams& p, double height, double velocity)
  : p_(p), y_(height), v_(velocity), basset_(p.dt, velocity)
{
  const double a = p.radius, volume = 4.0 / 3.0 * M_PI * a * a * a;
  mass_ = p.particleDensity * volume;
  addedMass0_ = 0.5 * p.fluidDensity * volume;
  // Linear spring-dashpot with the wall (m* = m): duration t_c, restitution xi_n when dry.
  const double lnXi = std::log(p.restitution), tc = p.contactTime;
  stiffness_ = mass_ * (M_PI * M_PI + lnXi * lnXi) / (tc * tc);
  damping_ = -2 * mass_ * lnXi / tc;
}

void HaradaModel::step()
{
  const double a = p_.radius, mu = p_.viscosity, rho = p_.fluidDensity, dt = p_.dt;
  const double hCol = 2 * a * p_.roughness;
  const double h = y_ - a;
  const bool held = h < hCol;
  const double eps = std::max(h, hCol) / a; // lubrication and image series are held at the roughness
  const double weight = (mass_ - 2 * addedMass0_) * p_.gravity; // (m - m_f) g

  // Each force is written explicit part + implicit coefficient times v^{n+1}.
  double cDrag = 0, cLub = 0, mAdded = 0, cImage = 0, cBasset = 0, bassetLagged = 0;
  if (p_.drag) {
    const double re = rho * std::fabs(v_) * 2 * a / mu;
    cDrag = 6 * M_PI * mu * a * schillerNaumannFactor(re);
  }
  // Hand-off: the resistance is held at the roughness gap down to contact, then the contact law
  // alone acts (docs/lubrication.md).
  if (p_.lubrication && !held) cLub = 6 * M_PI * mu * a / eps;
  if (p_.addedMass) {
    const AddedMassCoefficient C = p_.imageSeries ? wallAddedMass(eps) : AddedMassCoefficient{1, 0};
    mAdded = addedMass0_ * C.value;
    // (1/2) dm'/dt v = (1/2) (dm'/dy) v^2, linearised as (1/2) (dm'/dy) v^n v^{n+1}; m' is
    // constant where it is held.
    if (!held) cImage = 0.5 * addedMass0_ * C.derivative / a * v_;
  }
  // The history window opens at a contact and closes once the gap opens past it or the sphere turns back.
  if (held && p_.historyWindow > 0) inHistoryWindow_ = true;
  if (inHistoryWindow_ && !held && (h > p_.historyWindow || v_ < 0)) inHistoryWindow_ = false;
  if (p_.history && !inHistoryWindow_) {
    const double K = 6 * a * a * std::sqrt(M_PI * rho * mu);
    cBasset = K * basset_.newestWeight();
    bassetLagged = K * basset_.lagged();
  }
  double spring = 0, cContact = 0;
  if (p_.contact && held) {
    spring = stiffness_ * (hCol - h);
    cContact = damping_;
  }

  const double inertia = mass_ + mAdded;
  const double coefficient = cDrag + cLub + cImage + cBasset + cContact;
  const double explicitForce = weight + spring - bassetLagged + cBasset * v_;
  const double vNew = (inertia / dt * v_ + explicitForce) / (inertia / dt + coefficient);

  forces_.weight = weight;
  forces_.drag = -cDrag * vNew;
  forces_.lubrication = -cLub * vNew;
  forces_.addedMass = -mAdded * (vNew - v_) / dt - cImage * vNew;
  forces_.history = -bassetLagged - cBasset * (vNew - v_);
  forces_.contact = spring - cContact * vNew;

  v_ = vNew;
  y_ += dt * vNew;
  time_ += dt;
  if (p_.history) basset_.push(v_);
}

} // namespace vp
