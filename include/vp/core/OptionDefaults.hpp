#pragma once
// Defaults for PETSc solver options that the user may override (e.g. -pressure_pc_type):
// written into the options database only when the user did not give the option.
namespace vp {

void setOptionDefault(const char* name, const char* value);

} // namespace vp
