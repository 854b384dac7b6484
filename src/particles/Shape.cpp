#include "vp/particles/Shape.hpp"
#include <algorithm>

namespace vp {

namespace {

// Distance from (y0, y1), both >= 0, to the ellipse (x0/e0)^2 + (x1/e1)^2 = 1 with e0 >= e1 > 0.
// The closest point is x_k = e_k^2 y_k / (t + e_k^2) with t the root of
// F(t) = sum (e_k y_k / (t + e_k^2))^2 - 1, decreasing for t > -e1^2 (t > 0 outside, < 0 inside);
// on the axes the root may not exist and the closest point is found directly.
double ellipseDistance(double e0, double e1, double y0, double y1)
{
  if (y1 > 0) {
    if (y0 == 0) return std::fabs(y1 - e1);
    auto F = [&](double t) {
      const double u = e0 * y0 / (t + e0 * e0), v = e1 * y1 / (t + e1 * e1);
      return u * u + v * v - 1;
    };
    // F(-e1^2 + e1 y1) >= 0 and F(e0 |y|) <= 0 bracket the root; bisection to round-off.
    double lo = -e1 * e1 + e1 * y1, hi = e0 * std::hypot(y0, y1);
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (F(mid) > 0 ? lo : hi) = mid;
    }
    const double t = 0.5 * (lo + hi);
    const double x0 = e0 * e0 * y0 / (t + e0 * e0), x1 = e1 * e1 * y1 / (t + e1 * e1);
    return std::hypot(x0 - y0, x1 - y1);
  }
  // On the major axis: inside its evolute the closest point is off the axis.
  const double numer = e0 * y0, denom = e0 * e0 - e1 * e1;
  if (numer < denom) {
    const double r = numer / denom, x0 = e0 * r, x1 = e1 * std::sqrt(1 - r * r);
    return std::hypot(x0 - y0, x1);
  }
  return std::fabs(y0 - e0);
}

// An orthonormal pair t1, t2 normal to the unit n (t1 from the axis least aligned with n).
void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2)
{
  const int d = std::fabs(n.x) <= std::fabs(n.y) && std::fabs(n.x) <= std::fabs(n.z) ? 0 : (std::fabs(n.y) <= std::fabs(n.z) ? 1 : 2);
  Vec3 e;
  e[d] = 1;
  t1 = e - dot(e, n) * n;
  t1 = t1 / norm(t1);
  t2 = cross(n, t1);
}

Vec3 times(const Tensor3& A, const Vec3& v)
{
  return {A[0] * v.x + A[1] * v.y + A[2] * v.z, A[3] * v.x + A[4] * v.y + A[5] * v.z, A[6] * v.x + A[7] * v.y + A[8] * v.z};
}

// The body's support tensor in space, R diag(a^2, a^2, c^2) R^T: its extent along n is sqrt(n A n).
Tensor3 supportTensor(const Shape& g, const Quaternion& q)
{
  const double c = g.c();
  return rotatedTensor(Tensor3{g.a * g.a, 0, 0, 0, g.a * g.a, 0, 0, 0, c * c}, q);
}

} // namespace

ClosestPoints closestPoints(const Shape& gi, const Quaternion& qi, const Shape& gj, const Quaternion& qj, const Vec3& d,
                            const Vec3& guess)
{
  // The signed distance is the largest F(n) = n.d - h_i(n) - h_j(n) over unit n, h(n) = sqrt(n A n)
  // the extents (support functions): separated, the gap between the supporting planes; overlapping,
  // minus the smallest depth along any direction. Newton's method on the unit sphere, in the tangent
  // plane: gradient P (d - A_i n / h_i - A_j n / h_j), Hessian P grad^2 F P - F P (F is homogeneous).
  const Tensor3 Ai = supportTensor(gi, qi), Aj = supportTensor(gj, qj);
  const double scale = gi.boundingRadius() + gj.boundingRadius() + norm(d);
  Vec3 n = guess / norm(guess);
  ClosestPoints out;
  for (int it = 0; it < 100; ++it) {
    const Vec3 ui = times(Ai, n), uj = times(Aj, n);
    const double hi = std::sqrt(dot(n, ui)), hj = std::sqrt(dot(n, uj));
    const Vec3 grad = d - ui / hi - uj / hj;
    out = {n, dot(n, grad), ui / hi, -uj / hj};
    Vec3 t[2];
    tangentBasis(n, t[0], t[1]);
    const double g0 = dot(t[0], grad), g1 = dot(t[1], grad);
    if (std::hypot(g0, g1) <= 1e-14 * scale) break;
    // t_a grad^2 F t_b - F delta_ab, grad^2 F = -sum (A/h - (A n)(A n)^T / h^3)
    double H[2][2];
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const Vec3 Ati = times(Ai, t[b]), Atj = times(Aj, t[b]);
        H[a][b] = -(dot(t[a], Ati) / hi - dot(t[a], ui) * dot(t[b], ui) / (hi * hi * hi)) -
                  (dot(t[a], Atj) / hj - dot(t[a], uj) * dot(t[b], uj) / (hj * hj * hj)) - (a == b ? out.gap : 0);
      }
    const double det = H[0][0] * H[1][1] - H[0][1] * H[1][0];
    double s0, s1;
    if (H[0][0] < 0 && det > 0) {  // a maximum ahead: Newton
      s0 = -(H[1][1] * g0 - H[0][1] * g1) / det;
      s1 = -(H[0][0] * g1 - H[1][0] * g0) / det;
    } else {  // not yet near one: up the gradient, on the bodies' length scale
      s0 = g0 / scale;
      s1 = g1 / scale;
    }
    const double step = std::hypot(s0, s1);
    if (step > 0.5) s0 *= 0.5 / step, s1 *= 0.5 / step;
    n = n + s0 * t[0] + s1 * t[1];
    n = n / norm(n);
  }
  return out;
}

Vec3 Shape::inertiaOverMass() const
{
  const double ae = a * a, cp = c() * c();
  return {0.2 * (ae + cp), 0.2 * (ae + cp), 0.4 * ae};
}

double Shape::distance(const Vec3& p) const
{
  if (sphere()) return norm(p) - a;
  const double rho = std::hypot(p.x, p.y), z = std::fabs(p.z), cp = c();
  const double d = a >= cp ? ellipseDistance(a, cp, rho, z) : ellipseDistance(cp, a, z, rho);
  const double level = (rho * rho) / (a * a) + (z * z) / (cp * cp) - 1;
  return level < 0 ? -d : d;
}

double Shape::extent(const Vec3& n) const
{
  const double cp = c();
  return std::sqrt(a * a * (n.x * n.x + n.y * n.y) + cp * cp * n.z * n.z);
}

double Shape::volumeBetween(const Vec3& n, double lo, double hi) const
{
  const double e = extent(n), t0 = std::max(lo, -e), t1 = std::min(hi, e);
  if (t1 <= t0) return 0;
  // The section area A0 (1 - t^2 / e^2) integrates to the volume with A0 = 3 V / (4 e).
  auto primitive = [e](double t) { return t - t * t * t / (3 * e * e); };
  return 0.75 * volume() / e * (primitive(t1) - primitive(t0));
}

Vec3 Shape::pointWithNormal(const Vec3& n) const
{
  const double cp = c(), e = extent(n);
  return {a * a * n.x / e, a * a * n.y / e, cp * cp * n.z / e};
}

Tensor3 Shape::curvature(const Vec3& p) const
{
  const double cp = c();
  const double M[3] = {1 / (a * a), 1 / (a * a), 1 / (cp * cp)};
  const Vec3 g{M[0] * p.x, M[1] * p.y, M[2] * p.z};
  const double gn = norm(g);
  const Vec3 n = g / gn;
  // P M P / |M p|, P = I - n n^T the projection on the tangent plane
  double P[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) P[3 * i + j] = (i == j) - n[i] * n[j];
  Tensor3 K{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) K[3 * i + j] += P[3 * i + k] * M[k] * P[3 * k + j] / gn;
  return K;
}

std::array<double, 2> tangentEigenvalues(const Tensor3& K, const Vec3& n)
{
  Vec3 t1, t2;
  tangentBasis(n, t1, t2);
  auto form = [&](const Vec3& u, const Vec3& v) {
    double s = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s += u[i] * K[3 * i + j] * v[j];
    return s;
  };
  const double p = form(t1, t1), q = form(t2, t2), r = form(t1, t2);
  const double mean = 0.5 * (p + q), half = std::hypot(0.5 * (p - q), r);
  return {mean - half, mean + half};
}

double largestSqueezeRadiusSquared(const Shape& gi, const Shape* gj)
{
  const double H = gi.leastMeanCurvature() + (gj ? gj->leastMeanCurvature() : 0);
  const double rootK = gi.leastRootGaussCurvature() + (gj ? gj->leastRootGaussCurvature() : 0);
  return 1 / (H * rootK);
}

Tensor3 rotatedTensor(const Tensor3& K, const Quaternion& q)
{
  Vec3 col[3];  // R's columns: the body axes in space
  for (int k = 0; k < 3; ++k) {
    Vec3 e;
    e[k] = 1;
    col[k] = toSpace(q, e);
  }
  Tensor3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) out[3 * i + j] += col[k][i] * K[3 * k + l] * col[l][j];
  return out;
}

} // namespace vp
