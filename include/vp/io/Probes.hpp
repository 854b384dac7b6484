#pragma once
// Pressure probes (-probe x,y,z,...): probes.csv with one row per step, time and the pressure at
// each point (trilinear interpolation between cell centres; the dynamic pressure, i.e. without the
// hydrostatic part, so under a granular column it is the excess pore pressure). Each rank adds the
// weighted cells it owns, one reduction gives the values; rank 0 writes.
#include "vp/core/Vec3.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/io/CsvWriter.hpp"
#include "vp/io/Monitor.hpp"
#include <memory>
#include <vector>

namespace vp {

class Probes : public Monitor {
public:
  // resumeAfter >= 0 (a restart): continue probes.csv after the row of that time.
  Probes(const Grid& grid, std::vector<Vec3> points, const std::string& dir, double resumeAfter = -1);

  // The pressure at every probe (the same on every rank). Collective.
  std::vector<double> sample(Vec pressure);
  // sample() of the run's pressure and a row of probes.csv. Collective.
  void record(const RunView& run) override;

private:
  const Grid& grid_;
  std::vector<Vec3> points_;
  std::unique_ptr<CsvWriter> csv_;
};

} // namespace vp
