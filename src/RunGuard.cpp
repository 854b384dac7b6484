#include "vp/RunGuard.hpp"
#include "vp/core/Broadcast.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Logging.hpp"
#include <algorithm>
#include <cmath>
#include <csignal>

namespace vp {

namespace {

volatile std::sig_atomic_t stopSignal = 0;

// The first signal asks for a stop at the next step boundary; a second one (a hung run) is
// handled by the default action.
extern "C" void onStopSignal(int s)
{
  stopSignal = s;
  std::signal(s, SIG_DFL);
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string num(double v) { return formatNumber(v); }

std::string where(const Vec3& x) { return "(" + num(x.x) + ", " + num(x.y) + ", " + num(x.z) + ")"; }

} // namespace

void installStopSignals()
{
  struct sigaction a {};
  a.sa_handler = onStopSignal;
  a.sa_flags = SA_RESTART;  // a write interrupted by the signal goes on
  sigemptyset(&a.sa_mask);
  sigaction(SIGTERM, &a, nullptr);
  sigaction(SIGINT, &a, nullptr);
}

std::string RunGuard::localProblem(double dt, const ops::FieldStats& flow, DemSolver* dem) const
{
  if (!cfg_.fluid.off) {
    if (!std::isfinite(flow.kineticEnergy) || !std::isfinite(flow.maxRate))
      return "the flow blew up (non-finite velocity); reduce -time_cfl, -time_dt or -time_dt_max";
    const double cfl = dt * flow.maxRate;
    if (cfg_.time.dt > 0 && cfl > cfg_.health.cflMax)
      return "CFL number " + num(cfl) + " exceeds -health_cfl_max " + num(cfg_.health.cflMax) + " with the fixed step -time_dt " +
             num(cfg_.time.dt) + "; reduce -time_dt or leave it out for the CFL-adaptive step";
  }
  if (!dem) return "";
  const ParticleStore& s = dem->particles();
  // Fast pass: the kinetic energy of the last sub-step carries any non-finite velocity (and a
  // non-finite position follows from one); the extent of the centres shows an escape. The
  // per-particle search below runs only when something is wrong.
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    const Vec3& x = s.x[i];
    lo.x = std::min(lo.x, x.x), lo.y = std::min(lo.y, x.y), lo.z = std::min(lo.z, x.z);
    hi.x = std::max(hi.x, x.x), hi.y = std::max(hi.y, x.y), hi.z = std::max(hi.z, x.z);
  }
  bool inside = std::isfinite(dem->localKineticEnergy());
  for (int d = 0; d < 3; ++d)
    inside = inside && (cfg_.bc.periodic(d) || (lo[d] >= cfg_.grid.lo[d] && hi[d] <= cfg_.grid.hi[d]));
  for (std::size_t i = 0; !inside && i < s.nOwned; ++i) {
    const std::string id = "particle " + std::to_string(s.id[i]);
    if (!finite(s.x[i]) || !finite(s.v[i]) || !finite(s.w[i]))
      return id + " has a non-finite position or velocity; reduce the step (-time_dt, -dem_substeps up) or check the forces (-gravity, -contact_*)";
    for (int d = 0; d < 3; ++d) {
      if (cfg_.bc.periodic(d)) continue;
      if (s.x[i][d] < cfg_.grid.lo[d] || s.x[i][d] > cfg_.grid.hi[d])
        return id + " left the box: centre at " + where(s.x[i]) + ", velocity " + where(s.v[i]) +
               " m/s; a contact too soft for the step (-contact_tc, -time_dt, -dem_substeps) or a bad initial velocity";
    }
  }
  const OverlapRecord o = dem->takeLargestOverlap();
  if (o.fraction > cfg_.health.overlapMax) {
    const std::string with = o.j < 0 ? "the " + std::string("xyz").substr((-1 - o.j) / 2, 1) + ((-1 - o.j) % 2 ? "hi" : "lo") + " wall"
                                     : "particle " + std::to_string(o.j);
    return "contact between particle " + std::to_string(o.i) + " and " + with + " overlaps by " + num(100 * o.fraction) +
           " % of the smaller diameter (-health_overlap_max " + num(cfg_.health.overlapMax) +
           "): the contact is too soft for the step or the impact; shorten -contact_tc (or raise -contact_kn) or the step (-time_dt, -dem_substeps)";
  }
  return "";
}

StepVerdict RunGuard::check(double dt, const ops::FieldStats& flow, DemSolver* dem, double elapsed, double lastStep)
{
  StageScope stage(Stage::Health);
  int rank, size;
  MPI_Comm_rank(comm_, &rank);
  MPI_Comm_size(comm_, &size);
  const std::string problem = localProblem(dt, flow, dem);
  // One reduction: the lowest rank with a problem, a signal, the wall-time limit.
  const bool limit = cfg_.time.wallLimit > 0 && elapsed + 1.5 * lastStep > cfg_.time.wallLimit;
  int in[3] = {problem.empty() ? 0 : size - rank, int(stopSignal), limit ? 1 : 0}, out[3];
  MPI_Allreduce(in, out, 3, MPI_INT, MPI_MAX, comm_);
  StepVerdict v;
  v.signal = out[1];
  v.wallLimit = out[2] != 0;
  if (out[0] > 0) {
    const int from = size - out[0];
    v.problem = problem;
    broadcast(comm_, v.problem, from);
  }
  return v;
}

} // namespace vp
