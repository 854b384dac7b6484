#pragma once
// Time series of tracked particles (-track_particles): particle_<id>.csv with columns
// time,x,y,z,vx,vy,vz,wx,wy,wz,fx,fy,fz (hydrodynamic force) followed by fcx,fcy,fcz (contact,
// lubrication and gravity force) and tx,ty,tz (non-hydrodynamic torque). Owners send their rows to
// rank 0, which buffers them and appends them on flush(): at every progress line, checkpoint and the
// end of the run, and at least every kFlushSeconds of wall time, so a run killed outright (no end,
// no checkpoint) loses no more than that.
#include "vp/io/Monitor.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <map>
#include <mpi.h>
#include <set>
#include <string>

namespace vp {

class ParticleTracker : public Monitor {
public:
  // Starts the files afresh (header only); resumeAfter >= 0 (a restart): continues existing files
  // after the row of that time.
  ParticleTracker(MPI_Comm comm, std::string dir, const ParticleConfig& pc, const ParticleStore& s,
                  double resumeAfter = -1);
  ~ParticleTracker() override;
  ParticleTracker(const ParticleTracker&) = delete;
  ParticleTracker& operator=(const ParticleTracker&) = delete;

  bool active() const { return all_ || !ids_.empty(); }
  // Collective: one row per tracked particle.
  void record(const RunView& run) override;
  // Rank 0 appends the buffered rows.
  void flush() override;

private:
  bool tracked(std::int64_t id) const { return all_ || ids_.count(id); }
  MPI_Comm comm_;
  std::string dir_;
  bool all_;
  std::set<std::int64_t> ids_;
  static constexpr double kFlushSeconds = 10;
  std::map<std::int64_t, std::string> pending_;
  std::size_t pendingRows_ = 0;
  double lastFlush_ = MPI_Wtime();  // rank 0's wall time of the last flush
};

} // namespace vp
