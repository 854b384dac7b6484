#pragma once
// Local lubrication correction model (LLCM, after Lambert, Weynans & Bergmann 2018): lubrication
// theory on the disk r < r0 of the local parabolic gap h(r) = h + r^2/(2R) between the two surfaces,
// with r0 = region * R (region = R0 in units of the reduced radius; R = a at a wall).
//   squeeze: Reynolds solution with p(r0) = 0:  F_i = F_blcm (1 - h/H0)^2,  H0 = h + r0^2/(2R)
//   shear:   O'Neill & Stewartson / Cooley & O'Neill inner solution (pressure mode cos(theta) and
//            Couette shear) integrated over the disk in closed form, see docs/lubrication.md:
//            J1 = ln(H0/h),  J3 = ln(H0/h) + h/H0 - 1,
//            W  = (s_i + s_j)/(2R) - u_i/a_i - u_j/a_j       (tangential, s = surface velocity)
//            P  = -(12/5) pi mu R^3 J3 W,   S = 2 pi mu R J1 (s_i - s_j)
//            F_i += -(1/a_i - 1/a_j) P - S
//            T_i  =  a_i n x (P/R - S),     T_j = -a_j n x (P/R + S)
// Raw model at s.gap (no activation); T_i + T_j = (a_i + a_j) n x F_i exactly.
// openEdge: the squeeze as the inner solution's pressure p = 3 mu R (dh/dt) / h(r)^2 integrated over
// the disk, F_blcm (1 - h/H0), its pressure at r0 left as it is: the force on a gap patch whose
// resolved force is taken out (-lub_coupling replace), where the flow outside the disk is resolved.
#include "vp/interactions/Lubrication.hpp"

namespace vp {

// part: Squeeze the normal force alone, Shear the tangential terms alone (Lubrication.hpp).
PairForce llcmForce(const PairState& s, double region, bool openEdge = false, LubPart part = LubPart::Both);

} // namespace vp
