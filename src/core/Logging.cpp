#include "vp/core/Logging.hpp"
#include "vp/core/Error.hpp"

namespace vp {

PetscLogStage logStage(Stage s)
{
  static PetscLogStage stages[static_cast<int>(Stage::Count)];
  static bool registered = false;
  if (!registered) {
    const char* names[] = {"Advection", "Diffusion", "Pressure", "Penalization", "HydroForce", "DEM", "Exchange", "IO"};
    for (int i = 0; i < static_cast<int>(Stage::Count); ++i) VP_CALL(PetscLogStageRegister(names[i], &stages[i]));
    registered = true;
  }
  return stages[static_cast<int>(s)];
}

} // namespace vp
