#pragma once
// What ends a run early, checked once per step with one collective reduction (docs/robustness.md):
// health checks (non-finite flow or particles, a particle outside a wall-bounded box, a CFL beyond
// -health_cfl_max with a fixed -time_dt, a contact overlap beyond -health_overlap_max) and stop
// requests (SIGTERM/SIGINT, -time_wall_limit).
#include "vp/core/Config.hpp"
#include "vp/fluid/Operators.hpp"
#include "vp/particles/DemSolver.hpp"
#include <mpi.h>
#include <string>

namespace vp {

// SIGTERM and SIGINT set a flag read at the next step boundary instead of killing the run.
void installStopSignals();

struct StepVerdict {
  std::string problem;  // a failed health check (the same text on every rank), "" if healthy
  int signal = 0;       // a stop signal received by any rank
  bool wallLimit = false;
};

class RunGuard {
public:
  RunGuard(MPI_Comm comm, const Config& cfg) : comm_(comm), cfg_(cfg) {}
  // Collective, after a step of size dt. elapsed: wall time of the run so far; lastStep: of the
  // last step [s].
  StepVerdict check(double dt, const ops::FieldStats& flow, DemSolver* dem, double elapsed, double lastStep);

private:
  // This rank's first problem, "" if none.
  std::string localProblem(double dt, const ops::FieldStats& flow, DemSolver* dem) const;
  MPI_Comm comm_;
  const Config& cfg_;
};

} // namespace vp
