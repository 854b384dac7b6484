#pragma once
// Point-particle model of a sphere moving normal to a plane wall (Harada et al. 2001, "Model H";
// docs/lubrication.md section 5), the reference trajectory for the resolved simulations. The wall is y = 0, the
// sphere centre at height y > a, velocity v = dy/dt. Forces along y:
//   buoyant weight  (m - m_f) g
//   drag            -3 pi mu d (1 + 0.15 Re^0.687) v                 (Schiller & Naumann)
//   lubrication     -6 pi mu a v / eps  down to the roughness gap eps_col, zero in contact
//   added mass      -(m' dv/dt + (1/2) (dm'/dt) v),  m' = (2/3) pi rho a^3 C(eps) (image series)
//   history         -6 a^2 sqrt(pi rho mu) int_0^t v'(s) / sqrt(t - s) ds  (Basset, from rest);
//                   optionally left out from a contact until the gap opens past historyWindow
//   contact         k_n delta - gamma_n v while delta = h_col - h > 0 (linear spring-dashpot,
//                   docs/particles.md, m* = m, roughness gap h_col)
// Each term can be switched off. Time stepping: semi-implicit Euler with fixed dt; every term
// linear in v^{n+1} (drag with lagged Re, lubrication, added mass, the newest Basset increment,
// contact damping) is implicit, position-dependent terms are taken at y^n, then y^{n+1} = y^n +
// dt v^{n+1}. First order; the contact spring is resolved with dt <= t_c / 30.
#include "vp/interactions/BassetHistory.hpp"

namespace vp {

struct HaradaParams {
  double fluidDensity = 985;       // rho [kg/m^3]
  double viscosity = 0.142;        // mu [Pa s]
  double radius = 0.0127;          // a [m]
  double particleDensity = 1127;   // rho_p [kg/m^3]
  double gravity = -9.781;         // acceleration along y (the wall normal) [m/s^2]
  bool drag = true;
  bool lubrication = true;
  bool addedMass = true;
  bool imageSeries = true;         // wall effect on the added mass (else C = 1)
  bool history = true;
  bool contact = true;
  double restitution = 0.97;       // dry restitution xi_n
  double contactTime = 2.5e-3;     // t_c [s]
  double roughness = 2e-4;         // roughness gap h_col as a fraction of the diameter
  double dt = 5e-5;                // [s]
  // Gap [m] up to which the history force is left out from a contact on the way out, or until the
  // sphere turns back (0: never; below the roughness gap: the contact only): a resolved run that
  // excludes its hydrodynamic force over such a window (docs/collisions.md) also loses the history
  // force there; the velocity history itself is still recorded. Needs history and contact.
  double historyWindow = 0;
};

// Force terms along y at the last step [N]; the hydrodynamic force is all but weight and contact.
struct HaradaForces {
  double weight = 0, drag = 0, lubrication = 0, addedMass = 0, history = 0, contact = 0;
  double hydrodynamic() const { return drag + lubrication + addedMass + history; }
};

class HaradaModel {
public:
  HaradaModel(const HaradaParams& p, double height, double velocity);

  void step();

  double time() const { return time_; }
  double height() const { return y_; }
  double velocity() const { return v_; }
  double gap() const { return y_ - p_.radius; }
  const HaradaForces& forces() const { return forces_; }

  double mass() const { return mass_; }
  double bulkAddedMass() const { return addedMass0_; } // (2/3) pi rho a^3
  double stiffness() const { return stiffness_; }
  double damping() const { return damping_; }

private:
  HaradaParams p_;
  double mass_, addedMass0_, stiffness_, damping_;
  double time_ = 0, y_, v_;
  BassetHistory basset_;
  HaradaForces forces_;
  bool inHistoryWindow_ = false;
};

} // namespace vp
