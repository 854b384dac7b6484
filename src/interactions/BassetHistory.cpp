#include "vp/interactions/BassetHistory.hpp"
#include <cmath>

namespace vp {

BassetHistory::BassetHistory(double dt, double u0) : weight_(2 / std::sqrt(dt)), u_{u0}, w_{0, 1} {}

double BassetHistory::sumAt(std::size_t level) const
{
  // Increment k (u_k -> u_{k+1}) seen from t_level has weight w_{level - k}.
  double sum = 0;
  for (std::size_t k = 0; k + 1 < u_.size() && k < level; ++k) sum += (u_[k + 1] - u_[k]) * w_[level - k];
  return sum;
}

double BassetHistory::lagged() const { return weight_ * sumAt(u_.size()); }

void BassetHistory::push(double u)
{
  u_.push_back(u);
  const double j = double(w_.size());
  w_.push_back(1 / (std::sqrt(j) + std::sqrt(j - 1))); // = sqrt(j) - sqrt(j-1) without cancellation
}

double BassetHistory::integral() const { return weight_ * sumAt(u_.size() - 1); }

} // namespace vp
