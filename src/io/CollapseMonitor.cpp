#include "vp/io/CollapseMonitor.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include "vp/particles/DemSolver.hpp"
#include "vp/particles/Shape.hpp"
#include <algorithm>
#include <cmath>

namespace vp {

CollapseConfig CollapseConfig::read()
{
  OptionGroup o("Granular collapse monitor", false);
  CollapseConfig c;
  c.on = o.flag("-collapse_monitor", false, "Granular collapse along +x from the low-x wall: front, 99th-percentile "
                                            "front and back-wall height (collapse.csv, one row per series step), "
                                            "deposit profile at the end (deposit.csv)");
  c.restSpeed = o.real("-collapse_rest_speed", 0, "With -collapse_monitor: the run ends once the 99th-percentile front has "
                                                  "moved slower than this (m/s) over the last -collapse_rest_window (0: never)");
  c.restWindow = o.real("-collapse_rest_window", c.restWindow, "Time over which the front must stay at rest (s)");
  return c;
}

void CollapseConfig::validate(bool particles) const
{
  if (!(restSpeed >= 0)) failOption("-collapse_rest_speed", "must be >= 0 (0: never), got " + formatNumber(restSpeed));
  if (!(restWindow > 0)) failOption("-collapse_rest_window", "must be > 0, got " + formatNumber(restWindow));
  if (restSpeed > 0 && !on) failOption("-collapse_rest_speed", "needs -collapse_monitor (it watches the front)");
  if (on && !particles) failOption("-collapse_monitor", "measures a granular collapse: the case has no particles");
}

CollapseMonitor::CollapseMonitor(const Grid& grid, const CollapseConfig& cfg, const std::string& dir, double resumeAfter)
  : grid_(grid), cfg_(cfg), dir_(dir)
{
  csv_ = std::make_unique<CsvWriter>(grid.comm(), dir + "/collapse.csv",
                                     std::vector<std::string>{"time", "front", "front99", "height_back"}, resumeAfter);
}

CollapseMonitor::Particles CollapseMonitor::gather(const ParticleStore& p) const
{
  const MPI_Comm comm = grid_.comm();
  int rank, size;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  constexpr int kValues = 5;
  std::vector<double> mine;
  mine.reserve(kValues * p.nOwned);
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    if (p.sphere(i)) {
      mine.insert(mine.end(), {p.x[i][0], p.x[i][2], p.radius[i], p.radius[i], 2 * p.radius[i]});
    } else {
      const Shape g = p.shape(i);
      mine.insert(mine.end(), {p.x[i][0], p.x[i][2], g.extent(toBody(p.q[i], {1, 0, 0})), g.extent(toBody(p.q[i], {0, 0, 1})),
                               2 * g.equalVolumeRadius()});
    }
  }
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(rank == 0 ? size : 0), offsets(counts.size(), 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  for (std::size_t k = 1; k < counts.size(); ++k) offsets[k] = offsets[k - 1] + counts[k - 1];
  std::vector<double> all(rank == 0 ? offsets.back() + counts.back() : 0);
  MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm);
  Particles s;
  for (std::size_t k = 0; k + kValues - 1 < all.size(); k += kValues) {
    s.x.push_back(all[k]);
    s.z.push_back(all[k + 1]);
    s.halfX.push_back(all[k + 2]);
    s.halfZ.push_back(all[k + 3]);
    s.diameter += all[k + 4];
  }
  if (!s.x.empty()) s.diameter /= s.x.size();
  return s;
}

CollapseState CollapseMonitor::measure(const ParticleStore& p) const
{
  const Particles s = gather(p);
  double v[3] = {0, 0, 0};
  if (!s.x.empty()) {
    std::vector<double> right(s.x.size());
    for (std::size_t k = 0; k < right.size(); ++k) right[k] = s.x[k] + s.halfX[k];
    std::sort(right.begin(), right.end());
    const double at = 0.99 * (right.size() - 1);
    const std::size_t lo = static_cast<std::size_t>(std::floor(at)), hi = std::min(lo + 1, right.size() - 1);
    v[0] = right.back();
    v[1] = right[lo] + (at - lo) * (right[hi] - right[lo]);
    for (std::size_t k = 0; k < s.x.size(); ++k)
      if (s.x[k] - grid_.lo(0) < 2 * s.diameter) v[2] = std::max(v[2], s.z[k] + s.halfZ[k]);
  }
  MPI_Bcast(v, 3, MPI_DOUBLE, 0, grid_.comm());
  return {v[0], v[1], v[2]};
}

void CollapseMonitor::record(const RunView& run)
{
  const CollapseState c = measure(run.dem->particles());
  csv_->row({run.time, c.front, c.front99, c.heightBack});
  front99_.emplace_back(run.time, c.front99);
}

std::string CollapseMonitor::stopRequest()
{
  return atRest() ? "the collapse came to rest (-collapse_rest_speed)" : "";
}

bool CollapseMonitor::atRest()
{
  const double speed = cfg_.restSpeed, window = cfg_.restWindow;
  if (speed <= 0 || front99_.empty()) return false;
  // Keep the rows of the last window and the one just before it, so that the window is covered.
  const double now = front99_.back().first;
  while (front99_.size() > 1 && now - front99_[1].first >= window) front99_.pop_front();
  if (now - front99_.front().first < window) return false;
  double lo = front99_.front().second, hi = lo;
  for (const auto& [t, f] : front99_) {
    lo = std::min(lo, f);
    hi = std::max(hi, f);
  }
  return hi - lo < speed * window;
}

void CollapseMonitor::finish(const RunView& run)
{
  const Particles s = gather(run.dem->particles());
  CsvWriter csv(grid_.comm(), dir_ + "/deposit.csv", {"x", "h"});
  if (s.x.empty()) return;  // every rank but 0
  const double lo = grid_.lo(0), width = s.diameter;
  const std::size_t bins = static_cast<std::size_t>(std::ceil((grid_.hi(0) - lo) / width));
  std::vector<double> top(bins, 0.0);
  for (std::size_t k = 0; k < s.x.size(); ++k) {
    const std::size_t b = std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, (s.x[k] - lo) / width)));
    top[b] = std::max(top[b], s.z[k] + s.halfZ[k]);
  }
  for (std::size_t b = 0; b < bins; ++b) csv.row({lo + (b + 0.5) * width, top[b]});
}

} // namespace vp
