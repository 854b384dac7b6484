#pragma once
// One PetscLogStage per phase of a time step, so that -log_view reads like the algorithm.
#include <mpi.h>
#include <petsclog.h>

namespace vp {

enum class Stage { Advection, Diffusion, Pressure, Penalization, HydroForce, DEM, Exchange, IO, Health, Count };

// The stage handle (registered on first use).
PetscLogStage logStage(Stage s);
const char* stageName(Stage s);

// Wall-clock seconds spent in each stage on this rank since the start (or the last reset):
// the run summary and the benchmarks read them without parsing -log_view.
double stageSeconds(Stage s);
void resetStageSeconds();
void addStageSeconds(Stage s, double seconds);

class StageScope {
public:
  explicit StageScope(Stage s) : stage_(s), start_(MPI_Wtime()) { PetscLogStagePush(logStage(s)); }
  ~StageScope()
  {
    PetscLogStagePop();
    addStageSeconds(stage_, MPI_Wtime() - start_);
  }
  StageScope(const StageScope&) = delete;
  StageScope& operator=(const StageScope&) = delete;

private:
  Stage stage_;
  double start_;
};

} // namespace vp
