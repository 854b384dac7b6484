#include "vp/io/ParticleTracker.hpp"
#include "vp/particles/DemSolver.hpp"
#include "vp/io/CsvWriter.hpp"
#include <cstdio>
#include <vector>

namespace vp {

namespace {

// Concatenation of every rank's values on rank 0 (empty elsewhere). Collective.
template <class T>
std::vector<T> gatherToRoot(MPI_Comm comm, const std::vector<T>& mine, MPI_Datatype type)
{
  int size, rank, n = static_cast<int>(mine.size());
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  std::vector<int> counts(size), displs(size);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  int total = 0;
  for (int r = 0; r < size; ++r) {
    displs[r] = total;
    total += counts[r];
  }
  std::vector<T> all(rank == 0 ? total : 0);
  MPI_Gatherv(mine.data(), n, type, all.data(), counts.data(), displs.data(), type, 0, comm);
  return all;
}

const char* kHeader = "time,x,y,z,vx,vy,vz,wx,wy,wz,fx,fy,fz,fcx,fcy,fcz,tx,ty,tz,thx,thy,thz,qw,qx,qy,qz\n";
constexpr int kCols = 27;  // id + 26 values

std::string fileName(const std::string& dir, std::int64_t id)
{
  return dir + "/particle_" + std::to_string(id) + ".csv";
}

} // namespace

ParticleTracker::ParticleTracker(MPI_Comm comm, std::string dir, const ParticleConfig& pc, const ParticleStore& s,
                                 double resumeAfter)
  : comm_(comm), dir_(std::move(dir)), all_(pc.trackAll), ids_(pc.track.begin(), pc.track.end())
{
  if (all_) {
    // "all" means the particles present at the start: collect their ids on rank 0.
    const std::vector<std::int64_t> mine(s.id.begin(), s.id.begin() + s.nOwned);
    const std::vector<std::int64_t> every = gatherToRoot(comm_, mine, MPI_INT64_T);
    ids_.insert(every.begin(), every.end());
  }
  int rank;
  MPI_Comm_rank(comm_, &rank);
  if (rank != 0) return;
  for (std::int64_t id : ids_) {
    if (resumeAfter >= 0 && keepRowsUpTo(fileName(dir_, id), resumeAfter)) continue;
    if (FILE* f = std::fopen(fileName(dir_, id).c_str(), "w")) {
      std::fputs(kHeader, f);
      std::fclose(f);
    }
  }
}

ParticleTracker::~ParticleTracker() { flush(); }

void ParticleTracker::record(const RunView& run)
{
  if (!active()) return;
  const ParticleStore& s = run.dem->particles();
  const double time = run.time;
  std::vector<double> rows;
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    if (!tracked(s.id[i])) continue;
    const Vec3 values[7] = {s.x[i], s.v[i], s.w[i], s.fhyd[i], s.force[i], s.torque[i], s.thyd[i]};
    rows.push_back(static_cast<double>(s.id[i]));
    rows.push_back(time);
    for (const Vec3& v : values) {
      rows.push_back(v.x);
      rows.push_back(v.y);
      rows.push_back(v.z);
    }
    rows.insert(rows.end(), {s.q[i].w, s.q[i].x, s.q[i].y, s.q[i].z});
  }
  const std::vector<double> all = gatherToRoot(comm_, rows, MPI_DOUBLE);
  int rank;
  MPI_Comm_rank(comm_, &rank);
  if (rank != 0) return;
  char line[1024];
  for (std::size_t r = 0; r + kCols <= all.size(); r += kCols) {
    const double* v = &all[r];
    int len = std::snprintf(line, sizeof line, "%.17g", v[1]);
    for (int c = 2; c < kCols; ++c) len += std::snprintf(line + len, sizeof line - len, ",%.17g", v[c]);
    std::snprintf(line + len, sizeof line - len, "\n");
    pending_[static_cast<std::int64_t>(v[0])] += line;
    ++pendingRows_;
  }
  if (pendingRows_ > 20000 || MPI_Wtime() - lastFlush_ >= kFlushSeconds) flush();
}

void ParticleTracker::flush()
{
  for (auto& [id, text] : pending_) {
    if (text.empty()) continue;
    if (FILE* f = std::fopen(fileName(dir_, id).c_str(), "a")) {
      std::fputs(text.c_str(), f);
      std::fclose(f);
    }
    text.clear();
  }
  pendingRows_ = 0;
  lastFlush_ = MPI_Wtime();
}

} // namespace vp
