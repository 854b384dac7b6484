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

// q <- exp(omega dt / 2) q: the exact rotation by angle |omega| dt about omega, renormalised.
inline Quaternion rotated(const Quaternion& q, const Vec3& omega, double dt)
{
  const double w = norm(omega);
  if (w == 0) return q;
  const double half = 0.5 * w * dt, s = std::sin(half) / w;
  Quaternion r = Quaternion{std::cos(half), s * omega.x, s * omega.y, s * omega.z} * q;
  const double len = std::sqrt(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
  return {r.w / len, r.x / len, r.y / len, r.z / len};
}

} // namespace vp
