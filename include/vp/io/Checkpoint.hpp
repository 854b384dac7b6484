#pragma once
// Checkpoint/restart (docs/outputs.md). checkpoint_<step 6 digits>.h5 holds all an exact
// continuation needs: a header (format, version, grid, boundaries, set-up options) and the run's
// counters, written here, and the components' own parts (core/StateArchive.hpp: the fluid's fields
// in natural DMDA order, so that a restart may use another number of ranks, the pressure
// solutions, every particle with its springs). It is written under a temporary name and renamed;
// checkpoint_latest.h5, a symbolic link, moves to it only then, so a crash never leaves a
// half-written checkpoint behind.
#include "vp/core/Config.hpp"
#include "vp/core/StateArchive.hpp"
#include "vp/grid/Grid.hpp"
#include <deque>
#include <functional>
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

// The components' parts of a checkpoint, written in one call (Projection::saveState, ...).
using StateParts = std::function<void(StateWriter&)>;

class CheckpointWriter {
public:
  // Keeps the newest `keep` checkpoints of the directory (those of the run's earlier pieces count),
  // deletes older ones.
  CheckpointWriter(MPI_Comm comm, std::string dir, int keep);
  // Collective: the header (format, grid, boundaries, set-up options, counters), then the parts.
  void write(const Grid& grid, const BoundaryConfig& bc, const RunState& run, const StateParts& parts);

private:
  void writeFile(const std::string& tmp, const Grid& grid, const BoundaryConfig& bc, const RunState& run, const StateParts& parts);
  MPI_Comm comm_;
  std::string dir_;
  int keep_;
  std::deque<std::string> written_;
};

// A checkpoint opened for a restart; the components read their parts from it (StateReader).
class CheckpointReader : public StateReader {
public:
  // Opens and checks the file's header against the run's grid and boundaries; throws InputError
  // naming -restart on a missing, foreign, damaged or mismatching file. Collective.
  CheckpointReader(MPI_Comm comm, const std::string& path, const Config& cfg);

  const RunState& run() const { return run_; }
  // "-name value" lines of the writing run's set-up options ("" in checkpoints older than them).
  const std::string& setupOptions() const { return setup_; }

  int version() const override { return version_; }
  bool has(const std::string& name) const override;
  void vector(const std::string& name, Vec v) const override;
  std::vector<double> table(const std::string& name, int& cols) const override;
  std::string text(const std::string& name) const override;
  [[noreturn]] void fail(const std::string& what) const override;

private:
  MPI_Comm comm_;
  int rank_ = 0;
  std::string path_;
  int version_ = 0;
  RunState run_;
  std::string setup_;
};

} // namespace vp
