#include "vp/fluid/Projection.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/Logging.hpp"
#include "vp/core/VecValues.hpp"
#include "vp/grid/Boundary.hpp"
#include "vp/grid/FieldArray.hpp"
#include <algorithm>
#include <cmath>

namespace vp {

namespace {

double norm2(Vec v)
{
  PetscReal n;
  VP_CALL(VecNorm(v, NORM_2, &n));
  return n;
}

} // namespace

Projection::Projection(const Grid& grid, const Config& cfg, const SolverOptions& solvers, bool weighted)
  : grid_(grid), bc_(cfg.bc), rho_(cfg.fluid.rho), nu_(cfg.fluid.nu()), force_(cfg.fluid.bodyForce),
    diffusion_(grid, cfg.bc, solvers.viscousOperator, solvers.viscousMgLevels), pressure_(grid, solvers, weighted), weighted_(weighted)
{
  DM f = grid.faceDM(), c = grid.cellDM();
  for (Vec* v : {&u_, &N_, &Nold_, &rhs_, &du_, &duOld_}) VP_CALL(DMCreateGlobalVector(f, v));
  for (Vec* v : {&p_, &div_, &psi_}) VP_CALL(DMCreateGlobalVector(c, v));
  VP_CALL(DMCreateLocalVector(f, &uL_));
  VP_CALL(DMCreateLocalVector(c, &pL_));
  VP_CALL(DMCreateLocalVector(c, &psiL_));
  for (Vec v : {u_, N_, Nold_, rhs_, du_, duOld_, p_, div_, psi_}) VP_CALL(VecSet(v, 0));
  if (weighted_) VP_CALL(DMCreateLocalVector(f, &betaL_));
}

Projection::~Projection()
{
  for (Vec* v : {&u_, &N_, &Nold_, &rhs_, &du_, &duOld_, &p_, &div_, &psi_, &uL_, &pL_, &psiL_, &betaL_}) VecDestroy(v);
}

StepStats Projection::step(double dt)
{
  StepStats st = predict(dt);
  st.pressureIterations = project(dt);
  return st;
}

StepStats Projection::predict(double dt, Vec theta, Vec thetaUs)
{
  const Grid& g = grid_;
  StepStats st;
  theta_ = theta;
  double uNorm = norm2(u_);
  {
    StageScope stage(Stage::Advection);
    // Ghosts of u^n are valid from finishStep() of the previous step (or of the initial state).
    // The Laplacian goes into rhs, which the combination below then overwrites in place.
    FaceArray u(g.faceDM(), uL_), N(g.faceDM(), N_), r(g.faceDM(), rhs_);
    ops::advectionAndLaplacian(g, u.a, N.a, r.a);
    VP_CALL(DMGlobalToLocal(g.cellDM(), p_, INSERT_VALUES, pL_));
    CellArray p(g.cellDM(), pL_);
    fillCellGhosts(g, p.a);
    // rhs = dt [ -(c1 N^n - c0 N^{n-1}) + nu L u^n + f ] - dt/rho grad p^n, zero on fixed faces.
    const double c0 = dtOld_ > 0 ? 0.5 * dt / dtOld_ : 0, c1 = 1 + c0;
    FaceArray Nold(g.faceDM(), Nold_);
    {
      // One pass over the owned faces, stored contiguously (3 values per face).
      const PetscInt k0 = g.start(2), j0 = g.start(1), i0 = g.start(0);
      const std::size_t n = 3 * std::size_t(g.end(0) - i0) * (g.end(1) - j0) * (g.end(2) - k0);
      PetscScalar* rp = &r.a[k0][j0][i0][0];
      const PetscScalar *np = &N.a[k0][j0][i0][0], *op = &Nold.a[k0][j0][i0][0];
      for (std::size_t q = 0; q < n; q += 3)
        for (int c = 0; c < 3; ++c)
          rp[q + c] = dt * (-(c1 * np[q + c] - c0 * op[q + c]) + nu_ * rp[q + c] + force_[c]);
      diffusion_.forFixedFaces([&](PetscInt o) { rp[o] = 0; });  // face 0 of a wall-bounded axis
    }
    ops::addGradient(g, p.a, -dt / rho_, r.a);
  }
  {
    StageScope stage(Stage::Diffusion);
    if (theta) {
      // Penalization in the same implicit solve: rhs += theta (u_s - u^n), so that a steady state
      // satisfies chi lambda (u - u_s) = the other momentum terms exactly (Brinkman), for any dt.
      PetscInt n;
      VP_CALL(VecGetLocalSize(rhs_, &n));
      ReadValues th(theta), ts(thetaUs), u(u_);
      WriteValues r(rhs_);
      for (PetscInt i = 0; i < n; ++i) r[i] += ts[i] - th[i] * u[i];
    }
    // The last two increments, rescaled to this step (du is about dt du/dt), extrapolated start the
    // solve: 13 % fewer iterations than the last one alone on the 64^3 cavity (docs/fluid.md).
    if (dtOld_ > 0 && dt != dtOld_) {
      VP_CALL(VecScale(du_, dt / dtOld_));
      VP_CALL(VecScale(duOld_, dt / dtOld_));
    }
    if (increments_ == 2) {
      VP_CALL(VecAXPBY(duOld_, 2.0, -1.0, du_));  // duOld = 2 du - duOld
      std::swap(du_, duOld_);                      // du = the extrapolation, duOld = the last increment
    } else {
      VP_CALL(VecCopy(du_, duOld_));
    }
    st.velocityIterations = diffusion_.solve(0.5 * nu_ * dt, rhs_, du_, 1e-14 * std::max(uNorm, norm2(rhs_)), theta);
    increments_ = std::min(increments_ + 1, 2);
    VP_CALL(VecAXPY(u_, 1.0, du_));  // u*
  }
  std::swap(N_, Nold_);
  dtOld_ = dt;
  return st;
}

int Projection::project(double dt)
{
  const Grid& g = grid_;
  int iterations;
  {
    StageScope stage(Stage::Pressure);
    VP_CALL(DMGlobalToLocal(g.faceDM(), u_, INSERT_VALUES, uL_));
    {
      FaceArray u(g.faceDM(), uL_);
      fillFaceGhosts(g, bc_, u.a);
      CellArray div(g.cellDM(), div_);
      ops::divergence(g, u.a, div.a);
    }
    VP_CALL(VecScale(div_, -1.0));
    const bool weighted = weighted_ && theta_;
    if (weighted) {
      // beta = 1/(1 + theta): the correction the penalized momentum equation allows on each face.
      VP_CALL(DMGlobalToLocal(g.faceDM(), theta_, INSERT_VALUES, betaL_));
      PetscInt n;
      VP_CALL(VecGetLocalSize(betaL_, &n));
      WriteValues b(betaL_);
      for (PetscInt q = 0; q < n; ++q) b[q] = 1 / (1 + b[q]);
    }
    if (weighted) pressure_.setFaceWeights(betaL_);  // after b releases the array
    double hmin = std::min({g.h(0), g.h(1), g.h(2)});
    iterations = pressure_.solve(div_, psi_, 1e-13 * norm2(u_) / hmin);
    VP_CALL(DMGlobalToLocal(g.cellDM(), psi_, INSERT_VALUES, psiL_));
    CellArray psi(g.cellDM(), psiL_);
    fillCellGhosts(g, psi.a);
    FaceArray u(g.faceDM(), u_);
    if (weighted) {
      FaceArray beta(g.faceDM(), betaL_, true);
      ops::addGradient(g, psi.a, -1.0, u.a, beta.a);
    } else {
      ops::addGradient(g, psi.a, -1.0, u.a);
    }
    VP_CALL(VecAXPY(p_, rho_ / dt, psi_));
  }
  return iterations;
}

void Projection::applyBoundaryConditions()
{
  const Grid& g = grid_;
  {
    FaceArray u(g.faceDM(), u_);
    for (int c = 0; c < 3; ++c) {
      if (!g.atLow(c)) continue;
      const double w = wallVelocity(bc_, 2 * c)[c];
      PetscInt lo[3] = {g.start(0), g.start(1), g.start(2)}, hi[3] = {g.end(0), g.end(1), g.end(2)};
      hi[c] = 1;  // the fixed face 0
      for (PetscInt k = lo[2]; k < hi[2]; ++k)
        for (PetscInt j = lo[1]; j < hi[1]; ++j)
          for (PetscInt i = lo[0]; i < hi[0]; ++i) u.a[k][j][i][c] = w;
    }
  }
  finishStep();
}

const ops::FieldStats& Projection::finishStep()
{
  VP_CALL(DMGlobalToLocal(grid_.faceDM(), u_, INSERT_VALUES, uL_));
  FaceArray u(grid_.faceDM(), uL_);
  fillFaceGhosts(grid_, bc_, u.a);
  stats_ = ops::stats(grid_, u.a);
  return stats_;
}

namespace {
const char* const kIncrementOld = "velocity_increment_old";
}

void Projection::saveState(StateWriter& w) const
{
  for (auto [name, v] : {std::pair<const char*, Vec>{"velocity", u_}, {"pressure", p_}, {"convection_old", Nold_},
                         {"pressure_increment", psi_}, {"velocity_increment", du_}})
    w.vector(name, v);
  if (increments_ == 2) w.vector(kIncrementOld, duOld_);
  if (const SolutionHistory* h = pressure_.history()) h->save(w);
}

void Projection::loadState(const StateReader& r, double previousDt)
{
  for (auto [name, v] : {std::pair<const char*, Vec>{"velocity", u_}, {"pressure", p_}, {"convection_old", Nold_},
                         {"pressure_increment", psi_}, {"velocity_increment", du_}})
    r.vector(name, v);
  // Checkpoints older than the second increment, or written after one solve, hold one at most.
  const bool two = r.has(kIncrementOld);
  if (two) r.vector(kIncrementOld, duOld_);
  increments_ = two ? 2 : previousDt > 0 ? 1 : 0;
  if (SolutionHistory* h = pressure_.history()) h->load(r);
  dtOld_ = previousDt;
  finishStep();
}

} // namespace vp
