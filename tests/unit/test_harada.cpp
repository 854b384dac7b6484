// Harada point-particle model: its pieces (drag, image-series added mass, Basset quadrature,
// contact) and the seed falling sphere.
#include "vp/interactions/BassetHistory.hpp"
#include "harada/Harada.hpp"
#include "harada/SchillerNaumann.hpp"
#include "harada/WallAddedMass.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace vp;

namespace {

HaradaParams dragOnly()
{
  HaradaParams p;
  p.lubrication = p.addedMass = p.history = p.contact = false;
  return p;
}

// Error of the quadrature of int_0^1 u'(s)/sqrt(1-s) ds for u = s^2 (exact 8/3) with n steps.
double bassetError(int n)
{
  const double dt = 1.0 / n;
  BassetHistory b(dt, 0);
  for (int k = 1; k <= n; ++k) b.push(std::pow(k * dt, 2));
  return std::fabs(b.integral() - 8.0 / 3.0);
}

} // namespace

TEST_CASE("Schiller-Naumann drag coefficient", "[harada]")
{
  CHECK(schillerNaumannDragCoefficient(1) == Approx(24 * 1.15).epsilon(1e-14));
  CHECK(schillerNaumannDragCoefficient(100) == Approx(0.24 * (1 + 0.15 * std::pow(100, 0.687))).epsilon(1e-14));
}

TEST_CASE("Harada: drag and buoyant weight only give the seed terminal velocity 0.1462 m/s", "[harada]")
{
  HaradaParams p = dragOnly();
  p.dt = 1e-3;
  HaradaModel m(p, 100, 0); // far from the wall; lubrication and contact are off anyway
  while (m.time() < 3) m.step();
  const double terminal = -m.velocity();
  INFO("terminal velocity " << terminal);
  CHECK(terminal == Approx(0.1462).epsilon(5e-3));
  // The terminal state balances the weight exactly (independent of the step size).
  CHECK(m.forces().drag + m.forces().weight == Approx(0).margin(1e-12 * m.forces().drag));
}

TEST_CASE("Wall added mass: bulk value far away, 3/8 (a/l)^3 correction, 0.803 at contact", "[harada]")
{
  CHECK(wallAddedMass(1e4).value == Approx(1).epsilon(1e-12));
  for (double eps : {10.0, 100.0}) {
    const double l = 1 + eps; // centre distance in radii
    const double first = 3.0 / 8.0 / (l * l * l);
    CHECK((wallAddedMass(eps).value - 1) / first == Approx(1).epsilon(2 / std::pow(2 * l, 3)));
  }
  // At contact the images sit at f_k = (k+2)/(k+1) a: C = 1 + 3 (zeta(3) - 1).
  const double zeta3 = 1.2020569031595942;
  CHECK(0.5 * wallAddedMass(1e-6).value == Approx(0.5 * (1 + 3 * (zeta3 - 1))).epsilon(5e-3));
  // Exact derivative against central differences.
  for (double eps : {1e-3, 0.1, 2.0}) {
    const double d = 1e-6 * eps;
    const double fd = (wallAddedMass(eps + d).value - wallAddedMass(eps - d).value) / (2 * d);
    CHECK(wallAddedMass(eps).derivative == Approx(fd).epsilon(1e-6));
  }
}

TEST_CASE("Basset product quadrature: exact for linear u, order 1.5 for smooth u", "[harada]")
{
  BassetHistory linear(0.01, 0);
  for (int k = 1; k <= 100; ++k) linear.push(3 * k * 0.01);
  CHECK(linear.integral() == Approx(3 * 2 * 1.0).epsilon(1e-12)); // int_0^1 3/sqrt(1-s) ds = 6

  std::vector<double> orders;
  for (int n = 100; n <= 1600; n *= 2) orders.push_back(std::log2(bassetError(n) / bassetError(2 * n)));
  for (double q : orders) {
    INFO("observed order " << q);
    CHECK(q == Approx(1.5).margin(0.05));
  }
  // The implicit split used by the integrator equals the committed integral.
  BassetHistory b(0.01, 0);
  for (int k = 1; k <= 10; ++k) b.push(std::sin(0.1 * k));
  const double lagged = b.lagged() + b.newestWeight() * (std::sin(1.1) - b.last());
  b.push(std::sin(1.1));
  CHECK(lagged == Approx(b.integral()).epsilon(1e-14));
}

TEST_CASE("Harada: dry contact with the wall lasts t_c and returns the restitution", "[harada]")
{
  HaradaParams p = dragOnly();
  p.drag = false;
  p.contact = true;
  p.gravity = 0;
  p.dt = p.contactTime / 100;
  const double hCol = 2 * p.radius * p.roughness;
  const double v0 = -0.1;
  HaradaModel m(p, p.radius + hCol + 10 * p.dt * 0.1, v0); // reaches the contact after ~10 steps
  double start = -1, end = -1;
  while (end < 0) {
    const bool before = m.forces().contact != 0;
    m.step();
    const bool now = m.gap() < hCol;
    if (now && start < 0) start = m.time() - p.dt;
    if (!now && start >= 0 && !before) continue;
    if (!now && start >= 0) end = m.time() - p.dt;
  }
  INFO("contact time " << end - start << " restitution " << -m.velocity() / v0);
  // First-order stepping resolves contact start/end to one step: 1 % of t_c at 100 steps.
  CHECK(end - start == Approx(p.contactTime).epsilon(0.02));
  CHECK(-m.velocity() / v0 == Approx(p.restitution).epsilon(0.01));
}

TEST_CASE("Harada: the history window leaves the history force out from a contact to its gap", "[harada]")
{
  // A steel sphere (a = 1.5 mm) thrown at the wall in a viscous liquid, history and contact only: the
  // velocity reversal at the contact sets off a history force that slows the way out.
  HaradaParams p = dragOnly();
  p.drag = false;
  p.history = p.contact = true;
  p.gravity = 0;
  p.radius = 1.5e-3;
  p.particleDensity = 7800;
  p.fluidDensity = 935;
  p.viscosity = 0.04;
  p.contactTime = 1e-5;
  p.dt = p.contactTime / 40;
  const double window = p.radius / 8;  // d/16: a cell at d/dx 16
  // The speed as the gap opens past 2 windows, and whether the history force was zero inside the window.
  auto rebound = [&](bool history, double historyWindow, bool* zeroInside) {
    HaradaParams q = p;
    q.history = history;
    q.historyWindow = historyWindow;
    HaradaModel m(q, q.radius + 0.2 * q.radius, -0.4);
    bool touched = false, zero = true, seenOutside = false;
    while (m.time() < 0.02) {
      m.step();
      touched = touched || m.gap() < 2 * q.radius * q.roughness;
      if (touched && m.velocity() > 0 && m.gap() > 2 * q.radius * q.roughness) {
        if (m.gap() < 0.99 * window) zero = zero && m.forces().history == 0;
        if (m.gap() > 1.01 * window) seenOutside = seenOutside || m.forces().history != 0;
        if (m.gap() > 2 * window) break;
      }
    }
    if (zeroInside) *zeroInside = zero && seenOutside;
    return m.velocity();
  };
  bool zeroInside = false;
  const double none = rebound(false, 0, nullptr), full = rebound(true, 0, nullptr), windowed = rebound(true, window, &zeroInside);
  INFO("speed at 2 windows: no history " << none << ", history " << full << ", history out over the window " << windowed);
  CHECK(zeroInside);
  CHECK(full < windowed);
  CHECK(windowed < none);
  // Most of the history force's effect on the way out comes right after the reversal (1/sqrt(t));
  // the rest, after the window, still counts the reversal (the velocity history is kept).
  CHECK(windowed - full > 0.5 * (none - full));
  CHECK(none - windowed > 0.15 * (none - full));
}

TEST_CASE("Harada: quasi-steady lubrication approach U = F eps / (6 pi mu a)", "[harada]")
{
  // Weight against lubrication only. The approach decays exponentially (rate F / (6 pi mu a^2)),
  // so inertia shifts the balance by m F eps / (a (6 pi mu a)^2): 8 % at eps = 1e-2, 0.08 % at
  // eps = 1e-4, where the quasi-steady speed must hold to 1 %.
  HaradaParams p = dragOnly();
  p.lubrication = true;
  p.roughness = 1e-6; // saturation well below the measured gap
  p.dt = 1e-5;
  HaradaModel m(p, p.radius * 1.05, 0);
  const double F = (m.mass() - 2 * m.bulkAddedMass()) * -p.gravity;
  while (m.gap() > 1e-4 * p.radius) m.step();
  const double eps = m.gap() / p.radius;
  const double quasiSteady = F * eps / (6 * M_PI * p.viscosity * p.radius);
  INFO("eps " << eps << " U / U_quasi-steady " << -m.velocity() / quasiSteady);
  CHECK(-m.velocity() == Approx(quasiSteady).epsilon(1e-2));
}

TEST_CASE("Harada: the seed sphere (St 3.3) settles on the wall without rebound", "[harada]")
{
  HaradaParams p; // the seed case, every term on
  HaradaModel m(p, p.radius + 3 * 2 * p.radius, 0);
  double vMin = 0, vMaxAfter = 0;
  bool touched = false;
  while (m.time() < 1.2) {
    m.step();
    vMin = std::min(vMin, m.velocity());
    touched = touched || m.forces().contact != 0;
    if (touched) vMaxAfter = std::max(vMaxAfter, m.velocity());
  }
  INFO("peak fall speed " << -vMin << ", largest upward speed after contact " << vMaxAfter);
  CHECK(touched);
  CHECK(-vMin < 0.1462);                   // still accelerating / braked by the wall
  // No rebound (experiments: none below St ~ 10; e < 0.02 counts as none): lubrication is off in
  // contact (hand-off), the contact returns the little speed left at the roughness gap, and the
  // resistance there takes it at once.
  CHECK(vMaxAfter < 0.02 * -vMin);
  CHECK(m.gap() < 2 * p.radius * p.roughness);
}
