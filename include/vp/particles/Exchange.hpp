#pragma once
// Parallel ownership of particles (docs/particles.md, parallel decomposition): the rank whose
// cell-DMDA box contains a particle's centre owns it. migrate() hands particles that left the box
// to their new owner (with their contact history); createGhosts() sends a copy of each particle to
// every subdomain whose box, widened by the halo, contains the particle or one of its periodic
// images (shifted copies; on a short periodic axis a rank holds images of its own particles), over
// any number of subdomains; updateGhosts() refreshes the ghosts' sub-step fields.
#include "vp/grid/Grid.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <vector>

namespace vp {

class ParticleExchange {
public:
  // Throws InputError (on every rank) when a periodic length is shorter than the halo.
  ParticleExchange(const Grid& grid, double halo);

  double halo() const { return halo_; }
  double boxLo(int d) const { return boxLo_[d]; }
  double boxHi(int d) const { return boxHi_[d]; }
  // Cell index of a coordinate along axis d, wrapped (periodic) or clamped into the grid.
  int cellOf(int d, double x) const;
  bool owns(const Vec3& x) const;
  // Maps a position into the periodic domain (no change on wall axes).
  Vec3 wrapped(Vec3 x) const;

  // Collective. Requires no ghosts. Returns the number of particles this rank sent away.
  std::size_t migrate(ParticleStore& s);
  // Collective. Drops old ghosts and creates the new ones.
  void createGhosts(ParticleStore& s);
  // Collective. Same ghosts as the last createGhosts(), new kinematics.
  void updateGhosts(ParticleStore& s);
  // Collective. The reverse of updateGhosts: values[width * g + m] of every ghost g is sent back
  // to the particle it copies and added to its owner's entry (hydrodynamic partial sums).
  void reduceToOwners(const ParticleStore& s, std::vector<double>& values, int width);

  // Messages this rank has sent (sizes included, self-messages excluded) and their bytes.
  long messagesSent() const { return messages_; }
  double bytesSent() const { return bytes_; }

private:
  // A particle at x is sent to the peer as x + shift when lo <= x < hi on every axis.
  struct Link {
    Vec3 lo, hi, shift;
  };
  struct Peer {
    int rank;
    PetscInt start[3], end[3];  // its cell box
    std::vector<Link> links;    // one per periodic shift under which the boxes meet
    std::vector<std::size_t> sendIndex;  // owned particles sent as ghosts, link by link
    std::vector<Vec3> sendShift;
    std::size_t recvCount = 0;  // ghosts received (stored in peer order after the owned ones)
    std::vector<char> sendBuf, recvBuf;
  };
  void findPeers();
  bool inBox(const Vec3& x, const PetscInt* start, const PetscInt* end) const;
  // Sends every peer its sendBuf and fills recvBuf with what it sent (already sized if knownSizes).
  void exchange(bool knownSizes);
  void count(int to, std::size_t bytes)
  {
    if (to == rank_) return;  // a self-image: no traffic between ranks
    ++messages_;
    bytes_ += static_cast<double>(bytes);
  }

  const Grid& grid_;
  MPI_Comm comm_;
  double halo_;
  PetscInt start_[3], end_[3];
  double boxLo_[3], boxHi_[3], length_[3];
  std::vector<Peer> peers_;
  int rank_ = 0;
  long messages_ = 0;
  double bytes_ = 0;
};

} // namespace vp
