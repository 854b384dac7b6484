#pragma once
// One PetscLogStage per phase of a time step, so that -log_view reads like the algorithm.
#include <petsclog.h>

namespace vp {

enum class Stage { Advection, Diffusion, Pressure, Penalization, HydroForce, DEM, Exchange, IO, Count };

// The stage handle (registered on first use).
PetscLogStage logStage(Stage s);

class StageScope {
public:
  explicit StageScope(Stage s) { PetscLogStagePush(logStage(s)); }
  ~StageScope() { PetscLogStagePop(); }
  StageScope(const StageScope&) = delete;
  StageScope& operator=(const StageScope&) = delete;
};

} // namespace vp
