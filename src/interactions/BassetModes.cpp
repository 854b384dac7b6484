#include "vp/interactions/BassetModes.hpp"
#include <cmath>

namespace vp {

namespace {

constexpr double kX0 = -5.5;  // x of the slowest mode: tau = e^11 s, about 17 hours

double tau(int m) { return std::exp(-2 * (kX0 + m)); }
double weight(int m) { return 2 / std::sqrt(M_PI) * std::exp(kX0 + m); }

} // namespace

BassetKernel::BassetKernel(double dt)
{
  for (int m = 0; m < kBassetModes; ++m) {
    const double r = dt / tau(m);
    decay_[m] = std::exp(-r);
    gain_[m] = r > 0 ? -std::expm1(-r) / r : 1;  // (tau/dt)(1 - e^{-dt/tau})
    newest_ += weight(m) * gain_[m];
  }
}

void BassetKernel::advance(BassetModes& z, const Vec3& du) const
{
  for (int m = 0; m < kBassetModes; ++m) z[m] = decay_[m] * z[m] + gain_[m] * du;
}

Vec3 BassetKernel::lagged(const BassetModes& z) const
{
  Vec3 sum;
  for (int m = 0; m < kBassetModes; ++m) sum += (weight(m) * decay_[m]) * z[m];
  return sum;
}

Vec3 BassetKernel::integral(const BassetModes& z)
{
  Vec3 sum;
  for (int m = 0; m < kBassetModes; ++m) sum += weight(m) * z[m];
  return sum;
}

double BassetKernel::kernel(double t)
{
  double sum = 0;
  for (int m = 0; m < kBassetModes; ++m) sum += weight(m) * std::exp(-t / tau(m));
  return sum;
}

} // namespace vp
