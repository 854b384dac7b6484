#pragma once
// Added mass of a sphere moving normal to a plane wall, from the image series (Harada et al. 2001,
// docs/lubrication.md section 5): m' = (2/3) pi rho a^3 C(eps) with
//   C = 1 + 3 sum_{i>=0} prod_{k=0..i} (a/f_k)^3,   f_0 = 2a(1 + eps),  f_k = f_0 - a^2/f_{k-1}.
// f_k is the distance from the centre of the k-th image dipole. The cube is required for a
// dimensionless series (the seed text omits it); the first term is the classical 3/8 (a/l)^3 at
// centre distance l, and at contact C -> 1 + 3 (zeta(3) - 1) (added-mass coefficient 0.803).
namespace vp {

struct AddedMassCoefficient {
  double value;      // C(eps)
  double derivative; // dC/deps
};

// eps = h/a > 0. The series is summed until its terms fall below 1e-16 of the sum.
AddedMassCoefficient wallAddedMass(double eps);

} // namespace vp
