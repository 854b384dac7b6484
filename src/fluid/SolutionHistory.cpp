#include "vp/fluid/SolutionHistory.hpp"
#include "vp/core/Error.hpp"
#include "vp/core/VecValues.hpp"
#include <algorithm>
#include <cmath>
#include <string>

namespace vp {

namespace {

// a . b summed in a fixed order (PETSc's dot kernels may group differently from call to call,
// and the Gram matrix of a restarted run must equal the uninterrupted one's bit for bit).
double dot(Vec a, Vec b)
{
  PetscInt n;
  VP_CALL(VecGetLocalSize(a, &n));
  double s = 0;
  {
    ReadValues pa(a), pb(b);
    for (PetscInt i = 0; i < n; ++i) s += pa[i] * pb[i];
  }
  MPI_Comm comm;
  VP_CALL(PetscObjectGetComm(reinterpret_cast<PetscObject>(a), &comm));
  MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPI_DOUBLE, MPI_SUM, comm);
  return s;
}

std::string storedName(int i) { return "pressure_history_" + std::to_string(i); }

} // namespace

SolutionHistory::SolutionHistory(Mat A, Vec like, int capacity)
    : A_(A), capacity_(capacity), x_(capacity), ax_(capacity), gram_(capacity * capacity, 0.0)
{
  for (int i = 0; i < capacity; ++i) {
    VP_CALL(VecDuplicate(like, &x_[i]));
    VP_CALL(VecDuplicate(like, &ax_[i]));
  }
}

SolutionHistory::~SolutionHistory()
{
  for (int i = 0; i < capacity_; ++i) {
    VecDestroy(&x_[i]);
    VecDestroy(&ax_[i]);
  }
}

void SolutionHistory::add(Vec x)
{
  if (capacity_ == 0) return;
  if (count_ == capacity_) {
    // Drop the oldest: its vectors take the newest place, the Gram matrix moves up and left.
    std::rotate(x_.begin(), x_.begin() + 1, x_.end());
    std::rotate(ax_.begin(), ax_.begin() + 1, ax_.end());
    for (int i = 1; i < capacity_; ++i)
      for (int j = 1; j < capacity_; ++j) gram(i - 1, j - 1) = gram(i, j);
    --count_;
  }
  const int k = count_++;
  VP_CALL(VecCopy(x, x_[k]));
  VP_CALL(MatMult(A_, x_[k], ax_[k]));
  for (int i = 0; i <= k; ++i) gram(i, k) = gram(k, i) = dot(ax_[k], ax_[i]);
}

void SolutionHistory::start(Vec b, Vec x)
{
  VP_CALL(VecSet(x, 0));
  const int m = count_;
  if (m == 0) return;
  // Least squares by the normal equations G c = (A x_i . b), G = L D L^T factored oldest first;
  // a product within 1e-5 rad of the span of the older ones (D_kk below 1e-10 G_kk: successive
  // solutions are nearly parallel in a slow flow) is left out of the fit.
  std::vector<double> l(m * m, 0.0), d(m), c(m);
  for (int k = 0; k < m; ++k) {
    for (int i = k; i < m; ++i) {
      double v = gram(i, k);
      for (int j = 0; j < k; ++j) v -= l[i * m + j] * l[k * m + j] * d[j];
      l[i * m + k] = v;  // L_ik D_kk for now
    }
    d[k] = l[k * m + k];
    const bool kept = d[k] > 1e-10 * gram(k, k);
    for (int i = k; i < m; ++i) l[i * m + k] = kept ? l[i * m + k] / d[k] : 0.0;
    if (!kept) d[k] = 0;
  }
  for (int i = 0; i < m; ++i) {  // L y = rhs, then c = D^-1 y, then L^T c = c
    c[i] = dot(ax_[i], b);
    for (int j = 0; j < i; ++j) c[i] -= l[i * m + j] * c[j];
  }
  for (int i = 0; i < m; ++i) c[i] = d[i] > 0 ? c[i] / d[i] : 0.0;
  for (int i = m - 1; i >= 0; --i)
    for (int j = i + 1; j < m; ++j) c[i] -= l[j * m + i] * c[j];
  VP_CALL(VecMAXPY(x, m, c.data(), x_.data()));
}

void SolutionHistory::save(StateWriter& w) const
{
  for (int i = 0; i < count_; ++i) w.vector(storedName(i), x_[i]);
}

void SolutionHistory::load(const StateReader& r)
{
  if (capacity_ == 0) return;
  int stored = 0;
  while (r.has(storedName(stored))) ++stored;
  Vec v;
  VP_CALL(VecDuplicate(x_[0], &v));
  for (int i = std::max(0, stored - capacity_); i < stored; ++i) {
    r.vector(storedName(i), v);
    add(v);
  }
  VecDestroy(&v);
}

} // namespace vp
