#pragma once
// The geometry of a particle, in one place (docs/shapes.md): a sphere of radius a, or a spheroid of
// equatorial semi-axis a and polar semi-axis c = aspect * a along its body z axis (aspect > 1
// prolate, < 1 oblate). Points and normals are in the body frame; the orientation quaternion maps
// them to space (Quaternion.hpp). A sphere is the aspect 1 and keeps its own closed forms, so sphere
// results do not change.
#include "vp/core/Vec3.hpp"
#include "vp/particles/Quaternion.hpp"
#include <array>
#include <cmath>

namespace vp {

// The aspect c / a a particle carries (ParticleFields.hpp); 1, a sphere, in old files and checkpoints.
struct Aspect {
  double value = 1;
};

// Symmetric 3 x 3 tensor, row-major.
using Tensor3 = std::array<double, 9>;

struct Shape {
  double a = 0;       // equatorial semi-axis; the radius of a sphere
  double aspect = 1;  // c / a

  bool sphere() const { return aspect == 1; }
  double c() const { return aspect * a; }
  double volume() const { return 4.0 / 3.0 * M_PI * a * a * c(); }
  double mass(double density) const { return density * 4.0 / 3.0 * M_PI * a * a * c(); }
  double equalVolumeRadius() const { return a * std::cbrt(aspect); }
  // The sphere around the particle, about its centre.
  double boundingRadius() const { return aspect > 1 ? c() : a; }
  double smallestSemiAxis() const { return aspect < 1 ? c() : a; }
  // Principal moments of inertia over the mass, about the body x, y and z axes.
  Vec3 inertiaOverMass() const;
  // Signed distance of the body-frame point p from the surface, > 0 outside (exact).
  double distance(const Vec3& p) const;
  // The surface point whose outward normal is the unit vector n; its distance from the centre
  // along n is the extent (the half-width of the particle across n).
  Vec3 pointWithNormal(const Vec3& n) const;
  double extent(const Vec3& n) const;
  // The part of the volume between two planes normal to the unit n (body frame) at signed distances
  // lo < hi from the centre: an ellipsoid's sections parallel to a plane are similar ellipses whose
  // area falls as 1 - (t / e)^2 with the distance t (e the extent along n).
  double volumeBetween(const Vec3& n, double lo, double hi) const;
  // Curvature tensor (shape operator) at the surface point p: its two non-zero eigenvalues are the
  // principal curvatures, in the tangent plane; n (x) n is its null space.
  Tensor3 curvature(const Vec3& p) const;
  // The least mean curvature (k1 + k2) / 2 and the least square root of the Gaussian curvature
  // sqrt(k1 k2) over the surface: a prolate body's equator, an oblate one's pole.
  double leastMeanCurvature() const { return aspect > 1 ? 0.5 * (1 / a + a / (c() * c())) : c() / (a * a); }
  double leastRootGaussCurvature() const { return aspect > 1 ? 1 / c() : c() / (a * a); }
};

// The two eigenvalues of the symmetric tensor K restricted to the plane normal to the unit n
// (k1 <= k2): for the sum of two surfaces' curvatures at their closest points, the gap there is
// h0 + k1 x^2 / 2 + k2 y^2 / 2.
std::array<double, 2> tangentEigenvalues(const Tensor3& K, const Vec3& n);

// Lubrication theory on the gap h0 + k1 x^2 / 2 + k2 y^2 / 2: the squeeze force is
// 6 pi mu V R^2 / h0 with R^2 = 2 / ((k1 + k2) sqrt(k1 k2)) (spheres: the reduced radius squared).
inline double squeezeRadiusSquared(double k1, double k2) { return 2 / ((k1 + k2) * std::sqrt(k1 * k2)); }

// The largest squeezeRadiusSquared two bodies can meet with, over all orientations and contact
// points (the stability bound of the explicit squeeze). gj null: a wall. At closest points the two
// surfaces share their normal, so k1 + k2 is the sum of the mean curvatures x 2, and by Minkowski's
// determinant inequality sqrt(k1 k2) >= sqrt(G_i) + sqrt(G_j): exact for spheres and for a
// spheroid's pole or equator at a wall.
double largestSqueezeRadiusSquared(const Shape& gi, const Shape* gj);

// Two bodies' nearest points, or their deepest ones when they overlap: n the unit normal from body i
// towards body j, gap the signed distance along it (< 0: the overlap depth), pI and pJ the points
// relative to their centres (pI the point of i whose outward normal is n, pJ that of j with -n).
// d = x_j - x_i; guess a unit direction to start from (the last normal, or d / abs(d)).
struct ClosestPoints {
  Vec3 n;
  double gap = 0;
  Vec3 pI, pJ;
};
ClosestPoints closestPoints(const Shape& gi, const Quaternion& qi, const Shape& gj, const Quaternion& qj, const Vec3& d,
                            const Vec3& guess);

// R K R^T, R the rotation of q: a body-frame tensor in space.
Tensor3 rotatedTensor(const Tensor3& K, const Quaternion& q);

} // namespace vp
