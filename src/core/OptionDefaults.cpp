#include "vp/core/OptionDefaults.hpp"
#include "vp/core/Error.hpp"

namespace vp {

void setOptionDefault(const char* name, const char* value)
{
  PetscBool has;
  VP_CALL(PetscOptionsHasName(nullptr, nullptr, name, &has));
  if (!has) VP_CALL(PetscOptionsSetValue(nullptr, name, value));
}

} // namespace vp
