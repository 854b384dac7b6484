#pragma once
// Reads the -contact_* options (vp/core/Options.hpp, listed by -help); the caller
// validates them with ContactConfig::validate once it knows whether the run has particles.
#include "vp/interactions/ContactConfig.hpp"

namespace vp {

ContactConfig readContactOptions();

} // namespace vp
