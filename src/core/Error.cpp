#include "vp/core/Error.hpp"

namespace vp {

PetscFailure::PetscFailure(PetscErrorCode c, const char* file, int line)
  : std::runtime_error("PETSc error " + std::to_string(c) + " at " + file + ":" + std::to_string(line)),
    code(c)
{
}

} // namespace vp
