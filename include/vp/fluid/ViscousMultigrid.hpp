#pragma once
// A geometric multigrid V-cycle for the viscous operator S (1 + theta) - a S L on the face grid: the
// preconditioner of the fused CG with -velocity_mg_levels > 1 (docs/fluid.md, viscous solve).
// Each coarser grid halves every axis (Grid::Coarsen) and rediscretises the operator there (its own
// DiffusionSolver: the same sweep, h doubled) with theta averaged from the finer grid. The
// transfers follow the staggering: along a face's normal the coarse face sits on every second fine
// face (full weighting 1/4 1/2 1/4, linear interpolation back), across it a coarse face covers two
// fine ones (average, injection back), so the restriction is the prolongation's transpose / 8. The
// smoother is damped Jacobi, the same sweep before and after the coarse correction, and the coarsest
// grid gets a fixed number of Jacobi sweeps: the cycle is a symmetric positive definite operator, as
// CG needs. The coarse grids remove the smooth error Jacobi leaves, so the iterations stay at 5-7
// as nu dt / h^2 grows; one iteration costs 2.5-3 Jacobi ones, so it pays only where nu dt / h^2
// is tens (measured in docs/fluid.md).
#include "vp/core/Config.hpp"
#include "vp/grid/Grid.hpp"
#include <memory>
#include <petscvec.h>
#include <vector>

namespace vp {

class DiffusionSolver;

class ViscousMultigrid {
public:
  // fine: the solver whose operator is preconditioned (its grid is level 0). levels: the most
  // levels wanted (>= 2); fewer where a grid cannot be halved (Grid::coarsenable).
  ViscousMultigrid(const DiffusionSolver& fine, const Grid& grid, const BoundaryConfig& bc, int levels);
  ~ViscousMultigrid();
  ViscousMultigrid(const ViscousMultigrid&) = delete;
  ViscousMultigrid& operator=(const ViscousMultigrid&) = delete;

  int levels() const { return static_cast<int>(levels_.size()); }
  // The coarse operators for a = nu dt / 2 and the fine theta (null: none).
  void setOperator(double a, Vec theta);
  // z = M r for a fine r (global layout, zero on the fixed wall faces); z in the fine solver's
  // local layout (owned values; its fixed wall faces hold rounding-size values until a ghost
  // refresh zeroes them). Returns this rank's part of r.z.
  double apply(Vec r, Vec z);

  // The transfers between level `fine` and the next coarser one. restrictTo: fine (local, ghosts
  // current) -> coarse (global) by the staggered full weighting, the coarse fixed wall faces zero.
  // prolongAdd: fine (local) += P coarse (local, ghosts current).
  void restrictTo(size_t fine, Vec fineLocal, Vec coarseGlobal) const;
  void prolongAdd(size_t fine, Vec coarseLocal, Vec fineLocal) const;
  const Grid& grid(size_t l) const { return *levels_[l].grid; }
  const DiffusionSolver& op(size_t l) const { return *levels_[l].op; }

  static constexpr double kOmega = 0.8;     // Jacobi damping (the operator's D^-1 A lies in (0, 2))
  static constexpr int kCoarsestSweeps = 6;  // Jacobi sweeps on the coarsest grid

private:
  struct Level {
    const Grid* grid = nullptr;
    const DiffusionSolver* op = nullptr;
    std::unique_ptr<Grid> ownGrid;               // coarse levels
    std::unique_ptr<DiffusionSolver> ownOp;      // coarse levels
    Vec b = nullptr, theta = nullptr;                 // global: right-hand side, theta (coarse levels)
    Vec x = nullptr, x2 = nullptr, rL = nullptr;      // local: iterate and the next, residual (its ghosts feed the restriction)
    Vec thetaL = nullptr;                             // local theta of a finer level (restricted)
  };
  // V(b) on level l: into out if given (level 0, never the coarsest; returns b.out), else into the
  // level's x.
  double cycle(size_t l, Vec out);

  std::vector<Level> levels_;
};

} // namespace vp
