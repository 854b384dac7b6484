#pragma once
// Shared by the step benchmarks: timed steps after a warm-up, and per-stage times.
#include "vp/Simulation.hpp"
#include "vp/core/Logging.hpp"
#include <initializer_list>
#include <petscsys.h>

namespace vp::bench {

// Mean wall seconds per step over `steps` steps after `warmup` untimed ones; the stage clocks
// (vp::stageSeconds) then cover the timed steps only.
inline double timeSteps(Simulation& sim, int warmup, int steps)
{
  for (int s = 0; s < warmup; ++s) sim.advance(sim.nextDt());
  MPI_Barrier(sim.grid().comm());
  resetStageSeconds();
  const double t0 = MPI_Wtime();
  for (int s = 0; s < steps; ++s) sim.advance(sim.nextDt());
  MPI_Barrier(sim.grid().comm());
  return (MPI_Wtime() - t0) / steps;
}

// Prints ",<seconds per step>" of the slowest rank for each stage.
inline void printStages(MPI_Comm comm, std::initializer_list<Stage> stages, int steps)
{
  for (Stage st : stages) {
    double mine = stageSeconds(st) / steps, slowest;
    MPI_Allreduce(&mine, &slowest, 1, MPI_DOUBLE, MPI_MAX, comm);
    PetscPrintf(comm, ",%.4f", slowest);
  }
}

} // namespace vp::bench
