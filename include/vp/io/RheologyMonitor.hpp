#pragma once
// The stress of a sheared suspension, measured by the run (-rheology_monitor; docs/rheology.md).
// The shear cell: walls at z = lo and hi moving along x (-bc_zlo velocity, -bc_zhi velocity with
// different x velocities), periodic along x and y; shear rate gamma = (U_hi - U_lo) / L_z.
// rheology.csv gets one row per time-series step, every stress over mu gamma:
//   eta_r       the wall traction: the fluid's viscous stress at the wall plus the walls' contact and
//               lubrication forces on the particles, per area, the mean of the two walls; fixed
//               particles belong to the wall on their side (a rough wall): the forces of the liquid
//               and of the free particles on them count
//   eta_r_bulk  the bulk stress of the core (the slab more than -rheology_margin mean diameters from
//               either wall) = eta_hydro + eta_lub + eta_contact:
//   eta_hydro   the fluid's mean viscous stress 2 mu <E_xz> over the core, the particles' stresslets
//               (first moment of the penalization force density, centres in the core) and the
//               fluid's Reynolds stress -rho <u_x u_z>
//   eta_lub, eta_contact  the pair stresses -(1/V) sum r_ij F_ij (midpoints in the core)
//   n1, n2      (S_xx - S_zz) and (S_zz - S_yy) of the core's particle stress (stresslets and pairs)
//   core_rate   the core's mean shear rate over gamma (below 1: the walls' layers shear more)
//   phi_core    the solid fraction of the core (the parts of the particles between its planes)
// The pair sums are means over the DEM sub-steps since the last row, the stresslets over the fluid
// steps, the fluid terms the present field.
#include "vp/core/Config.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/io/CsvWriter.hpp"
#include "vp/io/Monitor.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include "vp/particles/ParticleStore.hpp"
#include <memory>
#include <string>

namespace vp {

class DemSolver;
class Penalization;

// -rheology_monitor, -rheology_margin.
struct RheologyConfig {
  bool on = false;
  double margin = 2;  // core: this many mean diameters away from each wall

  static RheologyConfig read();
  void validate(const Config& c, const ParticleConfig& pc) const;  // throws InputError
  // Once the particles are known: a gap of at least 4 mean diameters and a core at least one thick
  // (throws InputError on every rank). Collective.
  void validateCell(const Config& c, const ParticleStore& s, MPI_Comm comm) const;
};

class RheologyMonitor : public Monitor {
public:
  // Enables the pair and stresslet sums over the core. resumeAfter >= 0 (a restart): continue
  // rheology.csv after the row of that time.
  RheologyMonitor(const Grid& grid, const Config& c, const RheologyConfig& cfg, DemSolver& dem, Penalization& pen,
                  const std::string& dir, double resumeAfter = -1);
  void start(const RunView& run) override;
  void record(const RunView& run) override;

private:
  const Grid& grid_;
  Config c_;
  DemSolver& dem_;
  Penalization& pen_;
  std::unique_ptr<CsvWriter> csv_;
  double gamma_ = 0;            // nominal shear rate [1/s]
  PetscInt kA_ = 0, kB_ = 0;    // the core: from the centre of cell kA to that of cell kB
  double phi_ = 0;              // solid fraction of the free particles in the cell
};

} // namespace vp
