#include "vp/core/Logging.hpp"
#include "vp/core/Error.hpp"

namespace vp {

namespace {
constexpr int kStages = static_cast<int>(Stage::Count);
const char* const kNames[kStages] = {"Advection", "Diffusion", "Pressure", "Penalization", "HydroForce", "DEM", "Exchange", "IO", "Health"};
double seconds[kStages] = {};
} // namespace

const char* stageName(Stage s) { return kNames[static_cast<int>(s)]; }

PetscLogStage logStage(Stage s)
{
  static PetscLogStage stages[kStages];
  static bool registered = false;
  if (!registered) {
    for (int i = 0; i < kStages; ++i) VP_CALL(PetscLogStageRegister(kNames[i], &stages[i]));
    registered = true;
  }
  return stages[static_cast<int>(s)];
}

double stageSeconds(Stage s) { return seconds[static_cast<int>(s)]; }

void resetStageSeconds()
{
  for (double& t : seconds) t = 0;
}

void addStageSeconds(Stage s, double dt) { seconds[static_cast<int>(s)] += dt; }

} // namespace vp
