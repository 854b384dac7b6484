#pragma once
// Reads the -contact_* options from the PETSc options database (listed by -help); the caller
// validates them with ContactConfig::validate once it knows whether the run has particles.
#include "vp/interactions/ContactConfig.hpp"
#include <mpi.h>

namespace vp {

ContactConfig readContactOptions(MPI_Comm comm);

} // namespace vp
