// The shape seam (particles/Shape.hpp) against independent computations: inertia by quadrature of
// the inside test, distances by brute force over the surface, curvatures by finite differences of
// the surface, the gap's squeeze radius at the values of lubrication theory; and a free spheroid in
// the DEM: torque-free precession against the exact solution of the symmetric top, and its bounce
// on a wall.
#include "../support/DemFixtures.hpp"
#include "vp/io/CollapseMonitor.hpp"
#include "vp/particles/Shape.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <random>

using namespace vp;
using namespace vp::test;

namespace {

// Spheroid surface point at polar angle t from the body z axis and azimuth p.
Vec3 surfacePoint(const Shape& g, double t, double p)
{
  return {g.a * std::sin(t) * std::cos(p), g.a * std::sin(t) * std::sin(p), g.c() * std::cos(t)};
}

} // namespace

TEST_CASE("Shape: volume and inertia of a spheroid by quadrature of its inside test", "[shape]")
{
  for (double aspect : {0.5, 2.0}) {
    const Shape g{1.0, aspect};
    // Midpoint rule over the bounding box with the signed distance as the inside test.
    const int n = 80;
    const double ex[3] = {g.a, g.a, g.c()};
    double V = 0, Ix = 0, Iz = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const Vec3 p{ex[0] * (2 * (i + 0.5) / n - 1), ex[1] * (2 * (j + 0.5) / n - 1), ex[2] * (2 * (k + 0.5) / n - 1)};
          if (g.distance(p) >= 0) continue;
          const double dV = 8 * ex[0] * ex[1] * ex[2] / (double(n) * n * n);
          V += dV;
          Ix += (p.y * p.y + p.z * p.z) * dV;
          Iz += (p.x * p.x + p.y * p.y) * dV;
        }
    const Vec3 I = g.volume() * g.inertiaOverMass();
    CHECK(V == Approx(g.volume()).epsilon(3e-3));
    CHECK(Ix == Approx(I.x).epsilon(5e-3));
    CHECK(Iz == Approx(I.z).epsilon(5e-3));
    CHECK(g.equalVolumeRadius() == Approx(std::cbrt(V * 3 / (4 * M_PI))).epsilon(2e-3));
  }
}

TEST_CASE("Shape: the volume between two planes against quadrature of the inside test, tilted bodies", "[shape]")
{
  // The space z planes cut a body whose axis is tilted by 0.6 rad: the slab's volume from the body
  // frame's normal against a midpoint sum over the points inside and between the planes.
  const Quaternion q = alignedWith(Vec3{std::sin(0.6), 0, std::cos(0.6)});
  const Vec3 nz = toBody(q, Vec3{0, 0, 1});
  for (double aspect : {1.0, 0.5, 2.0}) {
    const Shape g{1.0, aspect};
    const double L = g.boundingRadius();
    const int n = 100;
    const double slabs[][2] = {{-5, 5}, {-0.3, 0.4}, {0.5, 5}, {-5, -0.8}, {2.5, 3}};
    for (const auto& s : slabs) {
      // Midpoints over the bounding cube cut to the slab: the planes are cell faces.
      const double z0 = std::max(s[0], -L), z1 = std::min(s[1], L), hz = std::max(z1 - z0, 0.0) / n;
      double V = 0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          for (int k = 0; k < n; ++k) {
            const Vec3 x{L * (2 * (i + 0.5) / n - 1), L * (2 * (j + 0.5) / n - 1), z0 + (k + 0.5) * hz};
            if (g.distance(toBody(q, x)) < 0) V += 4 * L * L * hz / (double(n) * n);
          }
      INFO("aspect " << aspect << ", planes at " << s[0] << " and " << s[1]);
      CHECK(g.volumeBetween(nz, s[0], s[1]) == Approx(V).margin(1e-3 * g.volume()));
    }
    CHECK(g.volumeBetween(nz, -5, 5) == Approx(g.volume()).epsilon(1e-14));
    CHECK(g.volumeBetween(nz, -5, 0) == Approx(0.5 * g.volume()).epsilon(1e-14));
  }
}

TEST_CASE("Shape: the signed distance equals the nearest of many surface points, inside and outside", "[shape]")
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (double aspect : {0.4, 1.0, 3.0}) {
    const Shape g{0.5, aspect};
    const double R = g.boundingRadius();
    for (int trial = 0; trial < 40; ++trial) {
      // Points within 1.5 bounding radii, some on the axes and the equator (the degenerate cases).
      Vec3 p{u(rng), u(rng), u(rng)};
      p = (1.5 * R) * p;
      if (trial % 8 == 0) p.x = p.y = 0;
      if (trial % 8 == 1) p.z = 0;
      double best = HUGE_VAL;
      // Coarse search over the surface, then refinement around the best sample.
      double bt = 0, bp = 0;
      for (int i = 0; i <= 400; ++i)
        for (int j = 0; j < 400; ++j) {
          const double t = M_PI * i / 400, ph = 2 * M_PI * j / 400, d = norm(surfacePoint(g, t, ph) - p);
          if (d < best) best = d, bt = t, bp = ph;
        }
      for (double step = M_PI / 400; step > 1e-12; step *= 0.5)
        for (int it = 0; it < 4; ++it)
          for (int dt = -1; dt <= 1; ++dt)
            for (int dp = -1; dp <= 1; ++dp) {
              const double t = bt + dt * step, ph = bp + dp * step, d = norm(surfacePoint(g, t, ph) - p);
              if (d < best) best = d, bt = t, bp = ph;
            }
      const double inside = (p.x * p.x + p.y * p.y) / (g.a * g.a) + p.z * p.z / (g.c() * g.c()) - 1;
      const double expected = inside < 0 ? -best : best;
      INFO("aspect " << aspect << " point " << p.x << "," << p.y << "," << p.z);
      CHECK(g.distance(p) == Approx(expected).margin(1e-9 * R));
    }
  }
}

TEST_CASE("Shape: the point with a given normal lies on the surface with that normal", "[shape]")
{
  std::mt19937_64 rng(3);
  std::normal_distribution<double> u;
  for (double aspect : {0.5, 2.0}) {
    const Shape g{1.0, aspect};
    for (int trial = 0; trial < 20; ++trial) {
      Vec3 n{u(rng), u(rng), u(rng)};
      n = n / norm(n);
      const Vec3 p = g.pointWithNormal(n);
      CHECK(g.distance(p) == Approx(0).margin(1e-12));
      const Vec3 grad{p.x / (g.a * g.a), p.y / (g.a * g.a), p.z / (g.c() * g.c())};
      CHECK(norm(cross(grad / norm(grad), n)) < 1e-12);
      CHECK(dot(grad, n) > 0);
      CHECK(g.extent(n) == Approx(dot(p, n)).epsilon(1e-12));
    }
  }
}

TEST_CASE("Shape: curvature tensor against finite differences of the surface", "[shape]")
{
  // Meridian and parallel curvatures of the surface of revolution at polar angle t, by finite
  // differences of the meridian curve (rho(t), z(t)) and the parallel radius over the normal.
  const Shape g{1.0, 2.0};
  for (double t : {0.3, 0.9, 1.4}) {
    const Vec3 p = surfacePoint(g, t, 0);
    const Tensor3 K = g.curvature(p);
    const double h = 1e-4;
    auto r = [&](double s) { return surfacePoint(g, s, 0); };
    const Vec3 d1 = (r(t + h) - r(t - h)) / (2 * h), d2 = (r(t + h) - 2.0 * r(t) + r(t - h)) / (h * h);
    const double meridian = norm(cross(d1, d2)) / std::pow(norm(d1), 3);
    const Vec3 normal{p.x / (g.a * g.a), 0, p.z / (g.c() * g.c())};
    const double parallel = (normal.x / norm(normal)) / p.x;  // Meusnier: cos(angle to the axis normal) / rho
    const std::array<double, 2> k = tangentEigenvalues(K, normal / norm(normal));
    const double lo = std::min(meridian, parallel), hi = std::max(meridian, parallel);
    CHECK(k[0] == Approx(lo).epsilon(1e-6));
    CHECK(k[1] == Approx(hi).epsilon(1e-6));
  }
}

TEST_CASE("Shape: squeeze radius of two spheroids' gap at the values of lubrication theory", "[shape][lub]")
{
  // Equatorial semi-axis 1, polar c. The curvature tensors of the two surfaces at their closest
  // points, turned into space (the second body rotated), summed in the common tangent plane.
  auto pair = [](double c, const Quaternion& q1, const Vec3& n1, const Quaternion& q2, const Vec3& n2, const Vec3& normal) {
    const Shape g{1.0, c};
    const Tensor3 K1 = rotatedTensor(g.curvature(g.pointWithNormal(n1)), q1);
    const Tensor3 K2 = rotatedTensor(g.curvature(g.pointWithNormal(n2)), q2);
    Tensor3 K;
    for (int k = 0; k < 9; ++k) K[k] = K1[k] + K2[k];
    const std::array<double, 2> e = tangentEigenvalues(K, normal);
    return squeezeRadiusSquared(e[0], e[1]);
  };
  auto wall = [](double c, const Vec3& n) {
    const Shape g{1.0, c};
    const std::array<double, 2> e = tangentEigenvalues(g.curvature(g.pointWithNormal(n)), n);
    return squeezeRadiusSquared(e[0], e[1]);
  };
  const Quaternion none{}, turned = alignedWith(Vec3{0, 1, 0});  // body z along y
  // Axes parallel (z), equator to equator along x.
  CHECK(pair(2, none, {1, 0, 0}, none, {-1, 0, 0}, {1, 0, 0}) == Approx(0.80).epsilon(1e-12));
  CHECK(pair(3, none, {1, 0, 0}, none, {-1, 0, 0}, {1, 0, 0}) == Approx(1.35).epsilon(1e-12));
  // Pole to pole.
  CHECK(pair(2, none, {0, 0, 1}, none, {0, 0, -1}, {0, 0, 1}) == Approx(0.0625).epsilon(1e-12));
  // Crossed axes (z and y), equator to equator along x: the gap's curvatures are 1 + 1/4 both ways.
  CHECK(pair(2, none, {1, 0, 0}, turned, toBody(turned, {-1, 0, 0}), {1, 0, 0}) == Approx(2 / (2.5 * 1.25)).epsilon(1e-12));
  // Spheres: the reduced radius squared, (a1 a2 / (a1 + a2))^2 at a1 = a2 = 1.
  CHECK(pair(1, none, {0, 0, 1}, none, {0, 0, -1}, {0, 0, 1}) == Approx(0.25).epsilon(1e-12));
  // Against a wall: equator, pole (a^2 / c)^2.
  CHECK(wall(2, {1, 0, 0}) == Approx(3.20).epsilon(1e-12));
  CHECK(wall(2, {0, 0, 1}) == Approx(0.25).epsilon(1e-12));
  CHECK(wall(0.5, {0, 0, 1}) == Approx(4.0).epsilon(1e-12));
}

TEST_CASE("Shape: the largest squeeze radius bounds that of any two bodies' nearest points; spheres, poles and equators meet it", "[shape][lub]")
{
  // The least mean curvature and Gaussian curvature over the surface, against a sampling of it.
  for (double aspect : {0.4, 1.0, 2.0, 3.0}) {
    const Shape g{1.0, aspect};
    double H = HUGE_VAL, rootK = HUGE_VAL;
    for (int i = 0; i <= 400; ++i) {
      const Vec3 p = surfacePoint(g, M_PI * i / 400, 0.3);
      const Vec3 n = Vec3{p.x, p.y, p.z / (aspect * aspect)} / norm(Vec3{p.x, p.y, p.z / (aspect * aspect)});
      const std::array<double, 2> k = tangentEigenvalues(g.curvature(p), n);
      H = std::min(H, 0.5 * (k[0] + k[1]));
      rootK = std::min(rootK, std::sqrt(k[0] * k[1]));
    }
    CHECK(H == Approx(g.leastMeanCurvature()).epsilon(1e-9));
    CHECK(rootK == Approx(g.leastRootGaussCurvature()).epsilon(1e-9));
  }
  // The bound against the squeeze radius of random pairs at their nearest points.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> u;
  auto unit = [&] {
    Vec3 v{u(rng), u(rng), u(rng)};
    return v / norm(v);
  };
  const Shape shapes[] = {{1.0, 2.0}, {0.8, 0.5}, {0.7, 1.0}, {1.2, 3.0}};
  for (int trial = 0; trial < 200; ++trial) {
    const Shape gi = shapes[trial % 4], gj = shapes[(trial / 4) % 4];
    const Quaternion qi = alignedWith(unit()), qj = alignedWith(unit());
    const Vec3 d = 5.0 * unit();
    const ClosestPoints c = closestPoints(gi, qi, gj, qj, d, d);
    Tensor3 K = rotatedTensor(gi.curvature(toBody(qi, c.pI)), qi);
    const Tensor3 Kj = rotatedTensor(gj.curvature(toBody(qj, c.pJ)), qj);
    for (int m = 0; m < 9; ++m) K[m] += Kj[m];
    const std::array<double, 2> k = tangentEigenvalues(K, c.n);
    CHECK(squeezeRadiusSquared(k[0], k[1]) <= largestSqueezeRadiusSquared(gi, &gj) * (1 + 1e-12));
  }
  const Shape sphereI{1.0, 1}, sphereJ{0.7, 1}, prolate{1.0, 2}, oblate{1.0, 0.5};
  CHECK(largestSqueezeRadiusSquared(sphereI, &sphereJ) == Approx(std::pow(0.7 / 1.7, 2)).epsilon(1e-12));
  CHECK(largestSqueezeRadiusSquared(prolate, nullptr) == Approx(3.2).epsilon(1e-12));  // equator at a wall
  CHECK(largestSqueezeRadiusSquared(oblate, nullptr) == Approx(4.0).epsilon(1e-12));   // pole at a wall
  CHECK(largestSqueezeRadiusSquared(prolate, &prolate) == Approx(0.8).epsilon(1e-12));  // equators, axes parallel
}

TEST_CASE("Quaternion: alignedWith takes the body z axis onto the axis; toBody undoes toSpace", "[shape]")
{
  for (Vec3 axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, -1}, Vec3{0.6, -0.48, 0.64}}) {
    const Quaternion q = alignedWith(axis);
    const Vec3 z = toSpace(q, {0, 0, 1});
    CHECK(norm(z - axis) < 1e-14);
    const Vec3 v{0.3, -1.2, 2.5};
    CHECK(norm(toBody(q, toSpace(q, v)) - v) < 1e-14);
  }
}

namespace {

// A free spheroid (no walls reached, no gravity) spinning off its principal axes for a time T.
Vec3 freeAxis(double dt, double T, Vec3& L0, Vec3& L1, double& E0, double& E1)
{
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  ParticleConfig pc = contactConfig(1e-3, 0.9, 0);
  ParticleRecord r = sphere(0, {0.5, 0.5, 0.5}, 0.05, 1000, {}, {2.0, 0.0, 5.0});
  r.aspect.value = 2;
  c.time.dt = dt;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), {r});
  const ParticleStore& s = dem.particles();
  auto L = [&] {
    const Vec3 b = toBody(s.q[0], s.w[0]), k = s.invInertiaBody[0];
    return toSpace(s.q[0], Vec3{b.x / k.x, b.y / k.y, b.z / k.z});
  };
  L0 = L();
  E0 = dem.diagnostics().kineticEnergy;
  const int steps = static_cast<int>(std::lround(T / dt));
  for (int k = 0; k < steps; ++k) dem.advance(0, dt);
  L1 = L();
  E1 = dem.diagnostics().kineticEnergy;
  return toSpace(s.q[0], {0, 0, 1});
}

} // namespace

TEST_CASE("DEM spheroid: torque-free precession of a symmetric top, exact to second order in the step", "[shape][dem]")
{
  // Prolate, c = 2a: I1 = m (a^2 + c^2) / 5 = m a^2, I3 = 2 m a^2 / 5. Started with the symmetry
  // axis along z and w = (2, 0, 5): L = (2 I1, 0, 5 I3) stays fixed and the axis turns about L at
  // the rate |L| / I1 on a cone of half-angle acos(L_z / |L|) (Landau & Lifshitz, section 33).
  const double a = 0.05, m = 1000 * 4.0 / 3.0 * M_PI * a * a * 2 * a, I1 = m * a * a, I3 = 0.4 * m * a * a;
  const Vec3 L{2 * I1, 0, 5 * I3};
  const Vec3 l = L / norm(L);
  const double rate = norm(L) / I1, T = 1.3;
  // The exact axis: z turned about l by rate T.
  const Vec3 z{0, 0, 1};
  const double ang = rate * T;
  const Vec3 exact = std::cos(ang) * z + std::sin(ang) * cross(l, z) + (1 - std::cos(ang)) * dot(l, z) * l;
  double err[2];
  const double steps[2] = {2e-3, 1e-3};
  for (int k = 0; k < 2; ++k) {
    Vec3 L0, L1;
    double E0, E1;
    const Vec3 axis = freeAxis(steps[k], T, L0, L1, E0, E1);
    err[k] = norm(axis - exact);
    CHECK(norm(L1 - L0) < 1e-12 * norm(L0));  // angular momentum carried exactly
    CHECK(norm(L0 - L) < 1e-12 * norm(L));
    CHECK(std::fabs(E1 / E0 - 1) < 1e-3);
  }
  INFO("axis error " << err[0] << " at dt 2e-3, " << err[1] << " at dt 1e-3");
  CHECK(err[1] < 2e-3);
  CHECK(err[0] / err[1] == Approx(4).epsilon(0.15));  // second order
}

TEST_CASE("DEM spheroid: a wall bounce with the sphere law's restitution, and spin from an off-centre normal", "[shape][dem]")
{
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  c.gravity = {0, 0, 0};
  const double e = 0.7, a = 0.05;
  for (int tilted = 0; tilted < 2; ++tilted) {
    ParticleRecord r = sphere(0, {0.5, 0.5, 0.15}, a, 1000, {0, 0, -1});
    r.aspect.value = 2;
    r.q = alignedWith(tilted ? Vec3{std::sin(0.5), 0, std::cos(0.5)} : Vec3{0, 0, 1});
    ParticleConfig pc = contactConfig(1e-3, e, 0);
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc), {r});
    const ParticleStore& s = dem.particles();
    const double E0 = dem.diagnostics().kineticEnergy;
    for (int k = 0; k < 4000; ++k) dem.advance(0, 2e-5);  // 0.08 s: reaches the wall at 0.05 s, bounces
    const double E1 = dem.diagnostics().kineticEnergy;
    if (!tilted) {
      // Pole down: the normal passes through the centre, a sphere's bounce.
      CHECK(s.v[0].z / 1.0 == Approx(e).epsilon(0.02));
      CHECK(norm(s.w[0]) < 1e-12);
    } else {
      // Tilted: the contact point is off the vertical through the centre: the spheroid spins up
      // about y, rebounds slower than e, and gains no energy.
      CHECK(std::fabs(s.w[0].y) > 1);
      CHECK(s.v[0].z > 0);
      CHECK(s.v[0].z < e);
      CHECK(E1 < E0);
    }
  }
}

TEST_CASE("DEM spheroid: the squeeze at a wall is that of the sphere with the gap's curvatures, at the contact point", "[shape][dem][lub]")
{
  // A spheroid (a = 1 cm, c = 2 cm) moving at 1 cm/s towards the bottom wall at the gap h = 0.05 a,
  // held at that velocity (fixed). BLCM squeeze from the activation gap 0.5 a:
  // F = 6 pi mu R^2 V (1/h - 1/h_act), R^2 from lubrication theory on the gap (docs/shapes.md).
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  c.fluid.mu = 1e-3;
  const double a = 0.01, V = 0.01, h = 0.05 * a, hAct = 0.5 * a, mu = 1e-3;
  auto force = [&](const Vec3& axis, Vec3& torque, Vec3& centre) {
    const Shape g{a, 2};
    const Quaternion q = alignedWith(axis);
    centre = {0.5, 0.5, g.extent(toBody(q, {0, 0, -1})) + h};
    ParticleRecord r = sphere(0, centre, a, 1000, {0, 0, -V});
    r.aspect.value = 2;
    r.q = q;
    r.flags = kFixed;
    ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 1e-3, LubModel::Blcm, 0.5);
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc), {r});
    torque = dem.particles().torque[0];
    return dem.particles().force[0];
  };
  auto expected = [&](double R2) { return 6 * M_PI * mu * R2 * V * (1 / h - 1 / hAct); };
  Vec3 T, x;
  Vec3 F = force({0, 0, 1}, T, x);  // pole down: R^2 = (a^2 / c)^2
  CHECK(F.z == Approx(expected(0.25 * a * a)).epsilon(1e-9));
  CHECK(std::hypot(F.x, F.y) < 1e-12 * F.z);
  CHECK(norm(T) < 1e-12 * F.z * a);
  F = force({1, 0, 0}, T, x);  // equator down: R^2 = 3.2 a^2
  CHECK(F.z == Approx(expected(3.2 * a * a)).epsilon(1e-9));
  // Tilted by 0.6 rad: the force is normal to the wall and acts at the lowest surface point, found
  // here by a search over the surface.
  const Vec3 axis{std::sin(0.6), 0, std::cos(0.6)};
  F = force(axis, T, x);
  const Quaternion q = alignedWith(axis);
  Vec3 low{0, 0, HUGE_VAL};
  for (int i = 0; i <= 2000; ++i)
    for (int j = 0; j < 64; ++j) {
      const double t = M_PI * i / 2000, p = 2 * M_PI * j / 64;
      const Vec3 s = toSpace(q, Vec3{a * std::sin(t) * std::cos(p), a * std::sin(t) * std::sin(p), 2 * a * std::cos(t)});
      if (s.z < low.z) low = s;
    }
  CHECK(F.z > expected(0.25 * a * a));
  CHECK(F.z < expected(3.2 * a * a));
  CHECK(T.y == Approx(cross(low, F).y).epsilon(1e-3));
  CHECK(std::fabs(T.y) > 0.1 * a * F.z);
}

TEST_CASE("DEM spheroids: the squeeze between two is that of their gap's curvatures, equal and opposite, at the nearest points", "[shape][dem][lub]")
{
  // Body i (a = 1 cm) moving at 1 cm/s towards body j at rest, at the gap h = 0.05 a between their
  // nearest points; BLCM squeeze from the activation gap 0.5 a: F = 6 pi mu R^2 V (1/h - 1/h_act).
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  c.fluid.mu = 1e-3;
  c.gravity = {0, 0, 0};
  const double a = 0.01, V = 0.01, h = 0.05 * a, hAct = 0.5 * a, mu = 1e-3;
  struct Result {
    Vec3 F, Fj, Ti, Tj, xi, xj, n;
  };
  auto run = [&](const Shape& gi, const Vec3& axisI, const Shape& gj, const Vec3& axisJ, const Vec3& dir) {
    const Quaternion qi = alignedWith(axisI / norm(axisI)), qj = alignedWith(axisJ / norm(axisJ));
    const Vec3 xi{0.5, 0.5, 0.5};
    const ClosestPoints far = closestPoints(gi, qi, gj, qj, dir, dir);
    const Vec3 xj = xi + dir + (h - far.gap) * far.n;
    const ClosestPoints near = closestPoints(gi, qi, gj, qj, xj - xi, far.n);
    ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 1e-3, LubModel::Blcm, 0.5);
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc),
                  {spheroid(0, xi, gi.a, gi.aspect, axisI, 1000, V * near.n), spheroid(1, xj, gj.a, gj.aspect, axisJ, 1000)});
    const ParticleStore& s = dem.particles();
    return Result{s.force[0], s.force[1], s.torque[0], s.torque[1], s.x[0], s.x[1], near.n};
  };
  auto expected = [&](double R2, double smaller = 1) { return 6 * M_PI * mu * R2 * V * (1 / h - 1 / (hAct * smaller)); };
  const Shape prolate{a, 2}, ball{0.7 * a, 1};
  // Equator to equator, axes parallel: R^2 = 0.80 a^2, along the line of centres, no torque.
  Result r = run(prolate, {0, 0, 1}, prolate, {0, 0, 1}, {0.05, 0, 0});
  CHECK(-r.F.x == Approx(expected(0.80 * a * a)).epsilon(1e-9));
  CHECK(norm(r.Ti) + norm(r.Tj) < 1e-12 * norm(r.F) * a);
  // Pole to pole: R^2 = a^4 / (4 c^2) = 0.0625 a^2.
  r = run(prolate, {1, 0, 0}, prolate, {1, 0, 0}, {0.05, 0, 0});
  CHECK(-r.F.x == Approx(expected(0.0625 * a * a)).epsilon(1e-9));
  // A spheroid's equator against a sphere: the curvatures 1/a + 1/b and a/c^2 + 1/b (b = 0.7 a); the
  // activation gap is that of the smaller equatorial radius, b.
  r = run(prolate, {0, 0, 1}, ball, {0, 0, 1}, {0.05, 0, 0});
  CHECK(-r.F.x == Approx(expected(squeezeRadiusSquared(1 / a + 1 / (0.7 * a), 0.25 / a + 1 / (0.7 * a)), 0.7)).epsilon(1e-9));
  // Tilted bodies, off the line of centres: equal and opposite along the common normal, and the pair
  // exerts no net torque about any point (the two forces act at one point).
  r = run(prolate, {1, 0.3, 0.5}, Shape{0.8 * a, 0.5}, {0.2, 1, -0.4}, {0.03, 0.02, -0.01});
  CHECK(norm(r.F + r.Fj) < 1e-14 * norm(r.F));
  CHECK(norm(cross(r.F, r.n)) < 1e-12 * norm(r.F));
  CHECK(dot(r.F, r.n) < -expected(0.0625 * a * a, 0.8));
  CHECK(norm(r.Ti + r.Tj + cross(r.xi, r.F) + cross(r.xj, r.Fj)) < 1e-12 * norm(r.F) * norm(r.xi));
  CHECK(norm(r.Ti) > 0.01 * norm(r.F) * a);
}

TEST_CASE("DEM spheroids: a spheroid of aspect 1 + 1e-7 feels the sphere's lubrication force and torques, sliding and spinning", "[shape][dem][lub]")
{
  // The squeeze from the gap's curvatures and the tangential terms of the osculating spheres tend to
  // the sphere model's as the spheroid tends to a sphere: a pair and a body at a wall, approaching,
  // sliding and spinning at the gap 0.02 a (BLCM and LLCM from the gap 0.5 a).
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  c.fluid.mu = 1e-3;
  c.gravity = {0, 0, 0};
  const double a = 0.01, h = 0.02 * a;
  for (LubModel model : {LubModel::Blcm, LubModel::Llcm}) {
    auto run = [&](double aspect, bool wall, Vec3 F[2], Vec3 T[2]) {
      const Vec3 n = Vec3{0.3, -0.2, -0.9} / norm(Vec3{0.3, -0.2, -0.9});  // from body 0 towards body 1
      const Vec3 xi = wall ? Vec3{0.5, 0.5, a + h} : Vec3{0.5, 0.5, 0.5};
      std::vector<ParticleRecord> p = {spheroid(0, xi, a, aspect, {0.2, 1, 0.4}, 1000, {0.01, -0.02, -0.005}, {3, -1, 2})};
      if (!wall) p.push_back(spheroid(1, xi + (0.8 * a + a + h) * n, 0.8 * a, aspect, {1, 0, 0.3}, 1000, {-0.01, 0.005, 0.01}, {-2, 0, 4}));
      ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 1e-3, model, 0.5);
      Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
      DemSolver dem(grid, c, resolved(c, pc), p);
      for (std::size_t k = 0; k < p.size(); ++k) F[k] = dem.particles().force[k], T[k] = dem.particles().torque[k];
    };
    for (bool wall : {false, true}) {
      Vec3 Fs[2], Ts[2], Fq[2], Tq[2];
      run(1, wall, Fs, Ts);
      run(1 + 1e-7, wall, Fq, Tq);
      INFO((model == LubModel::Blcm ? "BLCM" : "LLCM") << (wall ? " at a wall" : " pair"));
      for (int k = 0; k < (wall ? 1 : 2); ++k) {
        CHECK(norm(Fq[k] - Fs[k]) < 1e-5 * norm(Fs[k]));
        CHECK(norm(Tq[k] - Ts[k]) < 1e-5 * norm(Ts[k]) + 1e-6 * norm(Fs[k]) * a);  // the 1e-7 tilt of a lever
      }
      if (model == LubModel::Llcm) {  // BLCM is the squeeze alone
        // The tangential terms are there: the force is not along the normal.
        const Vec3 n = wall ? Vec3{0, 0, 1} : Vec3{0.3, -0.2, -0.9} / norm(Vec3{0.3, -0.2, -0.9});
        CHECK(norm(cross(Fq[0], n)) > 0.05 * norm(Fq[0]));
        CHECK(norm(Tq[0]) > 0.05 * norm(Fq[0]) * a);
      }
    }
  }
}

TEST_CASE("DEM spheroids: the tangential lubrication of a pair conserves angular momentum; a prolate sliding at a wall feels the osculating sphere's", "[shape][dem][lub]")
{
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  c.fluid.mu = 1e-3;
  c.gravity = {0, 0, 0};
  const double a = 0.01, h = 0.02 * a;
  ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 1e-3, LubModel::Llcm, 0.5);
  {
    // Tilted prolate and oblate bodies, sliding and spinning near each other.
    const Shape gi{a, 2}, gj{0.8 * a, 0.5};
    const Vec3 axisI = Vec3{1, 0.3, 0.5} / norm(Vec3{1, 0.3, 0.5}), axisJ = Vec3{0.2, 1, -0.4} / norm(Vec3{0.2, 1, -0.4});
    const Vec3 xi{0.5, 0.5, 0.5}, dir{0.03, 0.02, -0.01};
    const ClosestPoints far = closestPoints(gi, alignedWith(axisI), gj, alignedWith(axisJ), dir, dir);
    const Vec3 xj = xi + dir + (h - far.gap) * far.n;
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc),
                  {spheroid(0, xi, gi.a, gi.aspect, axisI, 1000, {0.01, -0.02, 0.004}, {3, -1, 2}),
                   spheroid(1, xj, gj.a, gj.aspect, axisJ, 1000, {-0.01, 0.005, 0.01}, {-2, 0, 4})});
    const ParticleStore& s = dem.particles();
    CHECK(norm(s.force[0] + s.force[1]) < 1e-14 * norm(s.force[0]));
    CHECK(norm(s.torque[0] + s.torque[1] + cross(s.x[0], s.force[0]) + cross(s.x[1], s.force[1])) < 1e-12 * norm(s.force[0]) * norm(xi));
    CHECK(norm(cross(s.force[0], far.n)) > 0.05 * norm(s.force[0]));
  }
  {
    // A prolate lying on its side (equator down) sliding along its axis without spin: the tangential
    // force of a sphere of radius 1 / sqrt(k1 k2) = c sliding at the same gap, whose torque about the
    // sphere's centre moves to the body's (the osculating centre c - a above it). The ball's
    // activation gap in its radii is the body's in its equatorial one.
    const double V = 0.01;
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    ParticleConfig half = pc;
    half.lubrication.activation = 0.25;
    DemSolver body(grid, c, resolved(c, pc), {spheroid(0, {0.5, 0.5, a + h}, a, 2, {1, 0, 0}, 1000, {V, 0, 0})});
    DemSolver ball(grid, c, resolved(c, half), {sphere(0, {0.5, 0.5, 2 * a + h}, 2 * a, 1000, {V, 0, 0})});
    const Vec3 F = body.particles().force[0], T = body.particles().torque[0];
    const Vec3 Fb = ball.particles().force[0], Tb = ball.particles().torque[0];
    CHECK(F.x == Approx(Fb.x).epsilon(1e-9));
    CHECK(F.x < 0);
    CHECK(T.y == Approx(Tb.y + a * Fb.x).epsilon(1e-9));  // (0, 0, c - a) x F moves the torque
  }
}

TEST_CASE("Shape: closest points of two spheroids against a search over a surface; overlaps separated by their depth", "[shape]")
{
  std::mt19937_64 rng(11);
  std::normal_distribution<double> u;
  auto unit = [&] {
    Vec3 v{u(rng), u(rng), u(rng)};
    return v / norm(v);
  };
  // Spheres: the closed form.
  {
    const Vec3 d{0.3, -0.1, 0.2};
    const ClosestPoints c = closestPoints({0.1, 1}, {}, {0.15, 1}, alignedWith(unit()), d, d);
    CHECK(c.gap == Approx(norm(d) - 0.25).margin(1e-15));
    CHECK(norm(c.n - d / norm(d)) < 1e-15);
  }
  for (int trial = 0; trial < 24; ++trial) {
    const Shape gi{1.0, trial % 3 == 0 ? 0.5 : 2.0}, gj{0.7, trial % 2 ? 3.0 : 1.0};
    const Quaternion qi = alignedWith(unit()), qj = alignedWith(unit());
    const Vec3 dir = unit();
    // Separated by 0.05-0.5 along dir beyond touching: find the touching distance first.
    const ClosestPoints touch0 = closestPoints(gi, qi, gj, qj, 10.0 * dir, dir);
    const double clearance = trial < 16 ? 0.05 + 0.03 * trial : -0.02;  // the last eight overlap
    const Vec3 d = 10.0 * dir + (clearance - touch0.gap) * touch0.n;
    const ClosestPoints c = closestPoints(gi, qi, gj, qj, d, d);
    INFO("trial " << trial << " gap " << c.gap);
    // The points are on their surfaces, with normals n and -n, and apart by gap along n.
    CHECK(gi.distance(toBody(qi, c.pI)) == Approx(0).margin(1e-10));
    CHECK(gj.distance(toBody(qj, c.pJ)) == Approx(0).margin(1e-10));
    const Vec3 sep = (d + c.pJ) - c.pI;
    CHECK(norm(sep - c.gap * c.n) < 1e-9);
    if (c.gap > 0) {
      // Brute force: the nearest point of body j's surface to body i (exact distance), refined.
      double best = HUGE_VAL, bt = 0, bp = 0;
      auto dist = [&](double t, double p) {
        const Vec3 body{gj.a * std::sin(t) * std::cos(p), gj.a * std::sin(t) * std::sin(p), gj.c() * std::cos(t)};
        return gi.distance(toBody(qi, d + toSpace(qj, body)));
      };
      for (int i = 0; i <= 200; ++i)
        for (int j = 0; j < 200; ++j) {
          const double t = M_PI * i / 200, p = 2 * M_PI * j / 200, v = dist(t, p);
          if (v < best) best = v, bt = t, bp = p;
        }
      for (double step = M_PI / 200; step > 1e-12; step *= 0.5)
        for (int it = 0; it < 4; ++it)
          for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b) {
              const double v = dist(bt + a * step, bp + b * step);
              if (v < best) best = v, bt += a * step, bp += b * step;
            }
      CHECK(c.gap == Approx(best).margin(1e-8));
    } else {
      // Moved apart along n by the depth, the two just touch.
      const ClosestPoints t = closestPoints(gi, qi, gj, qj, d - c.gap * c.n, c.n);
      CHECK(t.gap == Approx(0).margin(1e-10));
      CHECK(c.gap == Approx(-0.02).margin(1e-9));
    }
  }
}

TEST_CASE("DEM spheroids: an oblique, spinning, frictional collision conserves momentum and angular momentum; pole to pole bounces with e", "[shape][dem]")
{
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  c.gravity = {0, 0, 0};
  const double a = 0.02;
  auto body = [&](std::int64_t id, Vec3 x, double aspect, Vec3 axis, Vec3 v, Vec3 w = {}) {
    return spheroid(id, x, a, aspect, axis, 2000, v, w);
  };
  {
    ParticleConfig pc = contactConfig(1e-3, 0.8, 0.4);
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc),
                  {body(1, {0.45, 0.5, 0.5}, 2.5, {1, 1, 0.3}, {0.3, 0.02, -0.01}, {5, -10, 20}),
                   body(2, {0.55, 0.51, 0.505}, 0.5, {0.3, 0, 1}, {-0.2, 0, 0.01}, {-8, 3, 0})});
    const ParticleStore& s = dem.particles();
    auto momenta = [&](Vec3& P, Vec3& L) {
      P = L = Vec3{};
      for (std::size_t i = 0; i < s.nOwned; ++i) {
        const Vec3 b = toBody(s.q[i], s.w[i]), k = s.invInertiaBody[i];
        P += s.mass[i] * s.v[i];
        L += cross(s.x[i], s.mass[i] * s.v[i]) + toSpace(s.q[i], Vec3{b.x / k.x, b.y / k.y, b.z / k.z});
      }
    };
    Vec3 P0, L0, P, L;
    momenta(P0, L0);
    const double E0 = dem.diagnostics().kineticEnergy;
    long contactSteps = 0;
    for (int step = 0; step < 6000; ++step) {  // meet near 0.08 s
      dem.advance(0, 1e-3 / 50);
      contactSteps += dem.diagnostics().contacts;
    }
    momenta(P, L);
    CHECK(contactSteps > 20);
    CHECK(norm(P - P0) < 1e-13 * norm(P0));
    CHECK(norm(L - L0) < 1e-11 * norm(L0));
    CHECK(dem.diagnostics().kineticEnergy < E0);
  }
  {
    // Pole to pole along x, axes aligned: a sphere's central impact, e of the law.
    const double e = 0.7;
    ParticleConfig pc = contactConfig(1e-3, e, 0.3);
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc),
                  {body(1, {0.4, 0.5, 0.5}, 2, {1, 0, 0}, {0.5, 0, 0}), body(2, {0.6, 0.5, 0.5}, 2, {1, 0, 0}, {-0.5, 0, 0})});
    for (int step = 0; step < 8000; ++step) dem.advance(0, 1e-3 / 50);  // meet at 0.12 s, apart by 0.16 s
    const ParticleStore& s = dem.particles();
    CHECK((s.v[1].x - s.v[0].x) / 1.0 == Approx(e).epsilon(0.02));
    CHECK(norm(s.w[0]) + norm(s.w[1]) < 1e-9);
  }
}

TEST_CASE("Collapse monitor: the front and the column height reach a spheroid's surface, not its equatorial radius", "[shape]")
{
  // A prolate (a = 1 cm, c = 2 cm) lying along x at the front, one standing at the back wall, and a
  // sphere of 1 cm between them.
  Config c = boxConfig({0, 0, 0}, {1, 1, 1}, {4, 4, 4});
  c.gravity = {0, 0, 0};
  const double a = 0.01;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, contactConfig(1e-3, 0.9, 0.3)),
                {spheroid(0, {0.5, 0.5, 0.2}, a, 2, {1, 0, 0}, 2000), spheroid(1, {0.02, 0.5, 0.3}, a, 2, {0, 0, 1}, 2000),
                 sphere(2, {0.3, 0.5, 0.05}, a, 2000)});
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vp_test_collapse_shapes";
  std::filesystem::create_directories(dir);
  CollapseConfig cfg;
  cfg.on = true;
  const CollapseState m = CollapseMonitor(grid, cfg, dir.string()).measure(dem.particles());
  CHECK(m.front == Approx(0.5 + 2 * a).epsilon(1e-12));
  // Within two mean (equal-volume) diameters of the back wall: the standing prolate's top.
  CHECK(m.heightBack == Approx(0.3 + 2 * a).epsilon(1e-12));
  std::filesystem::remove_all(dir);
}
