#include "vp/fluid/FftPoisson.hpp"
#include <petsc/private/pcimpl.h>
#include <petscdmda.h>
#include <fftw3-mpi.h>
#include <cmath>
#include <cstring>
#include <vector>

namespace vp {

namespace {

constexpr char kTypeName[] = "fft";

struct Fft {
  double w[3] = {-1, -1, -1};  // operator weight per axis (x, y, z); negative: not given
  PetscInt plan = 0;           // 0 estimate, 1 measure
  ptrdiff_t n[3] = {0, 0, 0};  // FFTW dimensions (z, y, x): slabs along z
  ptrdiff_t localZ = 0, startZ = 0, localY = 0, startY = 0;
  double* data = nullptr;      // FFTW's in-place buffer: slabs [localZ][y][x], after the forward
                               // transform transposed to [localY][z][x] (not on one rank in the
                               // z-line solve)
  // A wall z axis is solved along its lines (zLines): transforms over the x-y planes, a transpose
  // to whole z lines and one tridiagonal solve per line, which saves the strided third transform
  // (benchmarks/RESULTS.md). A periodic z axis takes the 3-D transform.
  bool zLines = false;
  fftw_plan forward = nullptr, backward = nullptr;         // 3-D, or per plane with zLines
  fftw_plan toLines = nullptr, fromLines = nullptr;        // zLines on several ranks: the transposes
  std::vector<double> eig[3];  // eigenvalues per axis (z, y, x), normalisation folded in
  std::vector<double> gain;    // zLines: the forward elimination's factors of one y row [z][x]
  Vec slab = nullptr;          // a PETSc view of the buffer (natural order, slab partition)
  VecScatter toSlab = nullptr; // DMDA order -> slabs
};

// PETSc index of every natural index (k, j, i) with k in [k0, k1): the DMDA orders each rank's
// block contiguously, ranks x fastest.
std::vector<PetscInt> dmdaIndices(DM da, PetscInt k0, PetscInt k1)
{
  PetscInt M[3], procs[3];
  const PetscInt* l[3];
  DMDAGetInfo(da, nullptr, &M[0], &M[1], &M[2], &procs[0], &procs[1], &procs[2], nullptr, nullptr, nullptr,
              nullptr, nullptr, nullptr);
  DMDAGetOwnershipRanges(da, &l[0], &l[1], &l[2]);
  std::vector<PetscInt> owner[3], first[3];  // per axis and coordinate: rank index, block start
  for (int d = 0; d < 3; ++d) {
    owner[d].resize(M[d]);
    first[d].resize(M[d]);
    PetscInt s = 0;
    for (PetscInt r = 0; r < procs[d]; ++r) {
      for (PetscInt q = s; q < s + l[d][r]; ++q) {
        owner[d][q] = r;
        first[d][q] = s;
      }
      s += l[d][r];
    }
  }
  std::vector<PetscInt> offset(procs[0] * procs[1] * procs[2] + 1, 0);
  for (PetscInt pk = 0, r = 0; pk < procs[2]; ++pk)
    for (PetscInt pj = 0; pj < procs[1]; ++pj)
      for (PetscInt pi = 0; pi < procs[0]; ++pi, ++r) offset[r + 1] = offset[r] + l[0][pi] * l[1][pj] * l[2][pk];
  std::vector<PetscInt> idx;
  idx.reserve((k1 - k0) * M[1] * M[0]);
  for (PetscInt k = k0; k < k1; ++k)
    for (PetscInt j = 0; j < M[1]; ++j)
      for (PetscInt i = 0; i < M[0]; ++i) {
        const PetscInt pi = owner[0][i], pj = owner[1][j], pk = owner[2][k];
        const PetscInt r = pi + procs[0] * (pj + procs[1] * pk);
        idx.push_back(offset[r] + (i - first[0][i]) +
                      l[0][pi] * ((j - first[1][j]) + l[1][pj] * (k - first[2][k])));
      }
  return idx;
}

PetscErrorCode reset(Fft* f)
{
  PetscFunctionBeginUser;
  for (fftw_plan* p : {&f->forward, &f->backward, &f->toLines, &f->fromLines}) {
    if (*p) fftw_destroy_plan(*p);
    *p = nullptr;
  }
  if (f->data) fftw_free(f->data);
  f->data = nullptr;
  PetscCall(VecDestroy(&f->slab));
  PetscCall(VecScatterDestroy(&f->toSlab));
  PetscFunctionReturn(0);
}

PetscErrorCode setUp(PC pc)
{
  auto* f = static_cast<Fft*>(pc->data);
  MPI_Comm comm = PetscObjectComm((PetscObject)pc);
  DM da;
  PetscInt dim, M[3], dof;
  DMBoundaryType bt[3];
  PetscFunctionBeginUser;
  PetscCall(reset(f));
  PetscCall(PCGetDM(pc, &da));
  PetscCheck(da, comm, PETSC_ERR_ARG_WRONGSTATE, "PC fft needs the DMDA of the grid (KSPSetDM)");
  PetscCall(DMDAGetInfo(da, &dim, &M[0], &M[1], &M[2], nullptr, nullptr, nullptr, &dof, nullptr, &bt[0], &bt[1],
                        &bt[2], nullptr));
  PetscCheck(dim == 3 && dof == 1, comm, PETSC_ERR_SUP, "PC fft solves scalar problems on 3-D DMDAs");
  PetscCheck(f->w[0] > 0 && f->w[1] > 0 && f->w[2] > 0, comm, PETSC_ERR_ARG_WRONGSTATE,
             "PC fft: the operator weights were not given (PCFftSetWeights)");
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCheck(size <= M[2], comm, PETSC_ERR_SUP,
             "-pressure_pc_type fft: %d ranks but only %" PetscInt_FMT
             " z slabs (FFTW splits the z axis; one cell per rank at least): use at most %" PetscInt_FMT
             " ranks or another -pressure_pc_type (hypre, pfmg, mg)",
             size, M[2], M[2]);
  static bool fftwReady = false;
  if (!fftwReady) {
    fftw_mpi_init();
    fftwReady = true;
  }
  // FFTW's row-major order (z, y, x) is the DMDA's natural order.
  for (int d = 0; d < 3; ++d) f->n[d] = M[2 - d];
  f->zLines = bt[2] != DM_BOUNDARY_PERIODIC;
  const ptrdiff_t nz = f->n[0], ny = f->n[1], nx = f->n[2], plane = ny * nx;
  const ptrdiff_t zy[2] = {nz, ny};
  const ptrdiff_t alloc =
    f->zLines ? fftw_mpi_local_size_many_transposed(2, zy, nx, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, comm,
                                                    &f->localZ, &f->startZ, &f->localY, &f->startY)
              : fftw_mpi_local_size_3d_transposed(nz, ny, nx, comm, &f->localZ, &f->startZ, &f->localY, &f->startY);
  f->data = fftw_alloc_real(alloc > 0 ? alloc : 1);
  fftw_r2r_kind fwd[3], bwd[3];
  double norm = 1;
  for (int a = 0; a < 3; ++a) {
    const int d = 2 - a;  // grid axis of FFTW axis a
    const bool periodic = bt[d] == DM_BOUNDARY_PERIODIC;
    fwd[a] = periodic ? FFTW_DHT : FFTW_REDFT10;
    bwd[a] = periodic ? FFTW_DHT : FFTW_REDFT01;
    if (a == 0 && f->zLines) continue;
    norm *= periodic ? f->n[a] : 2 * f->n[a];
    const double step = (periodic ? 2 : 1) * M_PI / f->n[a];
    f->eig[a].resize(f->n[a]);
    for (ptrdiff_t k = 0; k < f->n[a]; ++k) f->eig[a][k] = f->w[d] * (2 - 2 * std::cos(step * k));
  }
  // The round trip multiplies by norm: fold it into the eigenvalues (for the z lines: into their
  // weight, kept as eig[0][0]).
  if (f->zLines) f->eig[0].assign(1, f->w[2]);
  for (auto& e : f->eig)
    for (double& v : e) v *= norm;
  const unsigned flags = f->plan ? FFTW_MEASURE : FFTW_ESTIMATE;
  if (f->zLines) {
    f->gain.resize(nz * nx);
    const int dims[2] = {int(ny), int(nx)};
    if (f->localZ > 0) {
      f->forward = fftw_plan_many_r2r(2, dims, int(f->localZ), f->data, nullptr, 1, int(plane), f->data, nullptr, 1,
                                      int(plane), fwd + 1, flags);
      f->backward = fftw_plan_many_r2r(2, dims, int(f->localZ), f->data, nullptr, 1, int(plane), f->data, nullptr, 1,
                                       int(plane), bwd + 1, flags);
    }
    if (size > 1) {
      f->toLines = fftw_mpi_plan_many_transpose(nz, ny, nx, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, f->data,
                                                f->data, comm, flags);
      f->fromLines = fftw_mpi_plan_many_transpose(ny, nz, nx, FFTW_MPI_DEFAULT_BLOCK, FFTW_MPI_DEFAULT_BLOCK, f->data,
                                                  f->data, comm, flags);
      PetscCheck(f->toLines && f->fromLines, comm, PETSC_ERR_LIB, "PC fft: FFTW could not plan the transposes");
    }
    PetscCheck(f->localZ == 0 || (f->forward && f->backward), comm, PETSC_ERR_LIB,
               "PC fft: FFTW could not plan the transforms");
  } else {
    f->forward = fftw_mpi_plan_r2r_3d(nz, ny, nx, f->data, f->data, comm, fwd[0], fwd[1], fwd[2],
                                      flags | FFTW_MPI_TRANSPOSED_OUT);
    f->backward = fftw_mpi_plan_r2r_3d(nz, ny, nx, f->data, f->data, comm, bwd[0], bwd[1], bwd[2],
                                       flags | FFTW_MPI_TRANSPOSED_IN);
    PetscCheck(f->forward && f->backward, comm, PETSC_ERR_LIB, "PC fft: FFTW could not plan the transforms");
  }

  const PetscInt local = f->localZ * f->n[1] * f->n[2];
  PetscCall(VecCreateMPIWithArray(comm, 1, local, PETSC_DECIDE, f->data, &f->slab));
  const std::vector<PetscInt> from = dmdaIndices(da, f->startZ, f->startZ + f->localZ);
  IS isFrom, isTo;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, local, from.data(), PETSC_COPY_VALUES, &isFrom));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, local, f->startZ * f->n[1] * f->n[2], 1, &isTo));
  Vec g;
  PetscCall(DMGetGlobalVector(da, &g));
  PetscCall(VecScatterCreate(g, isFrom, f->slab, isTo, &f->toSlab));
  PetscCall(DMRestoreGlobalVector(da, &g));
  PetscCall(ISDestroy(&isFrom));
  PetscCall(ISDestroy(&isTo));
  PetscFunctionReturn(0);
}

// After the 3-D transforms (transposed layout [localY][z][x]): divides by the eigenvalues.
void divideByEigenvalues(Fft* f)
{
  const ptrdiff_t nz = f->n[0], nx = f->n[2];
  const double *ez = f->eig[0].data(), *ey = f->eig[1].data(), *ex = f->eig[2].data();
  for (ptrdiff_t jl = 0; jl < f->localY; ++jl) {
    const double y = ey[f->startY + jl];
    for (ptrdiff_t k = 0; k < nz; ++k) {
      double* row = f->data + (jl * nz + k) * nx;
      const double yz = y + ez[k];
      for (ptrdiff_t i = 0; i < nx; ++i) row[i] /= yz + ex[i];
    }
  }
  if (f->localY > 0 && f->startY == 0) f->data[0] = 0;  // the null space (constant mode)
}

// The zero (x, y) mode's z line, w_z T p = r with T the Neumann second difference: singular (the
// constant null space), so r loses its mean and p is the zero-mean solution, by summation:
// w_z (p_k - p_{k+1}) = r_0 + ... + r_k.
void solveZeroModeLine(double* p, ptrdiff_t nz, ptrdiff_t stride, double wz)
{
  double mean = 0;
  for (ptrdiff_t k = 0; k < nz; ++k) mean += p[k * stride] / nz;
  double sum = 0, value = 0, valueMean = 0;
  for (ptrdiff_t k = 0; k < nz; ++k) {
    const double r = p[k * stride] - mean;
    p[k * stride] = value;
    valueMean += value / nz;
    sum += r;
    value -= sum / wz;
  }
  for (ptrdiff_t k = 0; k < nz; ++k) p[k * stride] -= valueMean;
}

// After the plane transforms, with whole z lines on this rank ([localY][z][x] after the transpose,
// [z][y][x] on one rank): (w_z T + lambda_y + lambda_x) p = r for every (y, x) mode by Thomas'
// elimination, one y row at a time and vectorised over x; gain holds the row's elimination factors.
void solveZLines(Fft* f)
{
  const ptrdiff_t nz = f->n[0], ny = f->n[1], nx = f->n[2];
  const bool transposed = f->toLines != nullptr;
  const ptrdiff_t rows = transposed ? f->localY : ny, row0 = transposed ? f->startY : 0;
  const ptrdiff_t sk = transposed ? nx : ny * nx, sj = transposed ? nz * nx : nx;
  const double wz = f->eig[0][0], *ey = f->eig[1].data(), *ex = f->eig[2].data();
  double* gain = f->gain.data();
  for (ptrdiff_t jl = 0; jl < rows; ++jl) {
    double* p = f->data + jl * sj;
    const double ly = ey[row0 + jl];
    const ptrdiff_t i0 = row0 + jl == 0 ? 1 : 0;  // the zero mode's line apart
    for (ptrdiff_t k = 0; k < nz; ++k) {
      double* __restrict r = p + k * sk;
      double* __restrict g = gain + k * nx;
      const double diag = nz == 1 ? 0 : k == 0 || k == nz - 1 ? wz : 2 * wz;
      if (k == 0) {
        for (ptrdiff_t i = i0; i < nx; ++i) {
          const double m = 1 / (diag + ly + ex[i]);
          g[i] = wz * m;
          r[i] *= m;
        }
      } else {
        const double* __restrict gp = g - nx;
        const double* __restrict rp = r - sk;
        for (ptrdiff_t i = i0; i < nx; ++i) {
          const double m = 1 / (diag + ly + ex[i] - wz * gp[i]);
          g[i] = wz * m;
          r[i] = (r[i] + wz * rp[i]) * m;
        }
      }
    }
    for (ptrdiff_t k = nz - 2; k >= 0; --k) {
      double* __restrict r = p + k * sk;
      const double* __restrict rn = r + sk;
      const double* __restrict g = gain + k * nx;
      for (ptrdiff_t i = i0; i < nx; ++i) r[i] += g[i] * rn[i];
    }
    if (i0 == 1) solveZeroModeLine(p, nz, sk, wz);
  }
}

PetscErrorCode apply(PC pc, Vec b, Vec x)
{
  auto* f = static_cast<Fft*>(pc->data);
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(f->toSlab, b, f->slab, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(f->toSlab, b, f->slab, INSERT_VALUES, SCATTER_FORWARD));
  if (f->zLines) {
    if (f->forward) fftw_execute(f->forward);
    if (f->toLines) fftw_execute(f->toLines);
    solveZLines(f);
    if (f->fromLines) fftw_execute(f->fromLines);
    if (f->backward) fftw_execute(f->backward);
  } else {
    fftw_execute(f->forward);
    divideByEigenvalues(f);
    fftw_execute(f->backward);
  }
  PetscCall(VecScatterBegin(f->toSlab, f->slab, x, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(f->toSlab, f->slab, x, INSERT_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

PetscErrorCode setFromOptions(PC pc, PetscOptionItems* PetscOptionsObject)
{
  auto* f = static_cast<Fft*>(pc->data);
  const char* plans[] = {"estimate", "measure"};
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "FFT Poisson solver options");
  PetscCall(PetscOptionsEList("-pc_fft_plan", "FFTW planning: estimate (instant) or measure (slower set-up)",
                              "PCFftSetWeights", plans, 2, plans[f->plan], &f->plan, nullptr));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode view(PC pc, PetscViewer viewer)
{
  auto* f = static_cast<Fft*>(pc->data);
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  FFTW r2r, slabs along z, %s planning\n", f->plan ? "measure" : "estimate"));
  PetscFunctionReturn(0);
}

PetscErrorCode destroy(PC pc)
{
  auto* f = static_cast<Fft*>(pc->data);
  PetscFunctionBeginUser;
  PetscCall(reset(f));
  delete f;
  pc->data = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode create(PC pc)
{
  PetscFunctionBeginUser;
  pc->data = new Fft;
  pc->ops->setup = setUp;
  pc->ops->apply = apply;
  pc->ops->applytranspose = apply;  // A is symmetric
  pc->ops->setfromoptions = setFromOptions;
  pc->ops->view = view;
  pc->ops->destroy = destroy;
  PetscFunctionReturn(0);
}

} // namespace

void registerFftPreconditioner()
{
  static bool registered = false;
  if (registered) return;
  PCRegister(kTypeName, create);
  registered = true;
}

PetscErrorCode PCFftSetWeights(PC pc, const double w[3])
{
  PetscBool isFft;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, kTypeName, &isFft));
  PetscCheck(isFft, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONG, "PCFftSetWeights: the PC is not of type fft");
  auto* f = static_cast<Fft*>(pc->data);
  for (int d = 0; d < 3; ++d) f->w[d] = w[d];
  pc->setupcalled = 0;  // new weights: set up again
  PetscFunctionReturn(0);
}

} // namespace vp
