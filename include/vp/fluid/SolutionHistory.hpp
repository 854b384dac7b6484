#pragma once
// Starts for a sequence of solves A x = b with one operator (the pressure projection, step after
// step): Fischer's projection (P. F. Fischer, Comput. Methods Appl. Mech. Engrg. 163, 1998, in the
// form of PETSc's KSPGUESSFISCHER model 3). The start is x0 = sum_i c_i x_i over the last solutions,
// with c minimising |b - sum_i c_i A x_i|: never a worse residual than the last solution alone. The
// history is kept here rather than in PETSc's guess object so that a checkpoint holds it and a
// restart continues bit for bit: every stored number depends only on the stored solutions.
#include "vp/core/StateArchive.hpp"
#include <petscmat.h>
#include <vector>

namespace vp {

class SolutionHistory {
public:
  // Up to `capacity` solutions of vectors like `like`.
  SolutionHistory(Mat A, Vec like, int capacity);
  ~SolutionHistory();
  SolutionHistory(const SolutionHistory&) = delete;
  SolutionHistory& operator=(const SolutionHistory&) = delete;

  // x = the fitted start for b (zero while the history is empty).
  void start(Vec b, Vec x);
  // Remembers x and A x; the oldest solution goes when the history is full.
  void add(Vec x);
  int size() const { return count_; }
  int capacity() const { return capacity_; }
  Vec solution(int i) const { return x_[i]; }  // oldest first
  // Its part of a checkpoint: the solutions as pressure_history_<i>, oldest first (collective).
  void save(StateWriter& w) const;
  // Re-adds the stored solutions in order (the newest `capacity` of them): the history is then the
  // uninterrupted run's. Checkpoints older than the history hold none (collective).
  void load(const StateReader& r);

private:
  double& gram(int i, int j) { return gram_[i * capacity_ + j]; }
  Mat A_;
  int capacity_, count_ = 0;
  std::vector<Vec> x_, ax_;   // solutions and their products, oldest first
  std::vector<double> gram_;  // (A x_i) . (A x_j)
};

} // namespace vp
