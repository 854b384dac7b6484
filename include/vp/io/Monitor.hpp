#pragma once
// A monitor measures the run as it goes and writes its own file: the time series (Diagnostics:
// diagnostics.csv), tracked particles (ParticleTracker: particle_<id>.csv), pressure probes
// (Probes: probes.csv), the granular collapse (CollapseMonitor: collapse.csv, deposit.csv). The
// Simulation keeps them in one list and calls each at the same points of the run (docs/extending.md,
// "A new diagnostic or monitor").
#include <string>

namespace vp {

class DemSolver;
class Projection;
struct StepStats;

// What the monitors see of the run: its state after the step just taken (or at its start).
struct RunView {
  int step = 0;
  double time = 0;
  double wallTime = 0;                 // since the run started [s]
  const Projection* fluid = nullptr;   // the flow (at rest with -fluid_off)
  const StepStats* solvers = nullptr;  // the last step's iteration counts
  const DemSolver* dem = nullptr;      // null without particles
};

class Monitor {
public:
  virtual ~Monitor() = default;
  // The initial state's row of a run that does not continue a checkpoint. Collective.
  virtual void start(const RunView& run) { record(run); }
  // A row after a time-series step (-series_every, the last step, a step that failed a check). Collective.
  virtual void record(const RunView& run) = 0;
  // Buffered rows to disk (at progress lines, checkpoints and the end).
  virtual void flush() {}
  // Non-empty: the run should end here, for this reason (the same on every rank). Collective.
  virtual std::string stopRequest() { return {}; }
  // At the end of the run (not after a failure). Collective.
  virtual void finish(const RunView& /*run*/) {}
};

} // namespace vp
