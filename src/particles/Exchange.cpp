#include "vp/particles/Exchange.hpp"
#include "vp/core/Error.hpp"
#include <cmath>
#include <cstring>
#include <sstream>
#include <type_traits>
#include <utility>

namespace vp {

namespace {

template <class T>
void write(char*& p, const T& v)
{
  static_assert(std::is_trivially_copyable_v<T>);
  std::memcpy(p, &v, sizeof(T));
  p += sizeof(T);
}

template <class T>
void put(std::vector<char>& b, const T& v)
{
  const std::size_t n = b.size();
  b.resize(n + sizeof(T));
  char* p = b.data() + n;
  write(p, v);
}

template <class T>
T get(const char*& p)
{
  T v;
  std::memcpy(&v, p, sizeof(T));
  p += sizeof(T);
  return v;
}

// The contact history has a variable length: a count, then the springs.
void put(std::vector<char>& b, const ContactHistory& h)
{
  put(b, static_cast<std::uint32_t>(h.size()));
  for (const ContactSpring& c : h) put(b, c);
}

template <class T>
void getInto(const char*& p, T& v)
{
  if constexpr (std::is_same_v<T, ContactHistory>) {
    v.resize(get<std::uint32_t>(p));
    for (auto& c : v) c = get<ContactSpring>(p);
  } else {
    v = get<T>(p);
  }
}

// The fixed-size fields of ParticleFields.hpp whose sync flags contain `Sync`: particle i of the
// store written at p, which the caller has sized (positions shifted by `shift`), or read from p.
template <unsigned Sync>
void putFields(char*& p, const ParticleStore& s, std::size_t i, const Vec3& shift)
{
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto, const ParticleFieldInfo&, auto sync) {
    if constexpr ((decltype(sync)::value & Sync) != 0) {
      if constexpr ((decltype(sync)::value & kShift) != 0)
        write(p, (s.*field)[i] + shift);
      else
        write(p, (s.*field)[i]);
    }
  });
}

template <unsigned Sync>
void getFields(const char*& p, ParticleStore& s, std::size_t i)
{
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto field, auto, const ParticleFieldInfo&, auto sync) {
    if constexpr ((decltype(sync)::value & Sync) != 0) getInto(p, (s.*field)[i]);
  });
}

template <unsigned Sync>
void getRecordFields(const char*& p, ParticleRecord& r)
{
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto value, const ParticleFieldInfo&, auto sync) {
    if constexpr ((decltype(sync)::value & Sync) != 0) getInto(p, r.*value);
  });
}

void putRecord(std::vector<char>& b, const ParticleRecord& r)
{
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto value, const ParticleFieldInfo&, auto sync) {
    if constexpr ((decltype(sync)::value & kMigrate) != 0) put(b, r.*value);
  });
}

// Bytes of one particle's fields with these sync flags (fixed-size fields only).
template <unsigned Sync>
std::size_t fieldBytes()
{
  std::size_t n = 0;
  forEachParticleField<ParticleStore, ParticleRecord>([&](auto, auto value, const ParticleFieldInfo&, auto sync) {
    using T = std::remove_reference_t<decltype(std::declval<ParticleRecord>().*value)>;
    if constexpr ((decltype(sync)::value & Sync) != 0) n += sizeof(T);
  });
  return n;
}

int offsetOf(int k, int d) { return (d == 0 ? k % 3 : d == 1 ? (k / 3) % 3 : k / 9) - 1; }

} // namespace

ParticleExchange::ParticleExchange(const Grid& grid, double halo) : grid_(grid), comm_(grid.comm()), halo_(halo)
{
  const PetscMPIInt* nb;
  VP_CALL(DMDAGetNeighbors(grid.cellDM(), &nb));
  PetscInt procs[3];
  VP_CALL(DMDAGetInfo(grid.cellDM(), nullptr, nullptr, nullptr, nullptr, &procs[0], &procs[1], &procs[2], nullptr,
                      nullptr, nullptr, nullptr, nullptr, nullptr));
  for (int d = 0; d < 3; ++d) {
    boxLo_[d] = grid.faceCoord(d, grid.start(d));
    boxHi_[d] = grid.faceCoord(d, grid.end(d));
    length_[d] = grid.hi(d) - grid.lo(d);
  }
  for (int k = 0; k < 27; ++k) {
    neighbour_[k] = (k == 13) ? -1 : nb[k];
    for (int d = 0; d < 3; ++d) {
      const int o = offsetOf(k, d);
      double s = 0;
      if (grid.periodic(d) && o < 0 && grid.start(d) == 0) s = length_[d];
      if (grid.periodic(d) && o > 0 && grid.end(d) == grid.n(d)) s = -length_[d];
      shift_[k][d] = s;
    }
  }
  // Ghosts reach one neighbour deep: every subdomain that has a neighbour along an axis must be at
  // least one halo wide, and a periodic axis at least two (one image per pair).
  double slack[3];
  for (int d = 0; d < 3; ++d) {
    const bool split = procs[d] > 1 || grid.periodic(d);
    double s = split ? (boxHi_[d] - boxLo_[d]) - halo_ : 1.0;
    if (grid.periodic(d)) s = std::min(s, length_[d] - 2 * halo_);
    slack[d] = s;
  }
  double minSlack[3];
  MPI_Allreduce(slack, minSlack, 3, MPI_DOUBLE, MPI_MIN, comm_);
  for (int d = 0; d < 3; ++d)
    if (minSlack[d] < 0) {
      std::ostringstream m;
      m << "option -grid_n: a subdomain along " << "xyz"[d] << " is thinner than the particle halo " << halo_
        << " m (2 x largest radius + contact range + neighbour skin; periodic axes need 2 halos). "
        << "Use fewer ranks, or a grid whose decomposition gives wider subdomains along " << "xyz"[d];
      throw InputError(m.str());
    }
}

int ParticleExchange::cellOf(int d, double x) const
{
  const int n = grid_.n(d);
  int c = static_cast<int>(std::floor((x - grid_.lo(d)) / grid_.h(d)));
  if (grid_.periodic(d)) c = ((c % n) + n) % n;
  return c < 0 ? 0 : (c >= n ? n - 1 : c);
}

bool ParticleExchange::owns(const Vec3& x) const
{
  for (int d = 0; d < 3; ++d) {
    const int c = cellOf(d, x[d]);
    if (c < grid_.start(d) || c >= grid_.end(d)) return false;
  }
  return true;
}

Vec3 ParticleExchange::wrapped(Vec3 x) const
{
  for (int d = 0; d < 3; ++d) {
    if (!grid_.periodic(d)) continue;
    if (x[d] >= grid_.hi(d)) x[d] -= length_[d];
    if (x[d] < grid_.lo(d)) x[d] += length_[d];
  }
  return x;
}

int ParticleExchange::direction(const Vec3& x, int* o) const
{
  int k = 0, stride = 1;
  for (int d = 0; d < 3; ++d) {
    // Unwrapped cell index: a particle below the low periodic face goes to the low neighbour.
    int c = static_cast<int>(std::floor((x[d] - grid_.lo(d)) / grid_.h(d)));
    if (!grid_.periodic(d)) c = c < 0 ? 0 : (c >= grid_.n(d) ? grid_.n(d) - 1 : c);
    o[d] = c < grid_.start(d) ? -1 : (c >= grid_.end(d) ? 1 : 0);
    k += (o[d] + 1) * stride;
    stride *= 3;
  }
  return k;
}

void ParticleExchange::exchange(const Buffers& send, Buffers& recv, bool knownSizes)
{
  std::vector<MPI_Request> req;
  req.reserve(108);
  std::array<unsigned long, 27> sendSize{}, recvSize{};
  if (!knownSizes) {
    for (int k = 0; k < 27; ++k) {
      if (neighbour_[26 - k] < 0) continue;
      req.emplace_back();
      MPI_Irecv(&recvSize[k], 1, MPI_UNSIGNED_LONG, neighbour_[26 - k], k, comm_, &req.back());
    }
    for (int k = 0; k < 27; ++k) {
      if (neighbour_[k] < 0) continue;
      sendSize[k] = send[k].size();
      req.emplace_back();
      MPI_Isend(&sendSize[k], 1, MPI_UNSIGNED_LONG, neighbour_[k], k, comm_, &req.back());
    }
    MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
    req.clear();
    for (int k = 0; k < 27; ++k) recv[k].resize(recvSize[k]);
  }
  for (int k = 0; k < 27; ++k) {
    if (neighbour_[26 - k] < 0 || recv[k].empty()) continue;
    req.emplace_back();
    MPI_Irecv(recv[k].data(), static_cast<int>(recv[k].size()), MPI_BYTE, neighbour_[26 - k], 27 + k, comm_, &req.back());
  }
  for (int k = 0; k < 27; ++k) {
    if (neighbour_[k] < 0 || send[k].empty()) continue;
    req.emplace_back();
    MPI_Isend(send[k].data(), static_cast<int>(send[k].size()), MPI_BYTE, neighbour_[k], 27 + k, comm_, &req.back());
  }
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
}

std::size_t ParticleExchange::migrate(ParticleStore& s)
{
  s.dropGhosts();
  for (auto& b : sendBuf_) b.clear();
  std::vector<char> keep(s.nOwned, 1);
  std::size_t sent = 0;
  int o[3];
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    const int k = direction(s.x[i], o);
    if (k == 13) continue;
    // A wall axis has no neighbour beyond it: direction() clamps, so neighbour_[k] >= 0 here.
    ParticleRecord r = s.record(i);
    r.x = wrapped(r.x + shift_[k]);
    putRecord(sendBuf_[k], r);
    keep[i] = 0;
    ++sent;
  }
  exchange(sendBuf_, recvBuf_, false);
  s.compactOwned(keep);
  int lost = 0;
  for (int k = 0; k < 27; ++k) {
    const char* p = recvBuf_[k].data();
    const char* end = p + recvBuf_[k].size();
    while (p < end) {
      ParticleRecord r;
      getRecordFields<kMigrate>(p, r);
      r.x = wrapped(r.x);
      if (!owns(r.x)) ++lost;
      s.append(r);
    }
  }
  s.nOwned = s.size();
  int anyLost = 0;
  MPI_Allreduce(&lost, &anyLost, 1, MPI_INT, MPI_SUM, comm_);
  if (anyLost)
    throw StepFailure(std::to_string(anyLost) + " particle(s) moved farther than one subdomain between two "
                             "neighbour-list rebuilds (time step too large for the particle speeds)");
  return sent;
}

void ParticleExchange::createGhosts(ParticleStore& s)
{
  static const std::size_t bytes = fieldBytes<kCreate>();
  s.dropGhosts();
  for (int k = 0; k < 27; ++k) {
    ghostSend_[k].clear();
    sendBuf_[k].clear();
    if (neighbour_[k] < 0) continue;
    int o[3];
    for (int d = 0; d < 3; ++d) o[d] = offsetOf(k, d);
    for (std::size_t i = 0; i < s.nOwned; ++i) {
      const Vec3& x = s.x[i];
      bool near = true;
      for (int d = 0; d < 3 && near; ++d)
        near = o[d] == 0 || (o[d] > 0 ? x[d] >= boxHi_[d] - halo_ : x[d] < boxLo_[d] + halo_);
      if (!near) continue;
      ghostSend_[k].push_back(i);
      const std::size_t at = sendBuf_[k].size();
      sendBuf_[k].resize(at + bytes);
      char* p = sendBuf_[k].data() + at;
      putFields<kCreate>(p, s, i, shift_[k]);
    }
  }
  exchange(sendBuf_, recvBuf_, false);
  for (int k = 0; k < 27; ++k) {
    const char* p = recvBuf_[k].data();
    ghostRecv_[k] = recvBuf_[k].size() / bytes;
    for (std::size_t g = 0; g < ghostRecv_[k]; ++g) {
      ParticleRecord r;
      getRecordFields<kCreate>(p, r);
      s.append(r);
    }
  }
}

void ParticleExchange::updateGhosts(ParticleStore& s)
{
  static const std::size_t bytes = fieldBytes<kStep>();
  for (int k = 0; k < 27; ++k) {
    sendBuf_[k].resize(ghostSend_[k].size() * bytes);
    char* p = sendBuf_[k].data();
    for (std::size_t i : ghostSend_[k]) putFields<kStep>(p, s, i, shift_[k]);
    recvBuf_[k].resize(ghostRecv_[k] * bytes);
  }
  exchange(sendBuf_, recvBuf_, true);
  std::size_t g = s.nOwned;
  for (int k = 0; k < 27; ++k) {
    const char* p = recvBuf_[k].data();
    for (std::size_t j = 0; j < ghostRecv_[k]; ++j, ++g) getFields<kStep>(p, s, g);
  }
}

void ParticleExchange::reduceToOwners(const ParticleStore& s, std::vector<double>& values, int width)
{
  // Ghosts received in direction k came from the neighbour opposite k: send their values back in
  // direction 26 - k; the owner gets them in recv[26 - k], in the order of ghostSend_[k].
  const std::size_t bytes = width * sizeof(double);
  std::size_t g = s.nOwned;
  for (int k = 0; k < 27; ++k) {
    sendBuf_[26 - k].assign(reinterpret_cast<const char*>(values.data() + width * g),
                            reinterpret_cast<const char*>(values.data() + width * (g + ghostRecv_[k])));
    g += ghostRecv_[k];
  }
  for (int k = 0; k < 27; ++k) recvBuf_[26 - k].resize(ghostSend_[k].size() * bytes);
  exchange(sendBuf_, recvBuf_, true);
  for (int k = 0; k < 27; ++k) {
    const double* p = reinterpret_cast<const double*>(recvBuf_[26 - k].data());
    for (std::size_t i : ghostSend_[k])
      for (int m = 0; m < width; ++m) values[width * i + m] += *p++;
  }
}

} // namespace vp
