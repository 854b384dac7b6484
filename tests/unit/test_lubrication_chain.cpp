// Lubrication among many neighbours (-lub_integration implicit; docs/lubrication.md): N spheres in a
// line, lubrication only (BLCM), pushed together by end forces +-F. Quasi-statically every gap
// carries F, c(h) dh/dt = -F with c = 6 pi mu R*^2 (1/h - 1/h_act), so every gap follows
// ln(h/h0) - (h - h0)/h_act = -F t / (6 pi mu R*^2), whatever N and its place in the chain. At ten
// times the explicit update's stability limit (2 m*/c at the smallest gap reached) the implicit
// squeeze follows it within 1 %; the explicit update is refused there (it would diverge). The spheres
// are light (m*/c a millionth of the squeeze time) so that the chain is quasi-static from the start;
// h_act = 1.5 a keeps the lubrication between neighbours.
#include "../support/DemFixtures.hpp"
#include "vp/core/Error.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace vp;
using namespace vp::test;

namespace {

constexpr double a = 5e-4, rho = 250, mu = 10, h0 = 0.1 * a, hAct = 1.5 * a;  // neighbours only
const double Rstar2 = 0.25 * a * a, tau = 1e-3;  // the squeeze time 6 pi mu R*^2 / F
const double F = 6 * M_PI * mu * Rstar2 / tau;

double exactGap(double t)  // ln(h/h0) - (h - h0)/h_act = -t/tau, by Newton
{
  double h = h0 * std::exp(-t / tau);
  for (int k = 0; k < 50; ++k) h -= (std::log(h / h0) - (h - h0) / hAct + t / tau) / (1 / h - 1 / hAct);
  return h;
}

// The gaps of the chain at t = tau (the explicit step limit at the smallest gap times `limits`).
std::vector<double> chain(int n, bool implicitSqueeze, double limits)
{
  const double length = n * 2 * a + (n - 1) * h0, margin = 1.2 * hAct;
  Config c = boxConfig({0, 0, 0}, {length + 2 * margin, 6 * a, 6 * a}, {2, 1, 1});
  c.fluid.off = false;  // the end forces are held "resolved" forces (fhyd), as a coupled run's
  c.fluid.mu = mu;
  ParticleConfig pc = lubricatedConfig(1, 0.9, 0, LubModel::Blcm, hAct / a);
  pc.lubrication.saturation = 1e-3;
  pc.lubrication.implicitSqueeze = implicitSqueeze;
  pc.contact.hydro = ContactHydro::Keep;
  pc.implicitDrag = 0;
  std::vector<ParticleRecord> all;
  for (int k = 0; k < n; ++k) all.push_back(sphere(k, {margin + a + k * (2 * a + h0), 3 * a, 3 * a}, a, rho));
  const double mStar = 0.5 * rho * 4.0 / 3.0 * M_PI * a * a * a;
  const double cEnd = 6 * M_PI * mu * Rstar2 * (1 / exactGap(tau) - 1 / hAct);
  const double dt = limits * 2 * mStar / cEnd;
  Grid grid(PETSC_COMM_SELF, c.grid, c.bc);
  c.time.dt = dt;
  DemSolver dem(grid, c, resolved(c, pc), all);
  ParticleStore& s = dem.particles();
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    s.fhyd[i] = Vec3{};
    if (s.id[i] == 0) s.fhyd[i].x = F;
    if (s.id[i] == n - 1) s.fhyd[i].x = -F;
  }
  const int steps = static_cast<int>(std::lround(tau / dt));
  for (int k = 0; k < steps; ++k) dem.advance(k * dt, tau / steps);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < s.nOwned; ++i) x[s.id[i]] = s.x[i].x;
  std::vector<double> gaps;
  for (int k = 0; k + 1 < n; ++k) gaps.push_back(x[k + 1] - x[k] - 2 * a);
  return gaps;
}

void check(int n)
{
  const double exact = exactGap(tau);
  const std::vector<double> gaps = chain(n, true, 10);
  for (std::size_t k = 0; k < gaps.size(); ++k) {
    INFO("N " << n << ", gap " << k << ": h/a " << gaps[k] / a << " vs " << exact / a);
    CHECK(std::fabs(gaps[k] / exact - 1) < 0.01);
  }
  CHECK_THROWS_WITH(chain(n, false, 10), Catch::Contains("-dem_substeps") && Catch::Contains("unstable"));
}

} // namespace

TEST_CASE("Lubrication chain of 2 spheres: the implicit squeeze follows the exact gap at 10x the explicit limit", "[chain][chain2]") { check(2); }
TEST_CASE("Lubrication chain of 5 spheres: the implicit squeeze follows the exact gap at 10x the explicit limit", "[chain][chain5]") { check(5); }
TEST_CASE("Lubrication chain of 10 spheres: the implicit squeeze follows the exact gap at 10x the explicit limit", "[chain][chain10]") { check(10); }
