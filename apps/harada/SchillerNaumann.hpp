#pragma once
// Steady drag of a sphere by Schiller & Naumann (Re < 1000):
//   C_d = 24/Re (1 + 0.15 Re^0.687),  F = -(1/2) rho C_d pi a^2 |U| U = -3 pi mu d U (1 + 0.15 Re^0.687)
#include <cmath>

namespace vp {

// Drag over the Stokes drag, f(Re) = 1 + 0.15 Re^0.687, so F = -3 pi mu d f(Re) U.
inline double schillerNaumannFactor(double re) { return 1 + 0.15 * std::pow(re, 0.687); }

inline double schillerNaumannDragCoefficient(double re) { return 24 / re * schillerNaumannFactor(re); }

} // namespace vp
