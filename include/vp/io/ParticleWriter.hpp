#pragma once
// Particle snapshots per the output contract: particles_<step 6 digits>.h5 written in parallel
// (datasets id, radius, position N x 3, velocity, angular_velocity, force (total, last sub-step),
// orientation N x 4; attribute time) and particles.xmf, a temporal collection of Polyvertex grids
// with relative paths that ParaView shows with a glyph filter.
#include "vp/particles/ParticleStore.hpp"
#include <mpi.h>
#include <string>
#include <vector>

namespace vp {

class ParticleWriter {
public:
  ParticleWriter(MPI_Comm comm, std::string dir);
  // Collective.
  void write(const ParticleStore& s, int step, double time);

  // The snapshots so far as (step, time, count) triples, and their restoration on a restart
  // (those whose files are in the output directory).
  std::vector<double> snapshotList() const;
  void resume(const std::vector<double>& list);

private:
  struct Snapshot {
    int step;
    double time;
    long count;
  };
  void writeXdmf() const;
  MPI_Comm comm_;
  std::string dir_;
  std::vector<Snapshot> snapshots_;
};

} // namespace vp
