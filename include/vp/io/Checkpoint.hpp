#pragma once
// Checkpoint/restart (docs/outputs.md). checkpoint_<step 6 digits>.h5 holds all
// an exact continuation needs: the fluid state (face velocity, pressure, the previous step's
// convection term, the last pressure and velocity increments, the pressure solutions the next
// starts are fitted from, all in natural DMDA order so that a restart may use
// another number of ranks), every particle with its contact springs and last-sub-step forces, and
// the run's counters. It is written under a temporary name and renamed; checkpoint_latest.h5, a
// symbolic link, moves to it only then, so a crash never leaves a half-written checkpoint behind.
#include "vp/core/Config.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <deque>
#include <string>
#include <vector>

namespace vp {

// The run's counters besides the fields and particles.
struct RunState {
  int step = 0;
  double time = 0;
  double dtOld = 0;                       // the previous step (variable-step AB2)
  double nextOutputTime = 0, nextCheckpointTime = 0;
  int lastOutputStep = -1;
  double penalizationFloor = 0;           // the largest floor of lambda so far (Simulation::buildMask)
  std::vector<double> fieldSnapshots;     // (step, time) of the field snapshots written so far
  std::vector<double> particleSnapshots;  // (step, time, count) of the particle snapshots
};

// The fluid vectors a checkpoint holds (faceDM, cellDM, faceDM, cellDM, faceDM global vectors) and
// the pressure solutions the next solves' starts are fitted from (cellDM, oldest first; SolutionHistory.hpp).
struct FluidState {
  Vec velocity, pressure, convectionOld, pressureIncrement, velocityIncrement;
  Vec velocityIncrementOld;  // optional (null: not written; absent from the oldest checkpoints)
  std::vector<Vec> pressureHistory;
};

class CheckpointWriter {
public:
  // Keeps the newest `keep` checkpoints of the directory (those of the run's earlier pieces count),
  // deletes older ones.
  CheckpointWriter(MPI_Comm comm, std::string dir, int keep);
  // Collective. owned: this rank's particles with their springs.
  void write(const Grid& grid, const BoundaryConfig& bc, const RunState& run, const FluidState& fluid,
             const std::vector<ParticleRecord>& owned);

private:
  // The HDF5 file itself (collective).
  void writeFile(const std::string& tmp, const Grid& grid, const BoundaryConfig& bc, const RunState& run,
                 const FluidState& fluid, const std::vector<ParticleRecord>& owned);
  MPI_Comm comm_;
  std::string dir_;
  int keep_;
  std::deque<std::string> written_;
};

class CheckpointReader {
public:
  // Opens and checks the file against the run's grid and boundaries; throws InputError naming
  // -restart on a missing, foreign, damaged or mismatching file. Collective.
  CheckpointReader(MPI_Comm comm, const std::string& path, const Config& cfg);

  const RunState& run() const { return run_; }
  // "-name value" lines of the writing run's set-up options ("" in checkpoints older than them).
  const std::string& setupOptions() const { return setup_; }
  // Every particle (the same list on every rank), springs attached.
  const std::vector<ParticleRecord>& particles() const { return particles_; }
  // Collective: reads the fluid vectors (not the pressure history).
  // Returns whether the file held velocityIncrementOld (then loaded into it).
  bool loadFluid(const FluidState& fluid) const;
  // Collective: the stored pressure history as new vectors like `like`, oldest first (none in
  // checkpoints older than it); the caller destroys them.
  std::vector<Vec> loadPressureHistory(Vec like) const;

private:
  MPI_Comm comm_;
  std::string path_;
  RunState run_;
  std::string setup_;
  std::vector<ParticleRecord> particles_;
};

} // namespace vp
