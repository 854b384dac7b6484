// The Basset history carried in exponential modes (interactions/BassetModes.hpp): the kernel
// against 1/sqrt(t), and the integral against the product integration over the whole velocity
// record (interactions/BassetHistory.hpp).
#include "vp/interactions/BassetHistory.hpp"
#include "vp/interactions/BassetModes.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

using namespace vp;

TEST_CASE("Basset modes: the sum of exponentials follows 1/sqrt(t) within 2.5 % from 2e-7 s to 7 s", "[basset]")
{
  double worst = 0, worstT = 0;
  for (double lt = std::log10(2e-7); lt <= std::log10(7.0); lt += 0.01) {
    const double t = std::pow(10.0, lt), err = std::fabs(BassetKernel::kernel(t) * std::sqrt(t) - 1);
    if (err > worst) worst = err, worstT = t;
  }
  INFO("largest relative error " << worst << " at t = " << worstT << " s");
  CHECK(worst < 0.025);
  // Within 3 % to 40 s; past the slowest mode (17 hours) an old velocity change is forgotten.
  CHECK(std::fabs(BassetKernel::kernel(40) * std::sqrt(40.0) - 1) < 0.03);
  CHECK(BassetKernel::kernel(1e6) * std::sqrt(1e6) < 1e-3);
}

TEST_CASE("Basset modes: the integral equals the product integration of the whole record", "[basset]")
{
  // A velocity reversal over 100 steps (a contact), then a slow drift: I(t) = int u'/sqrt(t - s) ds.
  const double dt = 1e-5;
  auto u = [](double t) { return t < 1e-3 ? -std::cos(M_PI * t / 1e-3) : 1 - 0.3 * (t - 1e-3) / 4e-3; };
  BassetHistory record(dt, u(0));
  BassetKernel kernel(dt);
  BassetModes modes{};
  double worst = 0, largest = 0;
  for (int n = 1; n <= 500; ++n) {
    const double du = u(n * dt) - u((n - 1) * dt);
    record.push(u(n * dt));
    kernel.advance(modes, {du, -2 * du, 0});
    const double exact = record.integral();
    const Vec3 I = BassetKernel::integral(modes);
    if (n == 250) {  // the split an integrator uses: the next step's integral is lagged + newest weight x du
      BassetModes next = modes;
      kernel.advance(next, {1e-3, 0, 0});
      CHECK(BassetKernel::integral(next).x == Approx(kernel.lagged(modes).x + kernel.newestWeight() * 1e-3).epsilon(1e-12));
    }
    largest = std::max(largest, std::fabs(exact));
    worst = std::max({worst, std::fabs(I.x - exact), std::fabs(I.y + 2 * exact)});
    CHECK(I.z == 0);
  }
  INFO("largest difference " << worst << " against the largest |I| " << largest);
  CHECK(largest > 20);  // 2 / sqrt(1 ms) for a unit reversal: the record is a real one
  CHECK(worst < 0.025 * largest);
}
