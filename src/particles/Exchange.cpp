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

// The contact history has a variable length: a count, then the springs field by field (the
// struct's padding bytes are never sent).
void put(std::vector<char>& b, const ContactHistory& h)
{
  put(b, static_cast<std::uint32_t>(h.size()));
  for (const ContactSpring& c : h) {
    put(b, c.partner);
    put(b, c.spring);
    put(b, c.departure);
  }
}

// The window's history: a count (0 or 1), then its modes and the contact's change.
void put(std::vector<char>& b, const WindowModes& w)
{
  put(b, static_cast<std::uint32_t>(w.size()));
  for (const WindowHistory& h : w) {
    put(b, h.modes);
    put(b, h.contactChange);
  }
}

template <class T>
void getInto(const char*& p, T& v)
{
  if constexpr (std::is_same_v<T, WindowModes>) {
    v.resize(get<std::uint32_t>(p));
    for (WindowHistory& h : v) {
      h.modes = get<BassetModes>(p);
      h.contactChange = get<Vec3>(p);
    }
  } else if constexpr (std::is_same_v<T, ContactHistory>) {
    v.resize(get<std::uint32_t>(p));
    for (ContactSpring& c : v) {
      c.partner = get<decltype(c.partner)>(p);
      c.spring = get<decltype(c.spring)>(p);
      c.departure = get<decltype(c.departure)>(p);
    }
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

} // namespace

ParticleExchange::ParticleExchange(const Grid& grid, double halo) : grid_(grid), comm_(grid.comm()), halo_(halo)
{
  for (int d = 0; d < 3; ++d) {
    start_[d] = grid.start(d);
    end_[d] = grid.end(d);
    boxLo_[d] = grid.faceCoord(d, grid.start(d));
    boxHi_[d] = grid.faceCoord(d, grid.end(d));
    length_[d] = grid.hi(d) - grid.lo(d);
    // Images one period away reach every point within the halo when the halo is at most a period.
    if (grid.periodic(d) && halo_ > length_[d]) {
      std::ostringstream m;
      m << "option -grid_hi: the periodic length along " << "xyz"[d] << " (" << length_[d]
        << " m) is shorter than the particle halo " << halo_
        << " m (2 x largest radius + contact range + neighbour skin). Use a longer periodic box or smaller spheres";
      throw InputError(m.str());
    }
  }
  findPeers();
}

// Every subdomain, this one included, whose box widened by the halo meets ours widened by the halo
// under some periodic shift of at most one period. The relation is symmetric, so each rank receives
// from exactly the ranks it sends to: ghosts reach as far as the halo, across any number of
// subdomains, and a rank holds images of its own particles when a periodic axis is short.
void ParticleExchange::findPeers()
{
  int size, me;
  MPI_Comm_size(comm_, &size);
  MPI_Comm_rank(comm_, &me);
  rank_ = me;
  const PetscInt mine[6] = {start_[0], start_[1], start_[2], end_[0], end_[1], end_[2]};
  std::vector<PetscInt> all(6 * static_cast<std::size_t>(size));
  MPI_Allgather(mine, 6, MPIU_INT, all.data(), 6, MPIU_INT, comm_);
  int span[3];
  for (int d = 0; d < 3; ++d) span[d] = grid_.periodic(d) ? 1 : 0;
  peers_.clear();
  for (int r = 0; r < size; ++r) {
    Peer p;
    p.rank = r;
    for (int d = 0; d < 3; ++d) {
      p.start[d] = all[6 * r + d];
      p.end[d] = all[6 * r + 3 + d];
    }
    for (int sz = -span[2]; sz <= span[2]; ++sz)
      for (int sy = -span[1]; sy <= span[1]; ++sy)
        for (int sx = -span[0]; sx <= span[0]; ++sx) {
          if (r == me && sx == 0 && sy == 0 && sz == 0) continue;
          const int sh[3] = {sx, sy, sz};
          Link l;
          bool meets = true;
          for (int d = 0; d < 3; ++d) {
            l.shift[d] = sh[d] * length_[d];
            // x goes to r as x + shift when x + shift lies within the halo of r's box.
            l.lo[d] = grid_.faceCoord(d, p.start[d]) - halo_ - l.shift[d];
            l.hi[d] = grid_.faceCoord(d, p.end[d]) + halo_ - l.shift[d];
            meets = meets && l.lo[d] < boxHi_[d] + halo_ && l.hi[d] > boxLo_[d] - halo_;
          }
          if (meets) p.links.push_back(l);
        }
    if (!p.links.empty()) peers_.push_back(std::move(p));
  }
}

int ParticleExchange::cellOf(int d, double x) const
{
  const int n = grid_.n(d);
  int c = static_cast<int>(std::floor((x - grid_.lo(d)) / grid_.h(d)));
  if (grid_.periodic(d)) c = ((c % n) + n) % n;
  return c < 0 ? 0 : (c >= n ? n - 1 : c);
}

bool ParticleExchange::inBox(const Vec3& x, const PetscInt* start, const PetscInt* end) const
{
  for (int d = 0; d < 3; ++d) {
    const int c = cellOf(d, x[d]);
    if (c < start[d] || c >= end[d]) return false;
  }
  return true;
}

bool ParticleExchange::owns(const Vec3& x) const { return inBox(x, start_, end_); }

Vec3 ParticleExchange::wrapped(Vec3 x) const
{
  for (int d = 0; d < 3; ++d) {
    if (!grid_.periodic(d)) continue;
    if (x[d] >= grid_.hi(d)) x[d] -= length_[d];
    if (x[d] < grid_.lo(d)) x[d] += length_[d];
  }
  return x;
}

void ParticleExchange::exchange(bool knownSizes)
{
  std::vector<MPI_Request> req;
  req.reserve(4 * peers_.size());
  if (!knownSizes) {
    std::vector<unsigned long> sendSize(peers_.size()), recvSize(peers_.size());
    for (std::size_t k = 0; k < peers_.size(); ++k) {
      req.emplace_back();
      MPI_Irecv(&recvSize[k], 1, MPI_UNSIGNED_LONG, peers_[k].rank, 0, comm_, &req.back());
    }
    for (std::size_t k = 0; k < peers_.size(); ++k) {
      sendSize[k] = peers_[k].sendBuf.size();
      req.emplace_back();
      MPI_Isend(&sendSize[k], 1, MPI_UNSIGNED_LONG, peers_[k].rank, 0, comm_, &req.back());
      count(peers_[k].rank, sizeof(unsigned long));
    }
    MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
    req.clear();
    for (std::size_t k = 0; k < peers_.size(); ++k) peers_[k].recvBuf.resize(recvSize[k]);
  }
  for (Peer& p : peers_) {
    if (p.recvBuf.empty()) continue;
    req.emplace_back();
    MPI_Irecv(p.recvBuf.data(), static_cast<int>(p.recvBuf.size()), MPI_BYTE, p.rank, 1, comm_, &req.back());
  }
  for (Peer& p : peers_) {
    if (p.sendBuf.empty()) continue;
    req.emplace_back();
    MPI_Isend(p.sendBuf.data(), static_cast<int>(p.sendBuf.size()), MPI_BYTE, p.rank, 1, comm_, &req.back());
    count(p.rank, p.sendBuf.size());
  }
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
}

std::size_t ParticleExchange::migrate(ParticleStore& s)
{
  s.dropGhosts();
  for (Peer& p : peers_) p.sendBuf.clear();
  std::vector<char> keep(s.nOwned, 1);
  std::size_t sent = 0;
  int lost = 0;
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    s.x[i] = wrapped(s.x[i]);
    if (owns(s.x[i])) continue;
    keep[i] = 0;
    Peer* to = nullptr;
    for (Peer& p : peers_)
      if (inBox(s.x[i], p.start, p.end)) to = &p;
    if (!to) {
      ++lost;
      continue;
    }
    putRecord(to->sendBuf, s.record(i));
    ++sent;
  }
  int anyLost = 0;
  MPI_Allreduce(&lost, &anyLost, 1, MPI_INT, MPI_SUM, comm_);
  if (anyLost)
    throw StepFailure(std::to_string(anyLost) + " particle(s) moved farther than the particle halo between two "
                             "neighbour-list rebuilds (time step too large for the particle speeds)");
  exchange(false);
  s.compactOwned(keep);
  for (const Peer& p : peers_) {
    const char* q = p.recvBuf.data();
    const char* end = q + p.recvBuf.size();
    while (q < end) {
      ParticleRecord r;
      getRecordFields<kMigrate>(q, r);
      s.append(r);
    }
  }
  s.nOwned = s.size();
  return sent;
}

void ParticleExchange::createGhosts(ParticleStore& s)
{
  static const std::size_t bytes = fieldBytes<kCreate>();
  s.dropGhosts();
  for (Peer& p : peers_) {
    p.sendIndex.clear();
    p.sendShift.clear();
    for (const Link& l : p.links)
      for (std::size_t i = 0; i < s.nOwned; ++i) {
        const Vec3& x = s.x[i];
        bool near = true;
        for (int d = 0; d < 3 && near; ++d) near = x[d] >= l.lo[d] && x[d] < l.hi[d];
        if (!near) continue;
        p.sendIndex.push_back(i);
        p.sendShift.push_back(l.shift);
      }
    p.sendBuf.resize(p.sendIndex.size() * bytes);
    char* q = p.sendBuf.data();
    for (std::size_t n = 0; n < p.sendIndex.size(); ++n) putFields<kCreate>(q, s, p.sendIndex[n], p.sendShift[n]);
  }
  exchange(false);
  for (Peer& p : peers_) {
    const char* q = p.recvBuf.data();
    p.recvCount = p.recvBuf.size() / bytes;
    for (std::size_t g = 0; g < p.recvCount; ++g) {
      ParticleRecord r;
      getRecordFields<kCreate>(q, r);
      s.append(r);
    }
  }
}

void ParticleExchange::updateGhosts(ParticleStore& s)
{
  static const std::size_t bytes = fieldBytes<kStep>();
  for (Peer& p : peers_) {
    p.sendBuf.resize(p.sendIndex.size() * bytes);
    char* q = p.sendBuf.data();
    for (std::size_t n = 0; n < p.sendIndex.size(); ++n) putFields<kStep>(q, s, p.sendIndex[n], p.sendShift[n]);
    p.recvBuf.resize(p.recvCount * bytes);
  }
  exchange(true);
  std::size_t g = s.nOwned;
  for (const Peer& p : peers_) {
    const char* q = p.recvBuf.data();
    for (std::size_t j = 0; j < p.recvCount; ++j, ++g) getFields<kStep>(q, s, g);
  }
}

void ParticleExchange::reduceToOwners(const ParticleStore& s, std::vector<double>& values, int width)
{
  // The ghosts received from a peer are sent back to it; it gets them in the order of its
  // sendIndex for us.
  const std::size_t bytes = width * sizeof(double);
  std::size_t g = s.nOwned;
  for (Peer& p : peers_) {
    p.sendBuf.assign(reinterpret_cast<const char*>(values.data() + width * g),
                     reinterpret_cast<const char*>(values.data() + width * (g + p.recvCount)));
    g += p.recvCount;
    p.recvBuf.resize(p.sendIndex.size() * bytes);
  }
  exchange(true);
  for (const Peer& p : peers_) {
    const double* q = reinterpret_cast<const double*>(p.recvBuf.data());
    for (std::size_t i : p.sendIndex)
      for (int m = 0; m < width; ++m) values[width * i + m] += *q++;
  }
}

} // namespace vp
