#pragma once
// diagnostics.csv (docs/outputs.md): one row per step with the fluid's statistics, the solvers'
// iteration counts and, with particles, the DEM's.
#include "vp/fluid/Operators.hpp"
#include "vp/fluid/Projection.hpp"
#include "vp/io/CsvWriter.hpp"
#include "vp/particles/DemSolver.hpp"
#include <memory>

namespace vp {

class Diagnostics {
public:
  // resumeStep >= 0 (a restart): continue the file after that step's row.
  Diagnostics(MPI_Comm comm, const std::string& dir, bool particles, double resumeStep);
  // Collective (the DEM sums).
  void record(int step, double time, double dt, const StepStats& solvers, const ops::FieldStats& flow, double rho,
              double wallTime, const DemSolver* dem);

private:
  std::unique_ptr<CsvWriter> csv_;
};

} // namespace vp
