// The contact law as a kernel (contactForce) and through the DEM: tangential restitution against
// the exact linear-spring result, the lubrication hand-off (a lubricated rebound does not depend
// on the contact time), the lubrication stability bound, the free-slip wall rule, and the rolling
// resistance (kernel and a sphere rolling to rest on a floor).
#include "../support/DemFixtures.hpp"
#include "vp/core/Error.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using namespace vp::test;

TEST_CASE("contactForce: spring-dashpot, tangential spring, Coulomb cap", "[contact]")
{
  ContactCoefficients c;
  c.kn = 1000;
  c.gn = 2;
  c.kt = 300;
  c.gt = 0.5;
  c.mu = 0.4;
  const Vec3 n{0, 0, 1};
  SECTION("normal: k_n delta - gamma_n v_n, no tangential force without tangential motion")
  {
    Vec3 spring;
    const ContactForce f = contactForce(n, 1e-3, {0, 0, -0.1}, c, spring, 1e-4);
    CHECK(f.normal.z == Approx(1000 * 1e-3 + 2 * 0.1).epsilon(1e-15));
    CHECK(norm(f.tangential) == 0);
  }
  SECTION("sticking: the spring grows by v_t dt and resists with k_t s + gamma_t v_t")
  {
    Vec3 spring{1e-5, 0, 0};
    const ContactForce f = contactForce(n, 1e-3, {0.01, 0, 0}, c, spring, 1e-4);
    CHECK(spring.x == Approx(1e-5 + 0.01 * 1e-4).epsilon(1e-15));
    CHECK(f.tangential.x == Approx(-(300 * spring.x + 0.5 * 0.01)).epsilon(1e-15));
  }
  SECTION("sliding: the force is capped at mu |F_n| and the spring reset to give exactly it")
  {
    Vec3 spring{1e-3, 0, 0};
    const ContactForce f = contactForce(n, 1e-3, {0.5, 0, 0}, c, spring, 1e-4);
    const double cap = 0.4 * 1000 * 1e-3;
    CHECK(norm(f.tangential) == Approx(cap).epsilon(1e-14));
    CHECK(f.tangential.x < 0);
    CHECK(-(300 * spring.x + 0.5 * 0.5) == Approx(f.tangential.x).epsilon(1e-14));
  }
  SECTION("the old spring is brought onto the new tangent plane")
  {
    Vec3 spring{1e-5, 0, 1e-6};
    contactForce(n, 1e-3, {}, c, spring, 1e-4);
    CHECK(spring.z == 0);
    CHECK(spring.x == 1e-5);
  }
}

TEST_CASE("contactForce: the critical load model, frictionless below F_CL and Coulomb above", "[contact]")
{
  ContactCoefficients c;
  c.kn = 1000;
  c.kt = 300;
  c.mu = 0.5;
  c.criticalLoad = 0.5;  // N
  const Vec3 n{0, 0, 1}, vc{0.2, 0, 0};
  Vec3 spring{1e-4, 0, 0};
  // 1e-4 m deep: F_n = 0.1 N, below the critical load: no tangential force, the spring dropped.
  ContactForce f = contactForce(n, 1e-4, vc, c, spring, 1e-3);
  CHECK(f.normal.z == Approx(0.1));
  CHECK(norm(f.tangential) == 0);
  CHECK(norm(spring) == 0);
  // 1e-3 m deep: F_n = 1 N, above it: the spring stretches by v_t dt, the force -k_t s is below the cap.
  f = contactForce(n, 1e-3, vc, c, spring, 1e-3);
  CHECK(f.tangential.x == Approx(-300 * 2e-4));
  // Sliding: capped at mu F_n as without the model.
  f = contactForce(n, 1e-3, {20, 0, 0}, c, spring, 1e-3);
  CHECK(norm(f.tangential) == Approx(0.5 * 1.0));
  // Without the model (0) friction acts at any load: 0.1 N carries 0.03 N (cap 0.05 N).
  c.criticalLoad = 0;
  spring = Vec3{};
  f = contactForce(n, 1e-4, {0.1, 0, 0}, c, spring, 1e-3);
  CHECK(f.tangential.x == Approx(-300 * 1e-4));
}

TEST_CASE("rollingTorque: against the relative rolling, capped so that it cannot reverse it", "[contact]")
{
  const Vec3 n{0, 0, 1};
  const double load = 2.0, muR = 0.1, radius = 1e-3, invI = 1e8, dt = 1e-5;
  // Rolling about y plus a twist about n: only the rolling part is resisted.
  const Vec3 t = rollingTorque(n, {0, 50, 7}, load, muR, radius, 0, invI, dt);
  CHECK(t.x == 0);
  CHECK(t.z == 0);
  CHECK(t.y == Approx(-muR * radius * load).epsilon(1e-14));
  // A nearly stopped rolling: the torque halves it within the step, no more.
  const Vec3 slow = rollingTorque(n, {0, 0.05, 0}, load, muR, radius, 0, invI, dt);
  CHECK(slow.y == Approx(-0.5 * 0.05 / (dt * invI)).epsilon(1e-14));
  CHECK(norm(rollingTorque(n, {0, 50, 0}, load, 0, radius, 0, invI, dt)) == 0);
}

namespace {

// A sphere (a = 1 mm) set rolling at v0 along a floor under gravity, DEM only, for `time`: the
// distance it rolls before it stops (|v| < 1 % of v0; NaN if it does not), its largest speed over
// the second half of the run (a chattering torque would show here), and its final speed.
struct Roll {
  double distance, speedLate, speed;
};
Roll rollOut(double muR, double v0, double time)
{
  Config c = boxConfig({0, 0, 0}, {0.1, 0.01, 0.01}, {4, 4, 4});
  c.gravity = {0, 0, -9.81};
  ParticleConfig pc = contactConfig(2e-4, 0.3, 0.5);
  pc.contact.rollingFriction = muR;
  const double a = 1e-3;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  // Resting on the floor, spinning as it rolls (w_y = v0 / a): no slip from the start.
  DemSolver dem(grid, c, resolved(c, pc), {sphere(0, {0.01, 0.005, a}, a, 2500, {v0, 0, 0}, {0, v0 / a, 0})});
  const ParticleStore& s = dem.particles();
  const double dt = 4e-6;
  Roll r{NAN, 0, 0};
  for (double t = 0; t < time; t += dt) {
    dem.advance(t, dt);
    if (std::isnan(r.distance) && std::fabs(s.v[0].x) < 0.01 * v0) r.distance = s.x[0].x - 0.01;
    if (t > 0.5 * time) r.speedLate = std::max(r.speedLate, norm(s.v[0]));
  }
  r.speed = s.v[0].x;
  return r;
}

} // namespace

TEST_CASE("Rolling resistance: a sphere rolling on a floor decelerates at (5/7) mu_r g", "[contact][dem]")
{
  // The torque mu_r a m g against the rolling, with the rolling constraint v = w a, decelerates the
  // sphere at mu_r g / (1 + I / (m a^2)) = (5/7) mu_r g: it stops after v0^2 / (2 (5/7) mu_r g).
  const double v0 = 0.05, g = 9.81;
  for (double muR : {0.05, 0.2}) {
    const Roll r = rollOut(muR, v0, 1.0);
    const double expect = v0 * v0 / (2 * 5.0 / 7.0 * muR * g);
    INFO("mu_r = " << muR << ": rolled " << r.distance << " m, expected " << expect << "; largest speed late "
                    << r.speedLate << " m/s");
    CHECK(r.distance == Approx(expect).epsilon(0.01));
    CHECK(r.speedLate < 1e-6 * v0);  // at rest: the capped torque does not chatter
  }
  // Without it the sphere keeps rolling.
  const Roll free = rollOut(0, v0, 0.05);
  CHECK(free.speed > 0.99 * v0);
}

namespace {

// A sphere without spin hits the wall z = 0 obliquely; returns (tangential contact-point velocity
// out) / (tangential in), i.e. -Psi_2 / Psi_in in the sticking regime.
double tangentialRecoil(double xiT, double psiIn)
{
  Config c = boxConfig({0, 0, 0}, {0.2, 0.1, 0.1}, {4, 4, 4});
  ParticleConfig pc = contactConfig(1e-3, 0.9, 1e3);  // friction large: the contact point sticks
  pc.contact.restitutionT = xiT;
  const double a = 0.005, vn = 0.1;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), {sphere(0, {0.02, 0.05, a + 1e-6}, a, 2500, {psiIn * vn, 0, -vn})});
  ParticleStore& s = dem.particles();
  const double dt = 1e-3 / 2000;
  bool touched = false;
  for (int step = 0; step < 100000; ++step) {
    dem.advance(0, dt);
    const bool inContact = s.x[0].z < a;
    touched |= inContact;
    if (touched && !inContact) break;
  }
  return (s.v[0].x - a * s.w[0].y) / (psiIn * vn);  // V_C = U + Omega x (-a e_z)
}

} // namespace

TEST_CASE("Tangential restitution: a sticking contact point reverses with -xi_t (exact linear spring)", "[contact][dem]")
{
  // With k_t, gamma_t from xi_t and the tangential mass (2/7) m, the contact point is a damped
  // oscillator with the normal contact's duration: after t_c its velocity is -xi_t times the
  // incoming one.
  for (double xiT : {0.1, 0.5, 0.9}) {
    const double r = tangentialRecoil(xiT, 0.5);
    INFO("xi_t = " << xiT << ": V_t,out / V_t,in = " << r);
    CHECK(r == Approx(-xiT).margin(0.01));
  }
}

namespace {

// St 152 steel sphere (a = 1.5 mm, U = 0.585 m/s) driven onto a wall through an LLCM film, DEM
// only: the rebound velocity over the impact speed.
double lubricatedRebound(double tc)
{
  Config c = boxConfig({0, 0, 0}, {0.02, 0.02, 0.04}, {4, 4, 8});
  const double a = 1.5e-3, rhoP = 7800, u = 0.585;
  c.fluid.mu = rhoP * u * 2 * a / (9 * 152);
  ParticleConfig pc = lubricatedConfig(tc, 0.97, 2e-4, LubModel::Llcm, 0.1);
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  DemSolver dem(grid, c, resolved(c, pc), {sphere(0, {0.01, 0.01, a * 1.1}, a, rhoP, {0, 0, -u})});
  const ParticleStore& s = dem.particles();
  const double dt = 1e-7;  // 50 sub-steps in the shortest contact
  double vmax = 0;
  for (double t = 0; t < 3 * tc + 1e-3; t += dt) {
    dem.advance(t, dt);
    vmax = std::max(vmax, s.v[0].z);
  }
  return vmax / u;
}

} // namespace

TEST_CASE("Hand-off: a lubricated rebound does not depend on the contact time", "[contact][lub][dem]")
{
  // Before the hand-off the saturated lubrication acted through the contact: e = 0.90 at
  // t_c = 1e-5 s, 0.09 at 1.3e-3 s.
  const double base = lubricatedRebound(1e-5);
  INFO("e(t_c = 1e-5 s) = " << base);
  CHECK(base > 0.85);
  CHECK(base < 0.97);  // the film costs something on the way in and out
  for (double factor : {0.5, 2.0, 100.0}) {
    const double e = lubricatedRebound(factor * 1e-5);
    INFO("t_c x " << factor << ": e = " << e);
    CHECK(std::fabs(e / base - 1) < 0.02);
  }
}

TEST_CASE("The saturated lubrication dashpot bounds the DEM sub-step", "[contact][lub][dem]")
{
  Config c = boxConfig({0, 0, 0}, {0.01, 0.01, 0.01}, {2, 2, 2});
  c.fluid.mu = 0.3;
  ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 5e-4, LubModel::Blcm, 0.1);
  const double a = 1e-3, m = 1000 * 4.0 / 3.0 * M_PI * a * a * a;
  const double resistance = 6 * M_PI * 0.3 * a * (1 / 1e-3 - 1 / 0.1);  // wall, saturated at eps 1e-3
  const double limit = 0.5 * m / resistance;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  SECTION("the suggested DEM step respects it")
  {
    DemSolver dem(grid, c, resolved(c, pc), {sphere(1, {0.005, 0.005, 0.005}, a, 1000)});
    CHECK(dem.suggestedStep() == Approx(limit).epsilon(1e-9));
  }
  SECTION("beyond it, a sphere far from everything runs; at the saturation gap the run stops")
  {
    c.time.dt = 3 * limit;  // a fixed step beyond the bound: a warning, not an error
    DemSolver far(grid, c, resolved(c, pc), {sphere(1, {0.005, 0.005, 0.005}, a, 1000)});
    CHECK_NOTHROW(far.advance(0, 3 * limit));
    const Vec3 atSaturation{0.005, 0.005, a * (1 + 1.0001e-3)};
    DemSolver stable(grid, c, resolved(c, pc), {sphere(1, atSaturation, a, 1000)});
    CHECK_NOTHROW(stable.advance(0, 1.98 * limit));  // c dt / m = 0.99
    DemSolver unstable(grid, c, resolved(c, pc), {sphere(1, atSaturation, a, 1000)});
    CHECK_THROWS_WITH(unstable.advance(0, 3 * limit),
                      Catch::Contains("option -dem_substeps: the DEM sub-step") && Catch::Contains("raise -dem_substeps to at least 3"));
  }
}

TEST_CASE("A free-slip wall resists a squeeze four times less than a no-slip wall", "[contact][lub][dem]")
{
  // Quasi-steady approach under a constant force F: U = F / (c(eps) - c(eps_act)), c four times
  // smaller at a free-slip wall.
  auto speedAt = [](BcType floor) {
    Config c = boxConfig({0, 0, 0}, {0.01, 0.01, 0.01}, {2, 2, 2});
    c.bc.type[4] = floor;
    c.gravity = {0, 0, -9.81};
    c.fluid.mu = 0.3;
    ParticleConfig pc = lubricatedConfig(1e-3, 0.9, 2.5e-3, LubModel::Blcm, 0.1);
    const double a = 1e-3;
    Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
    DemSolver dem(grid, c, resolved(c, pc), {sphere(1, {0.005, 0.005, a * 1.09}, a, 1000)});
    const ParticleStore& s = dem.particles();
    for (int k = 0; k < 200000 && s.x[0].z - a > 0.02 * a; ++k) dem.advance(0, 1e-6);
    return -s.v[0].z;
  };
  const double noSlip = speedAt(BcType::Wall), slip = speedAt(BcType::Slip);
  INFO("approach speed at eps 0.02: no-slip " << noSlip << ", slip " << slip);
  CHECK(slip / noSlip == Approx(4).epsilon(0.01));
}
