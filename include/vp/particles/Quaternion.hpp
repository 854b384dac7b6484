#pragma once
// Unit quaternion for particle orientation (w, x, y, z), rotated by a space-frame angular velocity.
#include "vp/core/Vec3.hpp"
#include <cmath>

namespace vp {

struct Quaternion {
  double w = 1, x = 0, y = 0, z = 0;
};

inline Quaternion operator*(const Quaternion& a, const Quaternion& b)
{
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// q <- exp(omega dt / 2) q: the rotation by angle |omega| dt about omega, renormalised. Up to
// 0.1 rad per step the series of cos and sin (truncation error < 1e-15) replaces the library
// calls; with no branch for the common case, rotations of many particles pipeline.
inline Quaternion rotated(const Quaternion& q, const Vec3& omega, double dt)
{
  const double w2 = dot(omega, omega);
  const double h2 = 0.25 * w2 * dt * dt;  // (angle / 2)^2
  double c, s;
  if (h2 < 2.5e-3) {
    constexpr double c4 = 1.0 / 24, c6 = 1.0 / 720, s2 = 1.0 / 6, s4 = 1.0 / 120, s6 = 1.0 / 5040;
    c = 1 - h2 * (0.5 - h2 * (c4 - h2 * c6));
    s = 0.5 * dt * (1 - h2 * (s2 - h2 * (s4 - h2 * s6)));
  } else {
    const double w = std::sqrt(w2), half = 0.5 * w * dt;
    c = std::cos(half);
    s = std::sin(half) / w;
  }
  const Quaternion r = Quaternion{c, s * omega.x, s * omega.y, s * omega.z} * q;
  // |r| = 1 up to round-off: one Newton step of 1/sqrt(|r|^2) from 1 renormalises it.
  const double f = 1.5 - 0.5 * (r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
  return {f * r.w, f * r.x, f * r.y, f * r.z};
}

} // namespace vp
