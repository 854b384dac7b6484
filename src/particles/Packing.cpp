#include "vp/particles/Packing.hpp"
#include "vp/core/Error.hpp"
#include <algorithm>
#include <cmath>
#include <random>

namespace vp {

namespace {

double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Sphere positions relaxed apart at radii scale * R on a grid of cells at least one largest
// diameter wide (periodic where the box wraps). Returns the largest overlap over the pair's radius sum.
class Relaxer {
public:
  Relaxer(const PackedInput& in, const std::array<bool, 3>& wrap, std::vector<Vec3>& x, const std::vector<double>& R)
    : in_(in), wrap_(wrap), x_(x), R_(R), shift_(x.size())
  {
    rmax_ = *std::max_element(R.begin(), R.end());
  }

  double sweep(double scale)
  {
    const Vec3 size = in_.hi - in_.lo;
    int n[3];
    for (int d = 0; d < 3; ++d) {
      n[d] = std::max(1, static_cast<int>(size[d] / (2 * rmax_ * scale)));
      if (wrap_[d] && n[d] < 3) n[d] = 1;  // one cell: its wrapped neighbours would be itself
    }
    head_.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
    next_.assign(x_.size(), -1);
    std::vector<std::array<int, 3>> cell(x_.size());
    for (std::size_t i = 0; i < x_.size(); ++i) {
      for (int d = 0; d < 3; ++d) cell[i][d] = std::min(n[d] - 1, std::max(0, static_cast<int>((x_[i][d] - in_.lo[d]) / size[d] * n[d])));
      const std::size_t c = cell[i][0] + n[0] * (cell[i][1] + static_cast<std::size_t>(n[1]) * cell[i][2]);
      next_[i] = head_[c];
      head_[c] = static_cast<long>(i);
    }
    std::fill(shift_.begin(), shift_.end(), Vec3{});
    double worst = 0;
    for (std::size_t i = 0; i < x_.size(); ++i)
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int c[3] = {cell[i][0] + dx, cell[i][1] + dy, cell[i][2] + dz};
            bool inside = true;
            for (int d = 0; d < 3; ++d) {
              if (c[d] >= 0 && c[d] < n[d]) continue;
              if (wrap_[d] && n[d] >= 3) c[d] = (c[d] + n[d]) % n[d];
              else inside = false;
            }
            if (!inside) continue;
            for (long j = head_[c[0] + n[0] * (c[1] + static_cast<std::size_t>(n[1]) * c[2])]; j >= 0; j = next_[j]) {
              if (static_cast<std::size_t>(j) <= i) continue;
              Vec3 d = x_[i] - x_[j];
              for (int a = 0; a < 3; ++a)
                if (wrap_[a]) d[a] -= size[a] * std::round(d[a] / size[a]);
              const double sum = scale * (R_[i] + R_[j]), r = norm(d), overlap = sum - r;
              if (overlap <= 0) continue;
              worst = std::max(worst, overlap / sum);
              const Vec3 push = (0.5 * overlap / std::max(r, 1e-12 * sum)) * d;
              shift_[i] += push;
              shift_[j] -= push;
            }
          }
    for (std::size_t i = 0; i < x_.size(); ++i) {
      x_[i] += shift_[i];
      for (int d = 0; d < 3; ++d) {
        if (wrap_[d]) {
          x_[i][d] = in_.lo[d] + std::fmod(std::fmod(x_[i][d] - in_.lo[d], size[d]) + size[d], size[d]);
          continue;
        }
        const double a = scale * R_[i], lo = in_.lo[d] + a, hi = in_.hi[d] - a;
        worst = std::max(worst, std::max(lo - x_[i][d], x_[i][d] - hi) / (2 * a));
        x_[i][d] = std::min(hi, std::max(lo, x_[i][d]));
      }
    }
    return worst;
  }

private:
  const PackedInput& in_;
  std::array<bool, 3> wrap_;
  std::vector<Vec3>& x_;
  const std::vector<double>& R_;
  std::vector<Vec3> shift_;
  std::vector<long> head_, next_;
  double rmax_ = 0;
};

} // namespace

std::vector<ParticleRecord> packedParticles(const PackedInput& in, double density, const std::array<bool, 3>& wrap,
                                            double clearance)
{
  const Vec3 size = in.hi - in.lo;
  const double volume = size.x * size.y * size.z, a = in.radius, b = in.radius * in.sizeRatio;
  auto ball = [](double r) { return 4.0 / 3.0 * M_PI * r * r * r; };
  std::vector<double> R;
  if (in.sizeRatio == 1) {
    R.assign(static_cast<std::size_t>(std::llround(in.volumeFraction * volume / ball(a))), a);
  } else {  // equal volumes of both sizes, the larger first
    R.assign(static_cast<std::size_t>(std::llround(0.5 * in.volumeFraction * volume / ball(b))), b);
    R.resize(R.size() + static_cast<std::size_t>(std::llround(0.5 * in.volumeFraction * volume / ball(a))), a);
  }
  if (R.empty()) failOption("-particles_packed", "the box holds no sphere at this volume fraction and radius");
  double solid = 0;
  for (double r : R) solid += ball(r);
  const double phi = solid / volume;
  std::mt19937_64 rng(in.seed);
  // Start at a tenth of the solid fraction, grow by at most 1 % a sweep once the overlaps are below
  // 1e-3 of the radius sums, and end at (1.002 + clearance) times the radii with overlaps below 2e-4.
  const double last = 1.002 + clearance, tolerance = 2e-4;
  double scale = std::min(last, std::cbrt(0.1 / phi));
  std::vector<Vec3> x(R.size());
  for (std::size_t i = 0; i < R.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      const double margin = wrap[d] ? 0 : scale * R[i];
      x[i][d] = in.lo[d] + margin + (size[d] - 2 * margin) * uniform(rng);
    }
  Relaxer relax(in, wrap, x, R);
  const long maxSweeps = 20000;
  for (long sweep = 0;; ++sweep) {
    const double worst = relax.sweep(scale);
    if (scale >= last && worst < tolerance) break;
    if (worst < 1e-3 && scale < last) scale = std::min(last, scale * 1.01);
    if (sweep == maxSweeps)
      failOption("-particles_packed", "the packing jammed at solid fraction " + formatNumber(phi * std::pow(scale, 3)) + " of the " +
                                          formatNumber(phi) + " asked for; lower the volume fraction (monodisperse spheres "
                                          "reach about 0.6 in a box)");
  }
  std::vector<ParticleRecord> out(R.size());
  for (std::size_t i = 0; i < R.size(); ++i) {
    out[i].id = static_cast<std::int64_t>(i);
    out[i].radius = R[i];
    out[i].density = density;
    out[i].x = x[i];
  }
  return out;
}

} // namespace vp
