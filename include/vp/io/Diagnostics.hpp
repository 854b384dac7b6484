#pragma once
// diagnostics.csv (docs/outputs.md): one row per step with the fluid's statistics, the solvers'
// iteration counts and, with particles, the DEM's.
#include "vp/fluid/Operators.hpp"
#include "vp/fluid/Projection.hpp"
#include "vp/io/CsvWriter.hpp"
#include "vp/io/Monitor.hpp"
#include "vp/particles/DemSolver.hpp"
#include <memory>

namespace vp {

class Diagnostics : public Monitor {
public:
  // resumeStep >= 0 (a restart): continue the file after that step's row. rho: the fluid's density
  // (the kinetic energy in J).
  Diagnostics(MPI_Comm comm, const std::string& dir, bool particles, double rho, double resumeStep);
  void start(const RunView&) override {}  // rows of steps only
  // Collective (the DEM sums).
  void record(const RunView& run) override;

private:
  std::unique_ptr<CsvWriter> csv_;
  double rho_;
};

} // namespace vp
