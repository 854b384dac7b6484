#pragma once
// Parallel ownership of particles (docs/particles.md, parallel decomposition): the rank whose cell-DMDA box contains a
// particle's centre owns it. migrate() hands particles that left the box to the neighbour (with
// their contact history); createGhosts() sends copies of particles within the halo to the 26
// neighbours (periodic images shifted); updateGhosts() refreshes the ghosts' x, v, omega, q.
#include "vp/grid/Grid.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <array>
#include <vector>

namespace vp {

class ParticleExchange {
public:
  // Throws InputError (on every rank) when a subdomain is thinner than the halo.
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

private:
  using Buffers = std::array<std::vector<char>, 27>;
  // Sends send[k] to the neighbour in direction k; recv[k] gets what the opposite neighbour sent
  // in direction k. knownSizes: recv[k] already has the right size.
  void exchange(const Buffers& send, Buffers& recv, bool knownSizes);
  int direction(const Vec3& x, int* offsets) const;

  const Grid& grid_;
  MPI_Comm comm_;
  double halo_;
  double boxLo_[3], boxHi_[3], length_[3];
  int neighbour_[27];
  Vec3 shift_[27];
  std::array<std::vector<std::size_t>, 27> ghostSend_;  // owned indices sent as ghosts, per direction
  std::array<std::size_t, 27> ghostRecv_{};             // ghosts received per direction
  Buffers sendBuf_, recvBuf_;
};

} // namespace vp
