#pragma once
// The particle layer: soft-sphere DEM with friction on the grid's domain decomposition.
// Simulation calls advance(t, dt) once per fluid step (M = -dem_substeps velocity-Verlet sub-steps
// of dt/M, with the hydrodynamic force and torque in particles().fhyd/thyd held fixed), and
// diagnostics() for diagnostics.csv. With -fluid_off, dt is the DEM step and fhyd/thyd are ignored.
#include "vp/core/Config.hpp"
#include "vp/core/StateArchive.hpp"
#include "vp/coupling/LubricationPatches.hpp"
#include "vp/grid/Grid.hpp"
#include "vp/interactions/ContactModel.hpp"
#include "vp/particles/CellBuckets.hpp"
#include "vp/particles/ContactHandOff.hpp"
#include "vp/particles/Exchange.hpp"
#include "vp/particles/PairList.hpp"
#include "vp/particles/PairStress.hpp"
#include "vp/particles/ParticleConfig.hpp"
#include "vp/particles/ParticleStore.hpp"
#include "vp/particles/Walls.hpp"
#include <algorithm>
#include <cmath>
#include <memory>

namespace vp {

struct DemDiagnostics {
  double kineticEnergy = 0;   // translational + rotational [J]
  long particles = 0;
  long contacts = 0;          // sphere-sphere pairs in contact
  long wallContacts = 0;      // sphere-wall contacts
};

// The deepest contact since it was last taken: overlap / smaller diameter, the particle ids (a
// wall as -1 - face index).
struct OverlapRecord {
  double fraction = 0;
  std::int64_t i = -1, j = -1;
};

class DemSolver {
public:
  // Particles from the options (-particles_file, generators, single particle).
  DemSolver(const Grid& grid, const Config& c, const ParticleConfig& pc);
  // Particles given as one global list, identical on every rank (tests, restart: loadParticles). restart: the
  // records carry the forces of their last sub-step and their contact springs: keep them.
  DemSolver(const Grid& grid, const Config& c, const ParticleConfig& pc, const std::vector<ParticleRecord>& all,
            bool restart = false);

  // One fluid step [t, t + dt]: -dem_substeps sub-steps. Collective.
  void advance(double t, double dt);

  // Its part of a checkpoint: this rank's particles with their contact springs
  // (particles/ParticleCheckpoint.hpp; a restart gives loadParticles' list to the constructor).
  // Collective.
  void saveState(StateWriter& w);
  ParticleStore& particles() { return store_; }
  const ParticleStore& particles() const { return store_; }
  // Collective: global sums over owned particles.
  DemDiagnostics diagnostics() const;
  // A stable DEM step: the shortest contact duration / 50, within the lubrication bound (collective).
  double suggestedStep() const;
  // Longest fluid step the lubrication dashpot allows with -dem_substeps (infinite without one).
  double lubricationStepLimit() const { return lubStableSubstep_ * pc_.substeps; }
  int substeps() const { return pc_.substeps; }  // -dem_substeps
  ParticleExchange& exchange() { return *exchange_; }
  // Collective: ghosts get the owners' current x, v, omega, q (the last sub-step sends predicted
  // velocities); the fluid coupling builds its mask from them.
  void syncGhosts() { exchange_->updateGhosts(store_); }
  const ContactLaw& law() const { return law_; }
  // The pairs' and walls' share of the stress, summed over the sub-steps once enabled (rheology).
  PairStress& pairStress() { return stress_; }
  std::size_t rebuilds() const { return rebuilds_; }
  // Kinetic energy of this rank's free particles after the last sub-step (0 before any).
  double localKineticEnergy() const { return std::max(kineticEnergy_, 0.0); }
  // This rank's deepest contact since the last call (the health check reads it once per step).
  OverlapRecord takeLargestOverlap();
  // -lub_coupling replace: the pairs whose gap patches the step's resolved force left out get the
  // whole model force (coupling/LubricationPatches.hpp); found by the coupling each fluid step.
  void setPatches(const LubricationPatches* patches) { patches_ = patches; }

private:
  void setUp(const std::vector<ParticleRecord>& all, bool restart);
  void substep(double dt);
  template <bool Hydro>
  void substep(double dt);
  bool needRebuild() const;
  void rebuild();
  void addStokesDrag();
  // -lub_integration implicit: the squeezing pairs of the sub-step (wall < 0: sphere j; else that
  // wall face), their resistance c, the normal n from i to the partner, d = x_i - x_j for the stress.
  struct SqueezePair {
    std::size_t i, j;
    int wall;
    double c;
    Vec3 n, d;
  };
  void solveSqueeze(double dt);
  void addSqueezeStress();
  void computeForces(double dt);
  bool nearWall(const Vec3& x, double reach) const;
  int spheroidWalls(std::size_t i, Vec3& F, Vec3& T, double dt);
  // One side of a gap with a non-sphere: the surface point nearest the partner and the point the
  // gap's forces act at, from its centre in space; its motion; its shape and orientation (none: a
  // wall, a flat half-space).
  struct GapSide {
    Vec3 point, lever, v, w;
    const Shape* shape = nullptr;
    Quaternion q;
  };
  PairForce gapForce(const GapSide& i, const GapSide& j, const Vec3& n, double gap, double contactGap, double scale,
                     const ContactCoefficients* law, Vec3& spring, bool leaving, bool slip, double invMassSum, double dt,
                     bool& touching);
  bool shapedPair(std::size_t k, double dt);
  void checkShapes(const std::vector<ParticleRecord>& all) const;
  // m v^2 + w . I w of a non-sphere
  double twiceKinetic(std::size_t i) const;
  // Largest c (1/m_i + 1/m_j) of the saturated normal lubrication over the particle classes of
  // `all` and the walls [1/s].
  double lubricationRate(const std::vector<ParticleRecord>& all) const;
  double shapedLubricationRate(const std::vector<ParticleRecord>& all) const;
  // Sub-steps per fluid step that keep the saturated lubrication stable at sub-step dtp.
  long requiredSubsteps(double dtp) const;
  // With a sub-step beyond the bound: the largest c (1/m_i + 1/m_j) a lubricating pair reaches
  // (recorded in the force loop), and the collective check after the fluid step (InputError
  // naming the options once a pair is unstable).
  // scale: the length of the activation and saturation gaps (lubricationForce's; 0: the smaller radius).
  void watchLubrication(const PairState& st, double contactGap, double invMassSum, double scale = 0);
  void checkLubricationSeen(double dtp);
  void noteOverlap(double fraction, std::int64_t i, std::int64_t j)
  {
    if (fraction > largestOverlap_.fraction) largestOverlap_ = {fraction, i, j};
  }

  const Grid& grid_;
  ParticleConfig pc_;
  ContactLaw law_;
  LubricationParams lub_;  // model none: no lubrication pairs
  double mu_ = 0;          // fluid viscosity seen by the lubrication kernels [Pa s]
  double rho_ = 0;         // fluid density (the gap's inertia at a wall, -lub_inertia) [kg/m^3]
  double lubGap_ = 0;      // largest activation or departure gap [m]
  double lubStableSubstep_ = HUGE_VAL;  // sub-step bound of the saturated lubrication dashpot [s]
  bool lubWatch_ = false;               // the sub-step exceeds it: watch the pairs
  double lubRateSeen_ = 0;              // largest c (1/m_i + 1/m_j) seen since the last check [1/s]
  Vec3 gravity_;
  std::array<Wall, 6> walls_;
  void relax(std::size_t i, double half, Vec3& v, Vec3& w) const;
  bool hydro_;             // a fluid sets fhyd/thyd (without one the kicks skip them)
  double drag_;                     // -dem_implicit_drag
  const LubricationPatches* patches_ = nullptr;
  ContactHandOff handOff_;          // -contact_hydro and its departure and history (keep in DEM-only runs)
  std::vector<int> activeWalls_;
  Vec3 wallLo_, wallHi_;   // wall planes per axis (+-infinity on periodic axes)
  double skin_ = 0;        // neighbour-list skin [m]
  double rmax_ = 0;     // the largest bounding radius
  bool shaped_ = false;  // a non-sphere among the particles: its orientation is integrated
  std::unique_ptr<ParticleExchange> exchange_;
  ParticleStore store_;
  CellBuckets buckets_;
  PairList pairs_;
  long contacts_ = 0, wallContacts_ = 0;
  double kineticEnergy_ = -1;   // of the owned particles after the last sub-step (-1: none yet)
  std::size_t rebuilds_ = 0;
  OverlapRecord largestOverlap_;
  PairStress stress_;
  std::vector<SqueezePair> squeezePairs_;
};

} // namespace vp
