#pragma once
// Basic lubrication correction model (BLCM): leading-order squeeze force between two spheres of
// radii a_i, a_j (or a sphere and a wall) at gap h, with the reduced radius R:
//   F_i = 6 pi mu R^2 (dh/dt) / h  n        (= -6 pi mu R^2 U_n / h along n, U_n approach speed)
// Squeeze only: no tangential force and no torque. Raw model at s.gap (no activation).
#include "vp/interactions/Lubrication.hpp"

namespace vp {

PairForce blcmForce(const PairState& s);

} // namespace vp
