#pragma once
// Owns everything of a run: grid, fluid, particles, outputs. The constructor builds the solvers
// from a validated RunConfig and writes nothing; run() opens the outputs (run.json first), steps
// ("advance, record, output if due, checkpoint if due") to -time_final or -time_max_steps unless a
// health check fails or a stop is requested, and ends with a final snapshot, a checkpoint when one
// is configured or the stop was early, the stage timings and the run record's stop reason
// (docs/architecture.md, run lifecycle).
#include "vp/RunConfig.hpp"
#include "vp/RunGuard.hpp"
#include "vp/TimeStepControl.hpp"
#include "vp/coupling/Penalization.hpp"
#include "vp/fluid/AnalyticFlow.hpp"
#include "vp/fluid/Projection.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/io/Checkpoint.hpp"
#include "vp/io/FieldWriter.hpp"
#include "vp/io/Monitor.hpp"
#include "vp/io/ParticleWriter.hpp"
#include "vp/io/Schedule.hpp"
#include "vp/particles/DemSolver.hpp"
#include <memory>

namespace vp {

class Simulation {
public:
  Simulation(MPI_Comm comm, const RunConfig& cfg);
  ~Simulation();

  // The whole run; returns the exit status (0, or 128 + the signal that stopped it). A failed
  // health check throws RunFailure after writing a snapshot.
  int run();
  void advance(double dt);
  double nextDt() const;  // TimeStepControl::next from the current state

  double time() const { return time_; }
  int step() const { return step_; }
  const Grid& grid() const { return grid_; }
  Projection& fluid() { return *fluid_; }
  const StepStats& lastStepStats() const { return last_; }
  DemSolver* particles() { return dem_.get(); }
  Penalization* penalization() { return penalization_.get(); }

private:
  void openOutputs();
  void record();      // every monitor's row of the step just taken
  RunView view() const;  // what the monitors measure
  // A failed health check (snapshot: of the completed step) or step: summary and run.json, then
  // RunFailure (collective).
  [[noreturn]] void stopOnFailure(const std::string& problem, double loopStart, bool snapshot);
  void output();      // field and particle snapshot
  void checkpoint();  // checkpoint_<step>.h5 (docs/outputs.md)
  // Continues from -restart: fluid state, particles, counters, output lists.
  void restore(const CheckpointReader& cp);
  // Refuses (or with -restart_allow_changes warns about) set-up options that differ from the checkpoint's.
  void compareSetup(const CheckpointReader& cp) const;
  // The penalization force on each particle from the predicted velocity, and the hydrodynamic
  // forces once the velocity is projected (dt = 0: only the fluid momentum, initial state).
  void penalize();
  void hydroForce(double dt);
  void buildMask(double dt);  // chi, u_s, theta from the particles' current state
  void startWithShear(const AnalyticFlow& flow);  // -init_flow couette: the particles move with it
  void monitor(double dt) const;
  void printSetup() const;
  // The summary lines, the stage table and run.json's end (stop reason, figures).
  void finish(const std::string& stopReason);

  Config cfg_;
  Grid grid_;
  ParticleConfig particleCfg_;
  CollapseConfig collapseCfg_;
  RheologyConfig rheologyCfg_;
  TimeStepControl stepControl_;
  std::unique_ptr<Projection> fluid_;
  std::unique_ptr<FieldWriter> fields_;
  std::unique_ptr<DemSolver> dem_;                 // when there are particles
  std::unique_ptr<Penalization> penalization_;     // particles in a fluid
  std::unique_ptr<LubricationPatches> patches_;    // -lub_coupling replace
  std::vector<double> hydroSums_;
  std::unique_ptr<ParticleWriter> particleWriter_;
  // The time series, tracked particles (with particles), probes (-probe), the collapse monitor
  // (-collapse_monitor), the rheology monitor (-rheology_monitor): each records the same steps (Monitor.hpp).
  std::vector<std::unique_ptr<Monitor>> monitors_;
  std::unique_ptr<CheckpointWriter> checkpoints_;
  std::unique_ptr<RunState> restart_;              // the checkpoint's run state, until the outputs resume it
  Schedule snapshots_, checkpointSchedule_;
  RunGuard guard_;
  double loopWall_ = 0;                            // wall time of the stepping loop
  double time_ = 0;
  double penalizationFloor_ = 0;                   // the largest floor of lambda so far (buildMask)
  int step_ = 0;
  int firstStep_ = 0;       // step and time this run started from (0 unless restarted)
  int recordedStep_ = -1;   // last step written to the time series (-series_every)
  double firstTime_ = 0;
  long particlesAtStart_ = 0;
  StepStats last_;
  double wallStart_ = 0, wallLastStep_ = 0;
  long pressureIterationsTotal_ = 0;
};

} // namespace vp
