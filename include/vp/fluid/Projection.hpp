#pragma once
// One fluid step of the incremental scalar projection (docs/fluid.md, time step):
//   du = u* - u^n:  (I - nu dt/2 L) du = dt [ -(AB2 N) + nu L u^n - grad p^n / rho + f ]
//   A psi = -div u*  (A = -lap_h),  u = u* - grad psi,  p^{n+1} = p^n + rho psi / dt
// AB2 with variable steps (Euler on the first step), Crank-Nicolson diffusion. The pressure is the
// dynamic pressure: gravity on a constant-density fluid is balanced by its hydrostatic part.
// Weighted (with particles, -penalization_projection weighted): the predictor's implicit
// penalization (1 + theta) du = ... is completed by -div(beta grad psi) = -div u*, u = u* - beta grad
// psi, beta = 1/(1 + theta) per face: together they solve the penalized step with the new pressure
// (the plain projection corrects the solid's faces as freely as the fluid's, and the next predictor
// undoes it there).
#include "vp/core/Config.hpp"
#include "vp/core/StateArchive.hpp"
#include "vp/fluid/DiffusionSolver.hpp"
#include "vp/fluid/Operators.hpp"
#include "vp/fluid/PressureSolver.hpp"

namespace vp {

struct StepStats {
  int pressureIterations = 0;
  int velocityIterations = 0;
};

class Projection {
public:
  // weighted: the projection of the penalized step (predict's theta), -penalization_projection weighted.
  Projection(const Grid& grid, const Config& cfg, const SolverOptions& solvers, bool weighted = false);
  ~Projection();
  Projection(const Projection&) = delete;
  Projection& operator=(const Projection&) = delete;

  // Advances u and p by dt (predictor, diffusion, pressure projection). Call finishStep() after
  // it to refresh ghosts and statistics.
  StepStats step(double dt);
  // The two halves of step(): the predictor u* (convection, diffusion, old pressure gradient and,
  // when given, the implicit penalization theta (u_s - u*), theta = chi lambda dt, thetaUs =
  // theta u_s) and the projection of u* (returns the pressure iterations).
  StepStats predict(double dt, Vec theta = nullptr, Vec thetaUs = nullptr);
  int project(double dt);
  // Imposes the boundary values on u (fixed wall faces) after it was set from outside, e.g. an
  // initial condition, then refreshes ghosts and statistics.
  void applyBoundaryConditions();
  // Ghost update of the final velocity and its statistics (divergence, energy, CFL rate).
  const ops::FieldStats& finishStep();
  const ops::FieldStats& stats() const { return stats_; }

  Vec velocity() const { return u_; }      // faceDM global
  bool weighted() const { return weighted_; }  // -penalization_projection weighted
  Vec pressure() const { return p_; }      // cellDM global
  Vec velocityLocal() const { return uL_; } // faceDM local, ghosts valid after finishStep()
  const Grid& grid() const { return grid_; }
  // Its part of a checkpoint (collective): u, p, the last step's convection term, the last pressure
  // and velocity increments (the next solves' starts; the one before when two were solved) and the
  // pressure solutions the next starts are fitted from. loadState takes the last step's length
  // (variable-step AB2) from the run's counters, then refreshes ghosts and statistics.
  void saveState(StateWriter& w) const;
  void loadState(const StateReader& r, double previousDt);
  double previousDt() const { return dtOld_; }
  PressureSolver& pressureSolver() { return pressure_; }
  const PressureSolver& pressureSolver() const { return pressure_; }
  DiffusionSolver& diffusionSolver() { return diffusion_; }

private:
  const Grid& grid_;
  const BoundaryConfig bc_;
  const double rho_, nu_;
  const Vec3 force_;
  DiffusionSolver diffusion_;
  PressureSolver pressure_;
  const bool weighted_;
  Vec u_, p_, uL_, pL_, N_, Nold_, rhs_, du_, duOld_, div_, psi_, psiL_;
  Vec theta_ = nullptr, betaL_ = nullptr;  // weighted: predict's theta, 1/(1 + theta) with ghosts
  double dtOld_ = 0;
  int increments_ = 0;
  ops::FieldStats stats_;
};

} // namespace vp
