#pragma once
// Basset history integral I(t_n) = int_0^{t_n} u'(s) / sqrt(t_n - s) ds on a uniform time grid,
// by product integration: u' is taken constant on each step and the kernel integrated exactly,
//   I_n = (2/sqrt(dt)) sum_{k<n} (u_{k+1} - u_k) (sqrt(n - k) - sqrt(n - k - 1)),
// which handles the 1/sqrt singularity without special treatment. The error is O(dt^1.5) for
// smooth u (dominated by the steps next to s = t). Cost O(n) per step.
#include <cstddef>
#include <vector>

namespace vp {

class BassetHistory {
public:
  BassetHistory(double dt, double u0);

  // I at the next level t_{n+1} is lagged() + newestWeight() * (u_{n+1} - u_n): the split lets an
  // integrator treat the newest increment implicitly.
  double lagged() const;
  double newestWeight() const { return weight_; }
  double last() const { return u_.back(); }

  void push(double u);       // commit u_{n+1}
  double integral() const;   // I at the last committed level

private:
  double sumAt(std::size_t level) const; // (sqrt(dt)/2) I at t_level from the committed increments

  double weight_;            // 2 / sqrt(dt)
  std::vector<double> u_;    // u_0 .. u_n
  std::vector<double> w_;    // w_j = sqrt(j) - sqrt(j - 1), j = 0 .. n + 1 (w_0 unused)
};

} // namespace vp
