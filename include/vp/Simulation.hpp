#pragma once
// Owns everything of a run: grid, fluid, output. setUp happens in the constructor; advance() does
// one time step (docs/fluid.md and docs/coupling.md), run() steps to -time_final or -time_max_steps with output,
// diagnostics and progress lines.
#include "vp/core/Config.hpp"
#include "vp/coupling/Penalization.hpp"
#include "vp/fluid/Projection.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/io/Checkpoint.hpp"
#include "vp/io/CsvWriter.hpp"
#include "vp/io/FieldWriter.hpp"
#include "vp/io/ParticleTracker.hpp"
#include "vp/io/ParticleWriter.hpp"
#include "vp/particles/DemSolver.hpp"
#include <memory>

namespace vp {

class Simulation {
public:
  Simulation(MPI_Comm comm, const Config& cfg);
  ~Simulation();

  void run();
  void advance(double dt);
  double nextDt() const;  // from -time_dt, or CFL and -time_dt_max, clipped to -time_final

  double time() const { return time_; }
  int step() const { return step_; }
  const Grid& grid() const { return grid_; }
  Projection& fluid() { return *fluid_; }
  const StepStats& lastStepStats() const { return last_; }
  DemSolver* particles() { return dem_.get(); }
  Penalization* penalization() { return penalization_.get(); }

private:
  void output();
  void checkpoint();  // checkpoint_<step>.h5 (docs/outputs.md)
  // Continues from -restart: fluid state, particles, counters, output lists.
  void restore(const CheckpointReader& cp);
  FluidState fluidState() const;  // the vectors a checkpoint holds
  // The penalization force on each particle from the predicted velocity, and the hydrodynamic
  // forces once the velocity is projected (dt = 0: only the fluid momentum, initial state).
  void penalize();
  void hydroForce(double dt);
  void buildMask(double dt);  // chi, u_s, theta from the particles' current state
  double particleRate() const;  // max over particles of (|U_c| + |Omega| a) / h_c (collective)
  void monitor(double dt) const;
  void printSetup() const;
  void printSummary() const;

  Config cfg_;
  Grid grid_;
  std::unique_ptr<Projection> fluid_;
  std::unique_ptr<FieldWriter> fields_;
  std::unique_ptr<CsvWriter> diagnostics_;
  ParticleConfig particleCfg_;
  std::unique_ptr<DemSolver> dem_;                 // when there are particles
  std::unique_ptr<Penalization> penalization_;     // particles in a fluid
  std::vector<double> hydroSums_;
  std::unique_ptr<ParticleWriter> particleWriter_;
  std::unique_ptr<ParticleTracker> tracker_;
  std::unique_ptr<CheckpointWriter> checkpoints_;
  double loopWall_ = 0;                            // wall time of the stepping loop
  double time_ = 0, nextOutputTime_ = 0, nextCheckpointTime_ = 0;
  int step_ = 0, lastOutputStep_ = -1, lastCheckpointStep_ = -1;
  int firstStep_ = 0;       // step and time this run started from (0 unless restarted)
  double firstTime_ = 0;
  StepStats last_;
  double wallStart_ = 0, wallLastStep_ = 0;
  long pressureIterationsTotal_ = 0;
};

} // namespace vp
