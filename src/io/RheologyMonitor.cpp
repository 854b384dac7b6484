#include "vp/io/RheologyMonitor.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Options.hpp"
#include "vp/coupling/Penalization.hpp"
#include "vp/fluid/Projection.hpp"
#include "vp/grid/FieldArray.hpp"
#include "vp/particles/DemSolver.hpp"
#include <cmath>
#include <vector>

namespace vp {

namespace {

constexpr int kZlo = 4, kZhi = 5;  // wall faces

double meanDiameter(const ParticleStore& s, MPI_Comm comm)
{
  double sum[2] = {0, double(s.nOwned)};
  for (std::size_t i = 0; i < s.nOwned; ++i) sum[0] += 2 * s.radius[i];
  MPI_Allreduce(MPI_IN_PLACE, sum, 2, MPI_DOUBLE, MPI_SUM, comm);
  return sum[1] > 0 ? sum[0] / sum[1] : 0;
}

} // namespace

RheologyConfig RheologyConfig::read()
{
  OptionGroup o("Rheology monitor (shear cell)", false);
  RheologyConfig c;
  c.on = o.flag("-rheology_monitor", false, "A suspension sheared between the z walls (moving along x, periodic along x "
                                            "and y): relative viscosity from the wall traction and from the bulk stress "
                                            "of the core, its parts and the normal stress differences (rheology.csv, "
                                            "one row per series step; docs/rheology.md)");
  c.margin = o.real("-rheology_margin", c.margin, "The core whose bulk stress is measured lies this many mean particle "
                                                  "diameters away from each wall");
  return c;
}

void RheologyConfig::validate(const Config& c, const ParticleConfig& pc) const
{
  if (!(margin >= 0) || !std::isfinite(margin)) failOption("-rheology_margin", "must be >= 0 (mean diameters), got " + formatNumber(margin));
  if (!on) return;
  if (!pc.any() || c.fluid.off) failOption("-rheology_monitor", "measures a suspension: the case needs particles and the fluid");
  // A resolved force dropped in contact leaves the momentum the penalization took from the liquid
  // nowhere: the stress would not be transmitted across the cell.
  if (pc.contact.hydro != ContactHydro::Keep)
    failOption("-contact_hydro", std::string("the rheology monitor needs keep (given: ") + contactHydroName(pc.contact.hydro) +
                                     "): a resolved force excluded in contact breaks the momentum balance the stress is measured by");
  if (!c.bc.periodic(0) || !c.bc.periodic(1))
    failOption(c.bc.periodic(0) ? "-bc_ylo" : "-bc_xlo", "the shear cell is periodic along x and y (-rheology_monitor)");
  for (int f : {kZlo, kZhi})
    if (c.bc.type[f] != BcType::Velocity)
      failOption(f == kZlo ? "-bc_zlo" : "-bc_zhi", "the shear cell's walls move: give 'velocity' and -bc_z" +
                                                        std::string(f == kZlo ? "lo" : "hi") + "_velocity U,0,0 (-rheology_monitor)");
  for (int f : {kZlo, kZhi}) {
    const Vec3& v = c.bc.velocity[f];
    if (v.y != 0 || v.z != 0)
      failOption(f == kZlo ? "-bc_zlo_velocity" : "-bc_zhi_velocity", "the shear cell shears along x: the y and z velocities must be 0");
  }
  if (c.bc.velocity[kZlo].x == c.bc.velocity[kZhi].x)
    failOption("-bc_zhi_velocity", "walls that do not shear: the x velocities of -bc_zlo_velocity and -bc_zhi_velocity must differ");
}

void RheologyConfig::validateCell(const Config& c, const ParticleStore& s, MPI_Comm comm) const
{
  if (!on) return;
  const double diameter = meanDiameter(s, comm);
  if (!(diameter > 0)) return;
  const double gap = c.grid.hi[2] - c.grid.lo[2];
  if (gap < 4 * diameter)
    failOption("-rheology_monitor", "the shear cell's gap (-grid_lo, -grid_hi along z) is " + formatNumber(gap / diameter) +
                                        " mean diameters: at least 4 are needed (15-20 keep the core free of the walls' layers)");
  if (gap - 2 * margin * diameter < diameter)
    failOption("-rheology_margin", "leaves a core thinner than a diameter in a gap of " + formatNumber(gap / diameter) +
                                       " mean diameters: at most " + formatNumber(0.5 * (gap / diameter - 1)));
}

RheologyMonitor::RheologyMonitor(const Grid& grid, const Config& c, const RheologyConfig& cfg, DemSolver& dem,
                                 Penalization& pen, const std::string& dir, double resumeAfter)
  : grid_(grid), c_(c), dem_(dem), pen_(pen)
{
  const MPI_Comm comm = grid.comm();
  const ParticleStore& s = dem.particles();
  const double d = meanDiameter(s, comm), h = grid.h(2);
  gamma_ = (c.bc.velocity[kZhi].x - c.bc.velocity[kZlo].x) / (grid.hi(2) - grid.lo(2));
  kA_ = static_cast<PetscInt>(std::ceil(cfg.margin * d / h - 0.5));
  kB_ = static_cast<PetscInt>(std::floor((grid.hi(2) - grid.lo(2) - cfg.margin * d) / h - 0.5));
  pen.enableStresslets(grid.cellCentre(2, kA_), grid.cellCentre(2, kB_));
  dem.pairStress().enable(grid.cellCentre(2, kA_), grid.cellCentre(2, kB_));
  double sums[2] = {0, 0};  // the free particles' volume, fixed particles in the core
  for (std::size_t i = 0; i < s.nOwned; ++i) {
    sums[0] += s.fixed(i) ? 0 : s.shape(i).volume();
    sums[1] += s.fixed(i) && s.x[i].z >= grid.cellCentre(2, kA_) && s.x[i].z <= grid.cellCentre(2, kB_);
  }
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm);
  const double volume = sums[0];
  // A fixed particle counts as part of the wall on its side: one in the core is an obstacle that
  // takes force out of the layer whose stress is measured.
  if (sums[1] > 0)
    PetscPrintf(comm, "vpsolve: warning: -rheology_monitor: %.0f fixed particles lie in the core; its bulk stress no longer "
                      "balances the wall traction\n", sums[1]);
  phi_ = volume / ((grid.hi(0) - grid.lo(0)) * (grid.hi(1) - grid.lo(1)) * (grid.hi(2) - grid.lo(2)));
  csv_ = std::make_unique<CsvWriter>(comm, dir + "/rheology.csv",
                                     std::vector<std::string>{"time", "strain", "phi", "eta_r", "eta_r_bulk", "n1", "n2", "eta_hydro",
                                                              "eta_lub", "eta_contact", "eta_r_bottom", "eta_r_top", "core_rate", "phi_core"},
                                     resumeAfter);
}

void RheologyMonitor::start(const RunView&)
{
  // No row for the initial state: the sums start with the first step.
  dem_.pairStress().take(grid_.comm());
  pen_.takeStresslets();
}

void RheologyMonitor::record(const RunView& run)
{
  const Grid& g = grid_;
  const MPI_Comm comm = g.comm();
  const PetscInt nz = g.n(2);
  const double h = g.h(2), area = (g.hi(0) - g.lo(0)) * (g.hi(1) - g.lo(1));
  // Plane means of u_x (every z) and the Reynolds stress of the core, sum of u_x u_z at cell centres.
  std::vector<double> sums(nz + 1, 0.0);
  {
    FaceArray u(g.faceDM(), run.fluid->velocityLocal(), true);
    for (PetscInt k = g.start(2); k < g.end(2); ++k)
      for (PetscInt j = g.start(1); j < g.end(1); ++j)
        for (PetscInt i = g.start(0); i < g.end(0); ++i) {
          sums[k] += u.a[k][j][i][0];
          if (k >= kA_ && k < kB_)
            sums[nz] += 0.25 * (u.a[k][j][i][0] + u.a[k][j][i + 1][0]) * (u.a[k][j][i][2] + u.a[k + 1][j][i][2]);
        }
  }
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), nz + 1, MPI_DOUBLE, MPI_SUM, comm);
  const double perPlane = double(g.n(0)) * g.n(1);
  auto mean = [&](PetscInt k) { return sums[k] / perPlane; };
  const double mu = c_.fluid.mu, scale = mu * gamma_;
  const double uLo = c_.bc.velocity[kZlo].x, uHi = c_.bc.velocity[kZhi].x;
  // The wall's viscous stress from the no-slip ghost u_g = (8 U - 6 u_0 + u_1) / 3 (grid/Boundary.cpp).
  const PairStress::Mean pairs = dem_.pairStress().take(comm);
  // The walls' forces on the particles: contacts and lubrication with the flat wall and with the
  // fixed particles on its side (a rough wall), less the liquid's force on those fixed particles.
  const ParticleStore& s = dem_.particles();
  double liquidOnFixed[6] = {0, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < s.nOwned; ++i)
    if (s.fixed(i)) liquidOnFixed[dem_.pairStress().wallOf(s.x[i].z)] += s.fhyd[i].x;
  MPI_Allreduce(MPI_IN_PLACE, liquidOnFixed, 6, MPI_DOUBLE, MPI_SUM, comm);
  auto wallForce = [&](int f) {
    return pairs.walls[PairStress::Contact][f].x + pairs.walls[PairStress::Lubrication][f].x - liquidOnFixed[f];
  };
  const double bottom = mu * (9 * mean(0) - mean(1) - 8 * uLo) / (3 * h) - wallForce(kZlo) / area;
  const double top = mu * (8 * uHi - 9 * mean(nz - 1) + mean(nz - 2)) / (3 * h) + wallForce(kZhi) / area;
  // The core from the centre of cell kA to that of kB.
  const double thickness = (kB_ - kA_) * h, volume = area * thickness;
  const double rate = (mean(kB_) - mean(kA_)) / thickness;
  // The core's own solid fraction (the layers at the walls order the spheres at other fractions).
  const double zA = g.cellCentre(2, kA_), zB = g.cellCentre(2, kB_);
  double solid = 0;
  for (std::size_t i = 0; i < s.nOwned; ++i)
    solid += s.shape(i).volumeBetween(toBody(s.q[i], Vec3{0, 0, 1}), zA - s.x[i].z, zB - s.x[i].z);
  MPI_Allreduce(MPI_IN_PLACE, &solid, 1, MPI_DOUBLE, MPI_SUM, comm);
  const double reynolds = -c_.fluid.rho * sums[nz] * g.cellVolume() / volume;
  SymTensor stresslets = pen_.takeStresslets();
  MPI_Allreduce(MPI_IN_PLACE, stresslets.data(), 6, MPI_DOUBLE, MPI_SUM, comm);
  SymTensor particle;
  for (int m = 0; m < 6; ++m)
    particle[m] = (stresslets[m] - pairs.pairs[PairStress::Contact][m] - pairs.pairs[PairStress::Lubrication][m]) / volume;
  constexpr int xx = 0, yy = 1, zz = 2, xz = 4;
  const double hydro = (mu * rate + stresslets[xz] / volume + reynolds) / scale;
  const double lub = -pairs.pairs[PairStress::Lubrication][xz] / volume / scale;
  const double contact = -pairs.pairs[PairStress::Contact][xz] / volume / scale;
  csv_->row({run.time, gamma_ * run.time, phi_, 0.5 * (bottom + top) / scale, hydro + lub + contact,
             (particle[xx] - particle[zz]) / scale, (particle[zz] - particle[yy]) / scale, hydro, lub, contact, bottom / scale,
             top / scale, rate / gamma_, solid / volume});
}

} // namespace vp
