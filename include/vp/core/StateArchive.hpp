#pragma once
// A checkpoint as the components see it (docs/outputs.md, checkpoints): each writes and reads its
// own part by name. Projection the fluid fields, PressureSolver its solution history,
// particles/ParticleCheckpoint the particle rows and their springs; io/Checkpoint implements both
// sides on one HDF5 file and adds the run's header and counters. Vectors are DMDA global vectors,
// stored in natural order (a restart may use another number of ranks); tables are rows of doubles,
// each rank writing its own block.
#include <petscvec.h>
#include <string>
#include <vector>

namespace vp {

class StateWriter {
public:
  virtual ~StateWriter() = default;
  virtual void vector(const std::string& name, Vec v) = 0;                                        // collective
  virtual void table(const std::string& name, const std::vector<double>& localRows, int cols) = 0;  // collective
  virtual void text(const std::string& name, const std::string& value) = 0;  // collective, one value on every rank
};

class StateReader {
public:
  virtual ~StateReader() = default;
  virtual int version() const = 0;                     // the checkpoint format's version
  virtual bool has(const std::string& name) const = 0; // a vector or table of that name (collective)
  // Loads the vector of that name into v (collective); a missing, mis-sized or unreadable one is an
  // InputError naming -restart.
  virtual void vector(const std::string& name, Vec v) const = 0;
  // Every row of the table, the same on every rank (collective), and its width in cols (0 when it
  // has no rows); none when absent.
  virtual std::vector<double> table(const std::string& name, int& cols) const = 0;
  virtual std::string text(const std::string& name) const = 0;  // "" when absent (collective)
  // Throws the InputError naming -restart for a file whose content is wrong (damaged, or foreign).
  [[noreturn]] virtual void fail(const std::string& what) const = 0;
};

} // namespace vp
