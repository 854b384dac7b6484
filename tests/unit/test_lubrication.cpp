// Lubrication kernels (BLCM, LLCM) against their formulas, the quadrature of the lubrication
// solution they are derived from, the classical near-contact coefficients, and the pair balances.
#include "vp/interactions/Blcm.hpp"
#include "vp/interactions/Llcm.hpp"
#include "vp/interactions/LubricationModel.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace vp;

namespace {

const double kMu = 0.142;
const double kA = 0.0127;
const double kGaps[] = {1e-4, 1e-3, 1e-2, 1e-1, 1};        // eps = h / a_i
const double kRatios[] = {0.25, 1, 4, kWallRadius};        // a_j / a_i

double relErr(const Vec3& a, const Vec3& b, double scale)
{
  return norm(a - b) / scale;
}

// A pair with generic velocities in an oblique frame, so every term of the kernels is exercised.
PairState genericPair(double eps, double ratio)
{
  PairState s;
  s.normal = Vec3{1, -2, 2} / 3.0;
  s.radiusI = kA;
  s.radiusJ = ratio * kA;
  s.gap = eps * kA;
  s.viscosity = kMu;
  s.velocityI = {0.3, -0.1, 0.2};
  s.velocityJ = {-0.05, 0.15, 0.1};
  s.angularVelocityI = {4, 7, -3};
  if (!s.isWall()) s.angularVelocityJ = {-6, 2, 5};
  return s;
}

// Orthonormal tangent basis of the plane normal to n.
void tangentBasis(const Vec3& n, Vec3& e1, Vec3& e2)
{
  Vec3 t = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  e1 = t - dot(t, n) * n;
  e1 = e1 / norm(e1);
  e2 = cross(n, e1);
}

// m-point Gauss-Legendre nodes and weights on [-1, 1] (Newton iteration on P_m).
void gaussLegendre(int m, std::vector<double>& x, std::vector<double>& w)
{
  x.resize(m);
  w.resize(m);
  for (int i = 0; i < m; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (m + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= m; ++k) {
        double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = m * (z * p1 - p0) / (z * z - 1);
      double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

// Tangential lubrication solution integrated numerically over the disk r < r0 (independent of the
// closed forms in Llcm.cpp). Surfaces: z_i = h + r^2/(2 a_i), z_j = -r^2/(2 a_j) along -n; pressure
// p = -(12 mu R / 5) (x.W) / h(r)^2 (infinite-domain solution, as in the seed), Couette-Poiseuille
// profile between the surface velocities. Returns the seed's integrals (traction on i, viscous
// tractions on i and j) and the edge pressure term B = \oint p h/2 n dl the kernel removes.
struct ShearQuadrature {
  Vec3 tractionI, viscousI, viscousJ, edge;
};

ShearQuadrature integrateShear(const PairState& s, double region)
{
  const Vec3 n = s.normal;
  Vec3 e1, e2;
  tangentBasis(n, e1, e2);
  const double R = s.reducedRadius(), h0 = s.gap, mu = s.viscosity;
  const double kI = s.curvatureI(), kJ = s.curvatureJ();
  const Vec3 sI = s.tangential(s.surfaceVelocityI()), sJ = s.tangential(s.surfaceVelocityJ());
  const Vec3 W = (0.5 / R) * (sI + sJ) - kI * s.tangential(s.velocityI) - kJ * s.tangential(s.velocityJ);
  const double c = -12 * mu * R / 5;
  const double r0 = region * R;

  std::vector<double> gx, gw;
  gaussLegendre(20, gx, gw);
  const int nTheta = 8; // the integrands are trigonometric polynomials of degree <= 2 in theta
  ShearQuadrature q;
  // Panels in u = r^2/(2R), geometric from h0/16 so the 1/h^k peaks are resolved.
  std::vector<double> edges{0};
  for (double u = h0 / 16; u < r0 * r0 / (2 * R); u *= 2) edges.push_back(u);
  edges.push_back(r0 * r0 / (2 * R));
  for (size_t k = 0; k + 1 < edges.size(); ++k) {
    const double ua = edges[k], ub = edges[k + 1];
    for (size_t g = 0; g < gx.size(); ++g) {
      const double u = 0.5 * (ua + ub) + 0.5 * (ub - ua) * gx[g];
      const double r = std::sqrt(2 * R * u), h = h0 + u;
      const double dA = 0.5 * (ub - ua) * gw[g] * R * (2 * M_PI / nTheta); // r dr = R du
      for (int t = 0; t < nTheta; ++t) {
        const double th = 2 * M_PI * t / nTheta;
        const Vec3 x = r * std::cos(th) * e1 + r * std::sin(th) * e2;
        const double p = c * dot(x, W) / (h * h);
        const Vec3 gradP = c * (W / (h * h) - (2 * dot(x, W) / (R * h * h * h)) * x);
        const Vec3 shear = (mu / h) * (sI - sJ);
        const Vec3 viscI = -0.5 * h * gradP - shear; // -mu du/dz on surface i
        const Vec3 viscJ = -0.5 * h * gradP + shear; // +mu du/dz on surface j
        q.viscousI += dA * viscI;
        q.viscousJ += dA * viscJ;
        q.tractionI += dA * (viscI - p * kI * x); // plus the pressure on the sloped surface of i
      }
    }
  }
  const double H0 = h0 + r0 * r0 / (2 * R);
  q.edge = (M_PI * r0 * r0 * c * H0 / (2 * H0 * H0)) * W; // \oint (p h / 2) n dl
  return q;
}

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y)
{
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) { mx += x[i]; my += y[i]; }
  mx /= x.size();
  my /= y.size();
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxy / sxx;
}

std::vector<double> logSpaced(double lo, double hi, int n)
{
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(lo * std::pow(hi / lo, double(i) / (n - 1)));
  return v;
}

} // namespace

TEST_CASE("BLCM equals -6 pi mu R^2 U_n / h for unequal spheres and the wall", "[lub]")
{
  for (double ratio : kRatios)
    for (double eps : kGaps) {
      const PairState s = genericPair(eps, ratio);
      const double aj = ratio * kA;
      const double R = std::isinf(aj) ? kA : kA * aj / (kA + aj);
      const double Un = dot(s.velocityI - s.velocityJ, s.normal); // approach speed
      const Vec3 expected = (-6 * M_PI * kMu * R * R * Un / s.gap) * s.normal;
      const PairForce f = blcmForce(s);
      CHECK(relErr(f.forceI, expected, norm(expected)) < 1e-12);
      CHECK(norm(f.torqueI) == 0);
      CHECK(norm(f.torqueJ) == 0);
    }
}

TEST_CASE("LLCM squeeze equals the seed formula (6 R0^4 / (4 H0^2)) / eps", "[lub]")
{
  const double region = 0.8;
  for (double ratio : kRatios)
    for (double eps : kGaps) {
      PairState s = genericPair(eps, ratio);
      s.angularVelocityI = s.angularVelocityJ = {};
      s.velocityI = 0.2 * s.normal;         // purely normal motion: no shear
      s.velocityJ = -0.05 * s.normal;
      const double R = s.reducedRadius();
      const double epsR = s.gap / R, H0 = epsR + region * region / 2; // in units of R
      const double U = 0.25;                                          // approach speed
      const Vec3 expected = (-M_PI * kMu * R * U * (6 * std::pow(region, 4) / (4 * H0 * H0)) / epsR) * s.normal;
      const PairForce f = llcmForce(s, region);
      CHECK(relErr(f.forceI, expected, norm(expected)) < 1e-12);
      CHECK(norm(f.torqueI) < 1e-12 * norm(f.forceI) * kA);
    }
}

TEST_CASE("LLCM shear closed forms equal the quadrature of the lubrication solution", "[lub]")
{
  const double region = 0.8;
  for (double ratio : kRatios)
    for (double eps : kGaps) {
      PairState s = genericPair(eps, ratio);
      s.velocityJ = s.velocityJ - dot(s.velocityJ - s.velocityI, s.normal) * s.normal; // no squeeze
      const PairForce f = llcmForce(s, region);
      const ShearQuadrature q = integrateShear(s, region);
      const double scaleF = norm(f.forceI), scaleT = norm(f.torqueI) + norm(f.torqueJ);
      INFO("eps " << eps << " ratio " << ratio);
      // The kernel is the seed's traction integral with the edge pressure term removed.
      CHECK(relErr(f.forceI, q.tractionI + q.edge, scaleF) < 1e-12);
      CHECK(relErr(f.torqueI, s.radiusI * cross(s.normal, q.viscousI + q.edge), scaleT) < 1e-12);
      if (!s.isWall())
        CHECK(relErr(f.torqueJ, -s.radiusJ * cross(s.normal, q.viscousJ + q.edge), scaleT) < 1e-12);
    }
}

TEST_CASE("The wall is the infinite-radius limit of the sphere-sphere kernels", "[lub]")
{
  for (double eps : kGaps)
    for (LubModel model : {LubModel::Blcm, LubModel::Llcm}) {
      PairState wall = genericPair(eps, kWallRadius);
      PairState big = wall;
      big.radiusJ = 1e9 * kA; // the same sliding body, curvature 1e-9 of the sphere's
      const PairForce fw = lubricationModelForce(model, 0.8, wall);
      const PairForce fb = lubricationModelForce(model, 0.8, big);
      CHECK(relErr(fw.forceI, fb.forceI, norm(fw.forceI)) < 1e-8);
      CHECK(relErr(fw.torqueI, fb.torqueI, norm(fw.torqueI) + 1e-30) < 1e-8);
    }
}

TEST_CASE("LLCM tends to BLCM as R0 grows, with F_llcm / F_blcm = (1 - eps/H0)^2", "[lub]")
{
  double previous = 1;
  for (double region : {1.0, 10.0, 100.0, 1000.0}) {
    for (double eps : kGaps) {
      PairState s = genericPair(eps, 1);
      const double ratio = dot(llcmForce(s, region).forceI, s.normal) / dot(blcmForce(s).forceI, s.normal);
      // Squeeze part only: project on n; the shear force is tangential.
      const double epsR = s.gap / s.reducedRadius(), H0 = epsR + region * region / 2;
      CHECK(std::fabs(ratio - std::pow(1 - epsR / H0, 2)) < 1e-13);
    }
    PairState s = genericPair(1e-2, 1);
    const double gap = 1 - dot(llcmForce(s, region).forceI, s.normal) / dot(blcmForce(s).forceI, s.normal);
    CHECK(gap < previous);
    previous = gap;
  }
  CHECK(previous < 1e-7);
}

TEST_CASE("LLCM reproduces the singular coefficients of a sphere at a wall", "[lub]")
{
  // Sphere above a wall at z = 0 (n = -e_z), region R0 = 1. Fit d(.)/d(ln eps) over 1e-6..1e-4.
  const std::vector<double> eps = logSpaced(1e-6, 1e-4, 9);
  std::vector<double> lnEps, fTrans, tTrans, fRot, tRot;
  const double U = 0.1, Omega = 3;
  for (double e : eps) {
    PairState s;
    s.normal = {0, 0, -1};
    s.radiusI = kA;
    s.radiusJ = kWallRadius;
    s.gap = e * kA;
    s.viscosity = kMu;
    s.velocityI = {U, 0, 0};
    const PairForce trans = llcmForce(s, 1);
    s.velocityI = {};
    s.angularVelocityI = {0, Omega, 0};
    const PairForce rot = llcmForce(s, 1);
    lnEps.push_back(std::log(e));
    fTrans.push_back(trans.forceI.x / (6 * M_PI * kMu * kA * U));
    tTrans.push_back(trans.torqueI.y / (8 * M_PI * kMu * kA * kA * U));
    fRot.push_back(rot.forceI.x / (6 * M_PI * kMu * kA * kA * Omega));
    tRot.push_back(rot.torqueI.y / (8 * M_PI * kMu * kA * kA * kA * Omega));
  }
  // Signs: drag opposes U (F_x ~ (8/15) ln eps < 0); the bottom surface of a sphere spinning
  // with +Omega e_y moves along -x, so the fluid pushes it along +x (F_x ~ -(2/15) ln eps) and
  // the resisting torque opposes the spin (T_y ~ (2/5) ln eps < 0).
  const double tol = 1e-3;
  CHECK(slope(lnEps, fTrans) == Approx(8.0 / 15).epsilon(tol));
  CHECK(slope(lnEps, tTrans) == Approx(-1.0 / 10).epsilon(tol));
  CHECK(slope(lnEps, fRot) == Approx(-2.0 / 15).epsilon(tol));
  CHECK(slope(lnEps, tRot) == Approx(2.0 / 5).epsilon(tol));
}

TEST_CASE("Two equal spheres: squeeze 1/(4 eps), without Jeffrey-Onishi's (9/40) ln(1/eps)", "[lub]")
{
  // Leading-order lubrication contains the 1/(4 eps) term; the (9/40) ln(1/eps) correction comes
  // from the next order of the inner expansion, which neither model contains. Measure both.
  const std::vector<double> eps = logSpaced(1e-6, 1e-4, 9);
  for (LubModel model : {LubModel::Blcm, LubModel::Llcm}) {
    std::vector<double> lnInv, remainder;
    double leading = 0;
    for (double e : eps) {
      PairState s;
      s.normal = {1, 0, 0};
      s.radiusI = s.radiusJ = kA;
      s.gap = e * kA;
      s.viscosity = kMu;
      s.velocityI = {0.05, 0, 0};
      s.velocityJ = {-0.05, 0, 0};
      const double Urel = 0.1;
      const double f = -lubricationModelForce(model, 1, s).forceI.x / (6 * M_PI * kMu * kA * Urel);
      lnInv.push_back(std::log(1 / e));
      remainder.push_back(f - 1 / (4 * e));
      leading = f * e;
    }
    CHECK(leading == Approx(0.25).epsilon(1e-3));
    CHECK(std::fabs(slope(lnInv, remainder)) < 1e-3); // J&O: 9/40 = 0.225
  }
}

TEST_CASE("Lubrication pair forces: swap antisymmetry and angular momentum balance", "[lub]")
{
  LubricationParams p;
  p.activation = 8; // every gap below is active, also relative to the smaller radius 0.25 a
  p.saturation = 2e-5;
  for (LubModel model : {LubModel::Blcm, LubModel::Llcm}) {
    p.model = model;
    for (double ratio : {0.25, 1.0, 4.0})
      for (double eps : kGaps) {
        const PairState s = genericPair(eps, ratio);
        PairState swapped = s;
        swapped.normal = -s.normal;
        std::swap(swapped.radiusI, swapped.radiusJ);
        std::swap(swapped.velocityI, swapped.velocityJ);
        std::swap(swapped.angularVelocityI, swapped.angularVelocityJ);
        const PairForce f = lubricationForce(p, s, 0), g = lubricationForce(p, swapped, 0);
        const double scaleT = norm(f.torqueI) + norm(f.torqueJ) + 1e-300;
        INFO("model " << lubModelName(model) << " eps " << eps << " ratio " << ratio);
        CHECK(relErr(g.forceI, -f.forceI, norm(f.forceI)) < 1e-12);
        CHECK(relErr(g.torqueI, f.torqueJ, scaleT) < 1e-12);
        CHECK(relErr(g.torqueJ, f.torqueI, scaleT) < 1e-12);
        // About any point: T_i + T_j + x_i x F_i + x_j x (-F_i) = 0.
        const double distance = s.radiusI + s.radiusJ + s.gap;
        const Vec3 balance = f.torqueI + f.torqueJ - distance * cross(s.normal, f.forceI);
        CHECK(norm(balance) < 1e-12 * (scaleT + distance * norm(f.forceI)));
      }
  }
}

namespace {

// eps_act 0.1 and eps_sat 1e-3 of the smaller radius; the model is set by each loop.
LubricationParams gapParams()
{
  LubricationParams p;
  p.activation = 0.1;
  p.saturation = 1e-3;
  return p;
}

} // namespace

TEST_CASE("Lubrication is zero above the activation gap, continuous at it, constant below saturation", "[lub]")
{
  LubricationParams p = gapParams();
  for (LubModel model : {LubModel::Blcm, LubModel::Llcm})
    for (double ratio : kRatios) {
      p.model = model;
      // Gaps relative to the smaller radius, as the activation and saturation are.
      auto pair = [&](double eps) {
        PairState s = genericPair(1, ratio);
        s.gap = eps * std::min(s.radiusI, s.radiusJ);
        return s;
      };
      auto at = [&](double eps) { return lubricationForce(p, pair(eps), 0); };
      const PairForce raw = lubricationModelForce(model, p.llcmRegion, pair(p.activation));
      const double scale = norm(raw.forceI);
      CHECK(norm(at(p.activation).forceI) == 0);
      CHECK(norm(at(1.5 * p.activation).forceI) == 0);
      CHECK(norm(at(1.5 * p.activation).torqueI) == 0);
      // Continuity: the force vanishes linearly as the gap rises to eps_act.
      const double jump = norm(at(p.activation * (1 - 1e-7)).forceI) / scale;
      CHECK(jump < 1e-5);
      CHECK(jump > 0);
      // Saturation: below eps_sat the force is that at eps_sat.
      const PairForce sat = at(p.saturation), below = at(0.25 * p.saturation);
      CHECK(norm(below.forceI - sat.forceI) == 0);
      CHECK(norm(at(0.5 * p.saturation).forceI) > 10 * scale);
    }
}

TEST_CASE("None gives no force", "[lub]")
{
  LubricationParams p;
  p.model = LubModel::None;
  p.activation = 1;
  p.saturation = 1e-3;
  const PairForce f = lubricationForce(p, genericPair(1e-3, 1), 0);
  CHECK(norm(f.forceI) == 0);
  CHECK(norm(f.torqueI) == 0);
  CHECK(norm(f.torqueJ) == 0);
}

TEST_CASE("BLCM in a pair-loop integration: quasi-steady approach under a constant force", "[lub]")
{
  // The usage the DEM pair loop will make: a sphere (seed mass) pushed at constant F towards a
  // wall, lubricationForce each step, symplectic Euler. Once inertia has relaxed (it shifts the
  // balance by about (dU/dt) m / (F) = 0.08 % at eps = 1e-4) the speed is
  // U = F / (6 pi mu a (1/eps - 1/eps_act)).
  LubricationParams p;
  p.model = LubModel::Blcm;
  p.activation = 0.1;
  p.saturation = 1e-6;
  const double mass = 1127 * 4.0 / 3.0 * M_PI * std::pow(kA, 3), F = 0.0119, dt = 1e-6;
  PairState s;
  s.normal = {0, -1, 0};
  s.radiusI = kA;
  s.radiusJ = kWallRadius;
  s.viscosity = kMu;
  s.gap = 0.2 * kA;
  while (s.gap > 1e-4 * kA) {
    const double force = -F + lubricationForce(p, s, 0).forceI.y;
    s.velocityI.y += dt * force / mass;
    s.gap += dt * s.velocityI.y;
  }
  const double eps = s.gap / kA;
  const double expected = F / (6 * M_PI * kMu * kA * (1 / eps - 1 / p.activation));
  INFO("U / U_quasi-steady = " << -s.velocityI.y / expected);
  CHECK(-s.velocityI.y == Approx(expected).epsilon(1e-2));
}

TEST_CASE("Hand-off: no lubrication once the surfaces touch, saturated resistance just above", "[lub]")
{
  LubricationParams p = gapParams();
  for (LubModel model : {LubModel::Blcm, LubModel::Llcm})
    for (double ratio : kRatios) {
      p.model = model;
      PairState s = genericPair(1, ratio);
      const double a = std::min(s.radiusI, s.radiusJ), contactGap = 4e-4 * a;
      for (double eps : {4e-4, 3e-4, 0.0, -1e-3}) {  // at, below the roughness gap, overlapping
        s.gap = eps * a;
        const PairForce f = lubricationForce(p, s, contactGap);
        INFO("model " << lubModelName(model) << " ratio " << ratio << " eps " << eps);
        CHECK(norm(f.forceI) == 0);
        CHECK(norm(f.torqueI) + norm(f.torqueJ) == 0);
      }
      // Just outside contact, below saturation: the saturated value, as without a contact gap.
      s.gap = 5e-4 * a;
      CHECK(norm(lubricationForce(p, s, contactGap).forceI - lubricationForce(p, s, 0).forceI) == 0);
      CHECK(norm(lubricationForce(p, s, contactGap).forceI) > 0);
    }
}

TEST_CASE("A free-slip wall gets a quarter of the squeeze and no shear", "[lub]")
{
  LubricationParams p;
  p.activation = 0.5;
  p.saturation = 1e-4;
  for (LubModel model : {LubModel::Blcm, LubModel::Llcm}) {
    p.model = model;
    for (double eps : {1e-3, 1e-2, 0.1}) {
      PairState s = genericPair(eps, 1);  // oblique velocities and spins
      s.radiusJ = kWallRadius;
      s.angularVelocityJ = Vec3{};
      s.gap = eps * s.radiusI;
      const PairForce noSlip = lubricationForce(p, s, 0);
      s.slipWall = true;
      const PairForce slip = lubricationForce(p, s, 0);
      INFO("model " << lubModelName(model) << " eps " << eps);
      CHECK(dot(slip.forceI, s.normal) == Approx(0.25 * dot(noSlip.forceI, s.normal)).epsilon(1e-14));
      CHECK(norm(s.tangential(slip.forceI)) <= 1e-15 * norm(slip.forceI));
      CHECK(norm(slip.torqueI) == 0);
      if (model == LubModel::Llcm)  // the no-slip wall does resist the sliding
        CHECK(norm(s.tangential(noSlip.forceI)) > 1e-3 * norm(noSlip.forceI));
    }
  }
}

TEST_CASE("Activation in grid cells: the same gap for every pair radius", "[lub]")
{
  LubricationParams p;
  p.model = LubModel::Blcm;
  p.activationCells = 1.5;
  const double h = 1e-4;
  p.resolveDefaults(h, false, 1e-3);
  p.checkRadius(2e-3);
  for (double ratio : kRatios) {
    PairState s = genericPair(1, ratio);
    CHECK(p.activationGap(std::min(s.radiusI, s.radiusJ)) == Approx(1.5 * h).epsilon(1e-15));
    s.gap = 1.5 * h * (1 + 1e-9);
    CHECK(norm(lubricationForce(p, s, 0).forceI) == 0);
    s.gap = 1.5 * h * (1 - 1e-3);
    CHECK(norm(lubricationForce(p, s, 0).forceI) > 0);
  }
}

TEST_CASE("Tangential terms from their own activation gap; the squeeze from the larger one", "[lub]")
{
  const double h = 1e-4;
  LubricationParams split, one;
  split.model = one.model = LubModel::Llcm;
  split.activationCells = one.activationCells = 0.5;
  split.shearActivationCells = 0.2;  // one: the same gap for both parts (shear 0.5 cells)
  one.shearActivationCells = 0.5;
  split.resolveDefaults(h, true, 1e-4);
  split.checkRadius(2e-3);
  one.resolveDefaults(h, true, 1e-4);
  one.checkRadius(2e-3);
  for (double ratio : kRatios) {
    PairState s = genericPair(1, ratio);  // oblique velocities and spins
    PairState squeeze = s;                 // the normal relative motion alone
    squeeze.velocityI = dot(s.velocityI, s.normal) * s.normal;
    squeeze.velocityJ = dot(s.velocityJ, s.normal) * s.normal;
    squeeze.angularVelocityI = squeeze.angularVelocityJ = Vec3{};
    INFO("ratio " << ratio);
    // Between the two gaps: the squeeze only, exactly what the normal motion alone gets.
    s.gap = squeeze.gap = 0.35 * h;
    const PairForce between = lubricationForce(split, s, 0);
    CHECK(norm(s.tangential(between.forceI)) <= 1e-14 * norm(between.forceI));
    CHECK(norm(between.forceI - lubricationForce(split, squeeze, 0).forceI) <= 1e-14 * norm(between.forceI));
    CHECK(norm(between.forceI - lubricationForce(one, squeeze, 0).forceI) <= 1e-14 * norm(between.forceI));
    // Below both: the split adds what the tangential part loses from 0.5 to 0.2 cells less than
    // the single gap; by linearity that is the tangential motion's correction between the two gaps.
    s.gap = 0.05 * h;
    PairState shear = s;
    shear.velocityI = s.tangential(s.velocityI);
    shear.velocityJ = s.tangential(s.velocityJ);
    shear.gap = 0.2 * h;
    LubricationParams wide = one;  // the tangential correction at 0.2 cells from the single 0.5-cell gap
    const PairForce lost = lubricationForce(wide, shear, 0);
    const PairForce a = lubricationForce(split, s, 0), b = lubricationForce(one, s, 0);
    CHECK(norm(s.tangential(lost.forceI)) > 0);
    // The mid-gap moment makes the torques depend on the gap: compare the forces.
    CHECK(norm(b.forceI - a.forceI - lost.forceI) <= 1e-12 * norm(b.forceI));
  }
}

TEST_CASE("Shear activation: default 0.06 cells, at most the squeeze's, checked", "[lub]")
{
  LubricationParams p;
  p.model = LubModel::Llcm;
  p.resolveDefaults(1e-4, true, 4e-4);
  p.checkRadius(1e-3);
  CHECK(p.shearActivationCells == kDefaultShearActivationCells);
  CHECK(p.shearActivationGap(1e-3) == Approx(0.06e-4).epsilon(1e-15));
  LubricationParams q;
  q.model = LubModel::Llcm;
  q.activationCells = 0.04;  // below the default shear gap: the shear gap follows it down
  q.resolveDefaults(1e-4, true, 4e-4);
  q.checkRadius(1e-5);
  CHECK(q.shearActivationGap(1e-3) == q.activationGap(1e-3));
  LubricationParams r;
  r.model = LubModel::Llcm;
  r.activationCells = 0.1;
  r.shearActivationCells = 0.2;
  CHECK_THROWS_WITH(r.resolveDefaults(1e-4, true, 4e-4),
                    "option -lub_shear_activation_cells: must be in (0, -lub_activation_cells = 0.1], got 0.2");
  LubricationParams e;  // an activation in radii: both parts use it
  e.model = LubModel::Llcm;
  e.activation = 0.05;
  e.resolveDefaults(1e-4, false, 4e-4);
  e.checkRadius(1e-3);
  CHECK(e.shearActivationGap(2e-3) == e.activationGap(2e-3));
}

TEST_CASE("Saturated resistance: BLCM wall value minus its activation value", "[lub]")
{
  LubricationParams p;
  p.model = LubModel::Blcm;
  p.activation = 0.1;
  p.saturation = 1e-3;
  PairState wall;
  wall.normal = {0, 0, 1};
  wall.radiusI = kA;
  wall.radiusJ = kWallRadius;
  wall.viscosity = kMu;
  // c = 6 pi mu a (1/eps_sat - 1/eps_act); a contact gap above the saturation gap takes its place.
  CHECK(lubricationResistance(p, wall, 0) == Approx(6 * M_PI * kMu * kA * (1 / 1e-3 - 1 / 0.1)).epsilon(1e-12));
  CHECK(lubricationResistance(p, wall, 4e-3 * kA) == Approx(6 * M_PI * kMu * kA * (1 / 4e-3 - 1 / 0.1)).epsilon(1e-9));
}

namespace {

// The first-order inertia of the squeeze film at a wall, computed here from the flow itself: the
// Poiseuille squeeze u0 = 3 U r z (h - z) / h^3 in the film h(r, t) = h0 - U t + r^2 / (2a) (t only
// moves h0), w0 from continuity, the inertial acceleration I = du0/dt + u0 du0/dr + w0 du0/dz by
// finite differences, and the pressure gradient that keeps the film's flux with it,
// dp1/dr = -(6 rho / h^3) int I z (h - z) dz. Returns the force of p1 on the sphere, integral of
// p1 2 pi r dr, between the films of minimum gaps h0 and h1 (the same outer edge, far out).
double filmInertiaForceDifference(double rho, double U, double a, double h0, double h1)
{
  std::vector<double> gx, gw;  // exact across the film: I z (h - z) is a polynomial of degree 6 in z
  gaussLegendre(4, gx, gw);
  auto force = [&](double hMin) {
    auto h = [&](double r, double t) { return hMin - U * t + r * r / (2 * a); };
    auto u0 = [&](double r, double z, double t) { const double g = h(r, t); return 3 * U * r * z * (g - z) / (g * g * g); };
    auto ru0r = [&](double r, double z) {  // (1/r) d(r u0)/dr
      const double e = 1e-6 * r;
      return ((r + e) * u0(r + e, z, 0) - (r - e) * u0(r - e, z, 0)) / (2 * e * r);
    };
    // The force is 2 pi a int p1 dh (r dr = a dh), and with p1 = 0 at the edge h = H,
    // int p1 dh = -int (h - hMin) dp1/dh dh.
    const double H = 100 * a;
    const int n = 600;
    double sum = 0;
    for (int k = 0; k < n; ++k) {  // midpoints in ln(h - hMin) from 1e-3 hMin up to H
      const double lo = std::log(1e-3 * hMin), hi = std::log(H);
      const double s = lo + (k + 0.5) * (hi - lo) / n, dh = std::exp(s), g = hMin + dh;
      const double r = std::sqrt(2 * a * dh);
      double p1r = 0;
      for (int q = 0; q < 4; ++q) {
        const double z = 0.5 * g * (1 + gx[q]);
        const double et = 1e-6 * g / U, er = 1e-6 * r;
        const double ut = (u0(r, z, et) - u0(r, z, -et)) / (2 * et);
        const double ur = (u0(r + er, z, 0) - u0(r - er, z, 0)) / (2 * er);
        const double uz = 3 * U * r * (g - 2 * z) / (g * g * g);
        double w = 0;  // w0 = -int_0^z (1/r) d(r u0)/dr dz'
        for (int m = 0; m < 4; ++m) w -= 0.5 * z * gw[m] * ru0r(r, 0.5 * z * (1 + gx[m]));
        const double I = ut + u0(r, z, 0) * ur + w * uz;
        p1r += 0.5 * g * gw[q] * I * z * (g - z);
      }
      p1r *= -6 * rho / (g * g * g);
      const double dp1dh = p1r * a / r;
      sum -= dh * dp1dh * dh * (hi - lo) / n;  // (h - hMin) dp1/dh dh, with dh = (h - hMin) d ln(h - hMin)
    }
    return 2 * M_PI * a * sum;
  };
  return force(h0) - force(h1);
}

} // namespace

TEST_CASE("The gap's inertia at a wall (-lub_inertia) is the first-order inertia of the squeeze film", "[lub]")
{
  LubricationParams p = gapParams();
  p.model = LubModel::Llcm;
  PairState s;
  s.normal = {0, 0, -1};
  s.radiusI = kA;
  s.radiusJ = kWallRadius;
  s.viscosity = kMu;
  s.density = 1200;
  s.gap = 0.2 * p.activation * kA;
  const double U = 0.7;
  const double hAct = p.activationGap(kA);
  for (double sign : {1.0, -1.0}) {  // approaching and leaving: the inertia repels both ways
    s.velocityI = sign * U * s.normal;
    const Vec3 viscous = lubricationForce(p, s, 0).forceI;
    p.inertia = true;
    const Vec3 inertial = lubricationForce(p, s, 0).forceI - viscous;
    p.inertia = false;
    const double expected = filmInertiaForceDifference(s.density, U, kA, s.gap, hAct);
    CHECK(inertial.z == Approx(expected).epsilon(0.01));  // along +z: away from the wall below
    CHECK(std::hypot(inertial.x, inertial.y) == 0);
  }
  // Pairs of spheres and the viscous resistance of the implicit squeeze are not changed.
  p.inertia = true;
  PairState pair = genericPair(0.2 * p.activation, 1);
  pair.density = 1200;
  PairState dry = pair;
  dry.density = 0;
  CHECK(norm(lubricationForce(p, pair, 0).forceI - lubricationForce(p, dry, 0).forceI) == 0);
  s.density = 1200;
  const double c = squeezeResistance(p, s, 0);
  p.inertia = false;
  CHECK(c == squeezeResistance(p, s, 0));
}
