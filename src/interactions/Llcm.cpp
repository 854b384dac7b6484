#include "vp/interactions/Llcm.hpp"
#include "vp/interactions/Blcm.hpp"

namespace vp {

PairForce llcmForce(const PairState& s, double region, bool openEdge, LubPart part)
{
  const Vec3& n = s.normal;
  const double R = s.reducedRadius();
  const double h = s.gap;
  const double mu = s.viscosity;
  const double H0 = h + 0.5 * region * region * R;
  // x = 1 - h/H0 = r0^2/(2R H0).
  const double x = 0.5 * region * region * R / H0;
  PairForce f;
  if (part != LubPart::Shear) {
    f = blcmForce(s);
    f.forceI *= openEdge ? x : x * x;  // squeeze with the inner pressure at r0, or with p(r0) = 0
  }
  if (part == LubPart::Squeeze) return f;
  // ln(H0/h) = -log1p(-x) stays accurate when x is small (small region or large gap); the direct
  // ratio is accurate when x is close to 1 (small gap).
  const double J1 = x < 0.5 ? -std::log1p(-x) : std::log(H0 / h);
  const double J3 = J1 - x;

  const double kI = s.curvatureI(), kJ = s.curvatureJ();
  const Vec3 sI = s.tangential(s.surfaceVelocityI());
  const Vec3 sJ = s.tangential(s.surfaceVelocityJ());
  const Vec3 W = (0.5 / R) * (sI + sJ) - kI * s.tangential(s.velocityI) - kJ * s.tangential(s.velocityJ);
  const Vec3 P = (-12.0 / 5.0 * M_PI * mu * R * R * R * J3) * W;
  const Vec3 S = (2 * M_PI * mu * R * J1) * (sI - sJ);

  f.forceI += -(kI - kJ) * P - S;
  f.torqueI = s.radiusI * cross(n, P / R - S);
  if (!s.isWall()) f.torqueJ = -s.radiusJ * cross(n, P / R + S);
  return f;
}

} // namespace vp
