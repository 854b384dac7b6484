#pragma once
// Reads the lubrication options (vp/core/Options.hpp, listed by -help):
//   -lub_model none|blcm|llcm   -lub_activation eps_act | -lub_activation_cells n
//   -lub_saturation eps_sat   -lub_llcm_r0 R0
// Gaps are fractions of the radius (or cells); 0 for activation/saturation means "set by the caller"
// (LubricationParams::complete). Throws InputError naming the option and its valid range.
#include "vp/interactions/LubricationModel.hpp"

namespace vp {

LubricationParams readLubricationOptions();

} // namespace vp
