#include "harada/WallAddedMass.hpp"
#include <cmath>

namespace vp {

AddedMassCoefficient wallAddedMass(double eps)
{
  // Lengths in units of a; carry df_k/deps alongside f_k for the exact derivative.
  const double f0 = 2 * (1 + eps);
  double f = f0, df = 2;
  double product = 1 / (f * f * f), dLogProduct = -3 * df / f; // prod (1/f_k)^3 and d ln(prod)/deps
  double sum = product, dsum = product * dLogProduct;
  // Near contact the ratio of successive terms tends to (1 + sqrt(2 eps))^-3; the cap only binds
  // for eps below about 1e-12, far inside any roughness gap.
  for (int k = 1; k < 10000000 && product > 1e-16 * sum; ++k) {
    df = 2 + df / (f * f);
    f = f0 - 1 / f;
    const double cube = 1 / (f * f * f);
    product *= cube;
    dLogProduct += -3 * df / f;
    sum += product;
    dsum += product * dLogProduct;
  }
  return {1 + 3 * sum, 3 * dsum};
}

} // namespace vp
