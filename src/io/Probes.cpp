#include "vp/io/Probes.hpp"
#include "vp/fluid/Projection.hpp"
#include "vp/core/Error.hpp"
#include "vp/grid/FieldArray.hpp"
#include <cmath>

namespace vp {

Probes::Probes(const Grid& grid, std::vector<Vec3> points, const std::string& dir, double resumeAfter)
  : grid_(grid), points_(std::move(points))
{
  if (dir.empty()) return;
  std::vector<std::string> columns{"time"};
  for (std::size_t p = 0; p < points_.size(); ++p) columns.push_back("p_" + std::to_string(p));
  csv_ = std::make_unique<CsvWriter>(grid.comm(), dir + "/probes.csv", columns, resumeAfter);
}

std::vector<double> Probes::sample(Vec pressure)
{
  const Grid& g = grid_;
  std::vector<double> values(points_.size(), 0.0);
  {
    // Each of the 8 cells around a point is owned by one rank, which adds its weighted value:
    // no ghost (the cell DMDA's stencil has no corner ghosts) and the same sum on any rank count.
    CellArray p(g.cellDM(), pressure, true);
    for (std::size_t n = 0; n < points_.size(); ++n) {
      PetscInt base[3];
      double w[3];
      for (int d = 0; d < 3; ++d) {
        const double s = (points_[n][d] - g.lo(d)) / g.h(d) - 0.5;
        base[d] = static_cast<PetscInt>(std::floor(s));
        w[d] = s - base[d];
      }
      for (int c = 0; c < 8; ++c) {
        const int off[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
        PetscInt q[3];
        double weight = 1;
        bool mine = true;
        for (int d = 0; d < 3; ++d) {
          q[d] = base[d] + off[d];
          // Beyond a wall the pressure mirrors the first cell (zero normal gradient); periodic wraps.
          if (g.periodic(d)) q[d] = (q[d] % g.n(d) + g.n(d)) % g.n(d);
          else q[d] = std::min<PetscInt>(std::max<PetscInt>(q[d], 0), g.n(d) - 1);
          weight *= off[d] ? w[d] : 1 - w[d];
          mine = mine && q[d] >= g.start(d) && q[d] < g.end(d);
        }
        if (mine) values[n] += weight * p.a[q[2]][q[1]][q[0]];
      }
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, g.comm());
  return values;
}

void Probes::record(const RunView& run)
{
  std::vector<double> row{run.time};
  const std::vector<double> v = sample(run.fluid->pressure());
  row.insert(row.end(), v.begin(), v.end());
  if (csv_) csv_->row(row);
}

} // namespace vp
