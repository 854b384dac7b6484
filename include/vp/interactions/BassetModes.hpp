#pragma once
// The Basset history integral I(t) = int u'(s) / sqrt(t - s) ds carried in a fixed number of
// exponential modes, so that a particle holds it in a few numbers instead of its velocity record
// (BassetHistory keeps the record). The kernel as a sum of exponentials:
//   1/sqrt(t) = (2/sqrt(pi)) int exp(-t e^{2x}) e^x dx  ~  sum_m w_m exp(-t / tau_m),
// the trapezoidal rule on x_m = x_0 + m (unit spacing): w_m = (2/sqrt(pi)) e^{x_m}, tau_m = e^{-2 x_m}.
// With 14 modes (x from -5.5 to 7.5) the sum is within 2.5 % of 1/sqrt(t) from 2e-7 s to 7 s
// (tests/unit/test_basset_modes.cpp); older velocity changes fade faster than 1/sqrt(t).
// Mode m holds z_m(t) = int exp(-(t - s) / tau_m) u'(s) ds. A step dt over which u' is constant
// (BassetHistory's product integration) is exact for each mode:
//   z_m <- exp(-dt/tau_m) z_m + (tau_m/dt) (1 - exp(-dt/tau_m)) du,      I = sum_m w_m z_m,
// so that I at the step's end is lagged(z) + newestWeight() du: an integrator can take du implicitly.
#include "vp/core/Vec3.hpp"
#include <array>

namespace vp {

constexpr int kBassetModes = 14;
using BassetModes = std::array<Vec3, kBassetModes>;  // z_m of the three velocity components

class BassetKernel {
public:
  explicit BassetKernel(double dt);  // the factors of a step dt

  // One step of dt whose velocity change du was spread evenly over it.
  void advance(BassetModes& z, const Vec3& du) const;
  // I at the end of the next step without its own change, and the weight of that change.
  Vec3 lagged(const BassetModes& z) const;
  double newestWeight() const { return newest_; }
  // I from the modes [m/s^(1/2)].
  static Vec3 integral(const BassetModes& z);
  // The sum of exponentials at t (the approximation of 1/sqrt(t)).
  static double kernel(double t);

private:
  std::array<double, kBassetModes> decay_{}, gain_{};
  double newest_ = 0;  // sum_m w_m gain_m
};

} // namespace vp
