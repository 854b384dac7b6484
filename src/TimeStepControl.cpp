#include "vp/TimeStepControl.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/particles/DemSolver.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace vp {

TimeStepControl::TimeStepControl(const Config& cfg, bool particles)
  : time_(cfg.time), bc_(cfg.bc), gravity_(cfg.gravity), nu_(cfg.fluid.nu()), fluidOff_(cfg.fluid.off), particles_(particles)
{
  for (int d = 0; d < 3; ++d) h_[d] = cfg.grid.spacing(d);
}

double TimeStepControl::particleRate(const DemSolver* dem, MPI_Comm comm) const
{
  if (!dem) return 0;
  const ParticleStore& s = dem->particles();
  double rate = 0;
  for (std::size_t i = 0; i < s.nOwned; ++i)
    for (int c = 0; c < 3; ++c) rate = std::max(rate, (std::fabs(s.v[i][c]) + norm(s.w[i]) * s.bound[i]) / h_[c]);
  double global = 0;
  MPI_Allreduce(&rate, &global, 1, MPI_DOUBLE, MPI_MAX, comm);
  return global;
}

double TimeStepControl::bound(double rate) const
{
  if (time_.dt > 0) return std::min(time_.dt, time_.final);
  const double hmin = std::min({h_[0], h_[1], h_[2]});
  // Without -time_dt_max: the viscous time of a cell, and at least ten steps over the run (a flow
  // at rest has no other bound).
  const double dt = time_.dtMax > 0 ? time_.dtMax : std::min(hmin * hmin / nu_, 0.1 * time_.final);
  return std::min({dt, motionStep(time_.cfl, rate), time_.final});
}

double TimeStepControl::motionStep(double cfl, double rate) const
{
  double dt = std::numeric_limits<double>::infinity();
  // Moving walls count too: they set the flow in motion from rest.
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 3; ++c) rate = std::max(rate, std::fabs(wallVelocity(bc_, f)[c]) / h_[c]);
  if (rate > 0) dt = cfl / rate;
  // Particles released from rest: a step may not let gravity move them more than cfl cells.
  const double g = norm(gravity_), hmin = std::min({h_[0], h_[1], h_[2]});
  if (particles_ && g > 0) dt = std::min(dt, std::sqrt(2 * cfl * hmin / g));
  return dt;
}

double TimeStepControl::next(double time, double flowRate, const DemSolver* dem, MPI_Comm comm) const
{
  double dt;
  if (time_.dt > 0)
    dt = time_.dt;
  else if (fluidOff_)  // DEM only: the step is -dem_substeps stable DEM steps.
    dt = dem->suggestedStep() * dem->substeps();
  else {
    dt = bound(std::max(flowRate, particleRate(dem, comm)));
    // The saturated lubrication is an explicit dashpot in the DEM sub-steps.
    if (dem) dt = std::min(dt, dem->lubricationStepLimit());
  }
  const double left = time_.final - time;
  // Land on -time_final exactly instead of leaving a sliver of a step.
  if (dt > left || left - dt < 1e-9 * dt) dt = left;
  return dt;
}

} // namespace vp
