#pragma once
// The measurements of a granular column collapse (a dam break), taken by the run itself
// (-collapse_monitor; docs/dam_break.md): the column stands against the low-x wall, flows along +x
// and gravity points along -z. collapse.csv gets one row per time-series step (-series_every):
//   front      the rightmost particle surface, max(x + r) (r: the radius of a sphere, a spheroid's
//              half-width along the axis; particles/Shape.hpp)
//   front99    the 99th percentile of x + r (numpy's linear rule), the front without stray particles
//   height_back the highest particle top, max(z + r), of the particles whose centre lies within two
//              mean (equal-volume) diameters of the low-x wall (the column height at the back wall)
// and deposit.csv at the end of the run: the highest particle top per bin of one mean diameter
// along x, from the low-x wall (the deposit profile h(x)). The owned particles' centres and
// half-widths are gathered on rank 0 (a few numbers each), so the values do not depend on the
// rank count.
#include "vp/grid/Grid.hpp"
#include "vp/io/CsvWriter.hpp"
#include "vp/io/Monitor.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <deque>
#include <memory>
#include <string>

namespace vp {

// -collapse_monitor, -collapse_rest_speed, -collapse_rest_window.
struct CollapseConfig {
  bool on = false;          // collapse.csv and deposit.csv
  double restSpeed = 0;     // stop once the 99th-percentile front is at rest [m/s] (0: never)
  double restWindow = 0.2;  // over this long [s]

  static CollapseConfig read();
  // Ranges, and that the case has particles to watch (throws InputError).
  void validate(bool particles) const;
};

struct CollapseState {
  double front = 0, front99 = 0, heightBack = 0;
};

class CollapseMonitor : public Monitor {
public:
  // resumeAfter >= 0 (a restart): continue collapse.csv after the row of that time.
  CollapseMonitor(const Grid& grid, const CollapseConfig& cfg, const std::string& dir, double resumeAfter = -1);

  // The measurements (on every rank). Collective.
  CollapseState measure(const ParticleStore& p) const;
  // measure() and a row of collapse.csv. Collective.
  void record(const RunView& run) override;
  // With -collapse_rest_speed: a stop once the recorded 99th-percentile front has moved by less
  // than speed * window over the last window of time (the same answer on every rank; a restart
  // starts a new window).
  std::string stopRequest() override;
  // deposit.csv: x of the bin centre, h. Collective.
  void finish(const RunView& run) override;

private:
  // All particles, rank 0 only: centres, half-widths along x and z (the radius of a sphere; a
  // spheroid's extent, particles/Shape.hpp), and the mean (equal-volume) diameter.
  struct Particles {
    std::vector<double> x, z, halfX, halfZ;
    double diameter = 0;
  };
  Particles gather(const ParticleStore& p) const;

  bool atRest();

  const Grid& grid_;
  CollapseConfig cfg_;
  std::string dir_;
  std::unique_ptr<CsvWriter> csv_;
  std::deque<std::pair<double, double>> front99_;  // (time, front99) of the recorded rows, the last window
};

} // namespace vp
