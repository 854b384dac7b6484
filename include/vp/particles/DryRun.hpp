#pragma once
// The DEM-only time loop of vpsolve -fluid_off: DemSolver steps with outputs (particle snapshots,
// tracked particles, diagnostics.csv) and a progress line. Returns the number of steps taken.
#include "vp/core/Config.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include <mpi.h>

namespace vp {

long runDryDem(MPI_Comm comm, const Config& c, const ParticleConfig& pc);

} // namespace vp
