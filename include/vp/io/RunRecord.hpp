#pragma once
// The record of how a run was made (docs/outputs.md): run.json in the output directory holds the
// version (git describe at build time), date, host, ranks, command line, every option with its
// effective value (defaults included) and, once the run ends, why it stopped and its summary.
// The same record (without the end) is the attribute "vpsolve_run" of each HDF5 file.
#include <mpi.h>
#include <string>
#include <utility>
#include <vector>

namespace vp {

// Called once by the application before the run (stored for the record).
void setCommandLine(int argc, char** argv);

// The record as JSON; `end` holds extra top-level members ("\"stop_reason\": ...") or is empty.
std::string runRecordJson(MPI_Comm comm, const std::string& end = "");
// The start record of this run, built once on rank 0 and broadcast: the first call is collective
// (writeRunRecord makes it when the outputs open).
const std::string& runRecord();
// Writes <dir>/run.json on rank 0 (atomically: a temporary file renamed).
void writeRunRecord(MPI_Comm comm, const std::string& dir, const std::string& end = "");

// How a run ended, as run.json records it (docs/outputs.md).
struct RunEnd {
  std::string stopReason;
  int step = 0, stepsThisRun = 0;
  double time = 0, wallSeconds = 0, loopSeconds = 0;
  std::vector<std::pair<std::string, double>> stageSeconds;  // the slowest rank's, stages that ran
  bool fluid = false;                                        // the kinetic energy is recorded
  double kineticEnergy = 0;                                  // [J]
  bool particles = false;                                    // the particle figures are recorded
  long particlesAtStart = 0, particleCount = 0;
  double particleKineticEnergy = 0;                          // [J]
};
// The end's members for runRecordJson / writeRunRecord.
std::string runEndJson(const RunEnd& e);

// A JSON string literal.
std::string jsonString(const std::string& s);

} // namespace vp
