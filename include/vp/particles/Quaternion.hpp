#pragma once
// Unit quaternion for particle orientation (w, x, y, z), rotated by a space-frame angular velocity.
// It maps the body frame to space: toSpace(q, v) = q v q*, toBody its inverse.
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

inline Vec3 toSpace(const Quaternion& q, const Vec3& v)
{
  // v + 2 u x (u x v + w v), u the vector part
  const Vec3 u{q.x, q.y, q.z};
  return v + 2.0 * cross(u, cross(u, v) + q.w * v);
}

inline Vec3 toBody(const Quaternion& q, const Vec3& v) { return toSpace(Quaternion{q.w, -q.x, -q.y, -q.z}, v); }

// The rotation taking the body z axis onto the unit vector axis (the shortest one; about x when
// axis = -z).
inline Quaternion alignedWith(const Vec3& axis)
{
  const double c = axis.z;  // cos of the angle from z
  if (c < -1 + 1e-12) return {0, 1, 0, 0};
  const double h = std::sqrt(0.5 * (1 + c));  // cos(angle / 2)
  const Vec3 k = cross(Vec3{0, 0, 1}, axis);  // sin(angle) times the rotation axis
  const double s = 0.5 / h;                    // sin(angle / 2) / sin(angle)
  return {h, s * k.x, s * k.y, s * k.z};
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
