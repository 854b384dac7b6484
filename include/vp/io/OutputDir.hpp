#pragma once
// One output directory holds one run (docs/outputs.md). A new run refuses a directory that holds
// another run's outputs, unless -output_overwrite (the old outputs are removed first) or -restart
// (the run continues them). Collective; InputError names the option to use.
#include <mpi.h>
#include <string>
#include <vector>

namespace vp {

// The files of a run found in dir (run.json, diagnostics.csv, fields/particles/checkpoint files,
// particle_<id>.csv, their .xmf indices).
std::vector<std::string> runOutputs(const std::string& dir);
// No side effects: throws InputError if the run may not write into dir (restart: the -restart
// path, "" if none; a restart continues the run of its own directory only).
void checkOutputDir(MPI_Comm comm, const std::string& dir, const std::string& restart, bool overwrite);
// Creates dir; with overwrite (and no restart) removes the previous run's outputs.
void prepareOutputDir(MPI_Comm comm, const std::string& dir, bool restart, bool overwrite);
// Before writing `what` (about `bytes`): throws RunFailure if dir's file system has less room,
// so that a full disk stops the run with the earlier files intact. Collective.
void requireSpace(MPI_Comm comm, const std::string& dir, double bytes, const std::string& what);

} // namespace vp
