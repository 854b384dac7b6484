#pragma once
// The fluid step (docs/fluid.md, the paragraph on dt): -time_dt, or the bounds of the grid (CFL at the
// flow's and the particles' rate, the viscous time of a cell or -time_dt_max), moving walls, gravity
// on particles released from rest and the explicit lubrication's limit, landing exactly on
// -time_final; DEM-only runs take -dem_substeps stable DEM steps. Built from the configuration
// alone, so that the run's configuration can resolve defaults from it (the contact time) before
// anything is built.
#include "vp/core/Config.hpp"
#include <mpi.h>

namespace vp {

class DemSolver;

class TimeStepControl {
public:
  TimeStepControl(const Config& cfg, bool particles);

  // The step at `cfl` that moving walls, the CFL rate `rate` [1/s] and gravity on particles allow (inf: none).
  double motionStep(double cfl, double rate) const;
  // The step -time_dt gives, or the bounds of the grid (CFL at this rate, viscous, -time_dt_max), the
  // walls and gravity; rate 0 before anything moves.
  double bound(double rate) const;
  // The step from `time`, the flow's largest rate |u|/h being `flowRate` (collective with particles).
  double next(double time, double flowRate, const DemSolver* dem, MPI_Comm comm) const;
  // Max over particles of (|U_c| + |Omega| a) / h_c (collective; 0 without particles).
  double particleRate(const DemSolver* dem, MPI_Comm comm) const;

private:
  TimeConfig time_;
  BoundaryConfig bc_;
  Vec3 gravity_;
  double nu_, h_[3];
  bool fluidOff_, particles_;
};

} // namespace vp
