#pragma once
// The record of how a run was made (docs/outputs.md): run.json in the output directory holds the
// version (git describe at build time), date, host, ranks, command line, every option with its
// effective value (defaults included) and, once the run ends, why it stopped and its summary.
// The same record (without the end) is the attribute "vpsolve_run" of each HDF5 file.
#include <mpi.h>
#include <string>
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

// A JSON string literal.
std::string jsonString(const std::string& s);

} // namespace vp
