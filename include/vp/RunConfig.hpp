#pragma once
// The whole configuration of a run, read and validated once before anything is built or written
// (docs/architecture.md, run lifecycle): fluid/grid/time/output (Config), particles with contact and
// lubrication (ParticleConfig), penalization, the solver choices vpsolve interprets and the collapse
// and rheology monitors.
#include "vp/core/Config.hpp"
#include "vp/coupling/Penalization.hpp"
#include "vp/fluid/SolverOptions.hpp"
#include "vp/io/CollapseMonitor.hpp"
#include "vp/io/RheologyMonitor.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include <mpi.h>

namespace vp {

struct RunConfig {
  Config main;
  ParticleConfig particles;
  PenalizationConfig penalization;
  SolverOptions solvers;
  CollapseConfig collapse;
  RheologyConfig rheology;
  bool allowUnknownOptions = false;  // -options_allow_unknown
  bool memoryCheck = true;           // -memory_check

  RunConfig() = default;
  // main as given (tests build it in code), the rest from the options database; defaults resolved.
  explicit RunConfig(const Config& c);

  // Parses every option (throws InputError naming a bad one).
  static RunConfig read();
  // Ranges and consistency of all parts (collective; throws InputError).
  void validate(MPI_Comm comm) const;
  // Defaults that depend on other options, resolved before anything is built: a coupled run without
  // a contact stiffness gets -contact_tc of ten first fluid steps (said on comm unless it is null).
  void resolveDefaults(MPI_Comm comm = MPI_COMM_NULL);
  // Estimated peak memory per node against the memory available there (collective).
  void checkMemory(MPI_Comm comm) const;
};

// Refuses options nothing has read (misspelt), naming the nearest valid one; with
// -options_allow_unknown they are only listed. Call once every object has read its options.
void checkUnknownOptions(MPI_Comm comm, bool allow);

} // namespace vp
