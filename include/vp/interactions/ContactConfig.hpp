#pragma once
// Soft-sphere contact parameters (docs/particles.md, contact model). Stiffness comes either from the
// contact time (-contact_tc or -contact_tc_steps, stiffness per pair mass) or directly (-contact_kn,
// -contact_kn_wall); the normal damping always gives the restitution -contact_restitution.
// Tangential: from a tangential restitution xi_t (-contact_restitution_t) with the tangential mass
// (2/7) m*, or, when it is not given, from the ratios k_t/k_n and gamma_t/gamma_n. Rolling
// resistance: a torque against the relative rolling (-contact_rolling_friction).

namespace vp {

// What the resolved (penalization) hydrodynamic force does while a particle is in contact
// (docs/lubrication.md, hand-off): kept, excluded (buoyancy stays), or excluded only while an
// overlap exceeds the one the particle's buoyant weight alone would cause.
enum class ContactHydro { Keep, Exclude, Limit };
const char* contactHydroName(ContactHydro h);

struct ContactConfig {
  double restitution = 0.9;   // normal restitution coefficient xi_n, (0, 1]
  double restitutionT = 0;    // tangential restitution xi_t, (0, 1]; 0: use ktRatio, gtRatio
  double friction = 0.25;     // Coulomb coefficient mu_c (sphere-sphere and sphere-wall)
  double tc = 0;              // contact time [s] (0: not set)
  double tcSteps = 0;         // contact time in fluid steps (0: not set)
  double kn = 0;              // sphere-sphere normal stiffness [N/m] (0: not set)
  double knWall = 0;          // sphere-wall normal stiffness [N/m] (0: same as kn)
  double ktRatio = 2.0 / 7.0; // k_t / k_n (without xi_t)
  double gtRatio = 0.5;       // gamma_t / gamma_n (without xi_t)
  double roughness = 0;       // contact starts at this surface gap, as a fraction of the diameter
  double rollingFriction = 0; // mu_r: rolling resistance torque mu_r R* k_n delta (0: none)
  double criticalLoad = 0;    // Coulomb friction only above this normal force [N] (0: always)
  ContactHydro hydro = ContactHydro::Limit;  // measured: docs/collisions.md
  // With Limit: a sphere leaving a wall or another sphere after an impact keeps its resolved force
  // excluded, and gets the lubrication correction from this gap, until its gap exceeds this many grid
  // cells (0: off).
  double departureCells = 0;
  // While the resolved force is excluded (exclude, limit, the departure): the Basset history force of
  // the particle's velocity changes since the exclusion began stands in for the resolved force's own
  // (docs/collisions.md).
  bool hydroHistory = false;

  bool stiffnessGiven() const { return tc > 0 || tcSteps > 0 || kn > 0; }
  // Throws InputError naming the option and the valid range.
  void validate() const;
};

} // namespace vp
