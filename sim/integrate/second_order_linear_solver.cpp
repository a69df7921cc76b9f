#include "sim/integrate/second_order_linear_solver.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>
#include <memory>

namespace fourbar {

namespace {

using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

struct Content {
  long n = 0, size = 0;  ///< half and whole size
  bool structured = false;
  Vec a12;               ///< diagonal of A12
  Mat a21, aq;           ///< A21 (n×n) and the quadrature rows' first 2n columns
  Eigen::PartialPivLU<Mat> schur, dense;
  Mat work;
  Vec r, x2, bq, full;
  SecondOrderSolverCounts counts;
  long last_flag = 0;
};

Content& content(SUNLinearSolver s) { return *static_cast<Content*>(s->content); }

SUNLinearSolver_Type get_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID get_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
sunindextype last_flag(SUNLinearSolver s) { return content(s).last_flag; }

/// Does A have the structure of the header, exactly?
bool has_structure(const double* a, long n, long size) {
  auto at = [&](long i, long j) { return a[i + j * size]; };  // column-major
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < size; ++j) {
      const double want_zero_or_one = (j == i) ? 1.0 : 0.0;
      if (j == i + n) continue;  // the diagonal of A12
      if (at(i, j) != want_zero_or_one) return false;
    }
  for (long i = 0; i < size; ++i)
    for (long j = 2 * n; j < size; ++j)
      if (at(i, j) != (i == j ? 1.0 : 0.0)) return false;
  return true;
}

int setup(SUNLinearSolver s, SUNMatrix A) {
  Content& c = content(s);
  const double* a = SUNDenseMatrix_Data(A);
  const long n = c.n, size = c.size;
  const Eigen::Map<const Mat> m(a, size, size);
  c.structured = has_structure(a, n, size);
  if (c.structured) {
    for (long i = 0; i < n; ++i) c.a12(i) = m(i, n + i);
    c.a21 = m.block(n, 0, n, n);
    c.aq = m.block(2 * n, 0, size - 2 * n, 2 * n);
    c.work = m.block(n, n, n, n);
    c.work.noalias() -= c.a21 * c.a12.asDiagonal();
    c.schur.compute(c.work);
    ++c.counts.structured;
  } else {
    c.dense.compute(m);
    ++c.counts.dense;
  }
  c.last_flag = 0;
  return SUNLS_SUCCESS;
}

int solve(SUNLinearSolver s, SUNMatrix, N_Vector x, N_Vector b, double) {
  Content& c = content(s);
  const long n = c.n, size = c.size;
  const Eigen::Map<const Vec> bb(N_VGetArrayPointer(b), size);
  Eigen::Map<Vec> xx(N_VGetArrayPointer(x), size);
  if (!c.structured) {
    c.full = c.dense.solve(bb);
    xx = c.full;
    return SUNLS_SUCCESS;
  }
  c.r = bb.segment(n, n);
  c.r.noalias() -= c.a21 * bb.head(n);
  c.x2 = c.schur.solve(c.r);
  // x may alias b: read what is still needed of b before writing x.
  c.bq = bb.tail(size - 2 * n);
  xx.head(n) = bb.head(n) - c.a12.cwiseProduct(c.x2);
  xx.segment(n, n) = c.x2;
  c.bq.noalias() -= c.aq * xx.head(2 * n);
  xx.tail(size - 2 * n) = c.bq;
  return SUNLS_SUCCESS;
}

int free_solver(SUNLinearSolver s) {
  if (!s) return SUNLS_SUCCESS;
  delete static_cast<Content*>(s->content);
  s->content = nullptr;
  SUNLinSolFreeEmpty(s);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver second_order_linear_solver(SUNContext ctx, std::size_t size, std::size_t half) {
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (!s) return nullptr;
  auto c = std::make_unique<Content>();
  c->n = static_cast<long>(half);
  c->size = static_cast<long>(size);
  c->a12 = Vec::Zero(c->n);
  c->a21 = Mat::Zero(c->n, c->n);
  c->aq = Mat::Zero(c->size - 2 * c->n, 2 * c->n);
  c->work = Mat::Zero(c->n, c->n);
  c->r = Vec::Zero(c->n);
  c->x2 = Vec::Zero(c->n);
  c->bq = Vec::Zero(c->size - 2 * c->n);
  c->full = Vec::Zero(c->size);
  s->content = c.release();
  s->ops->gettype = get_type;
  s->ops->getid = get_id;
  s->ops->initialize = initialize;
  s->ops->setup = setup;
  s->ops->solve = solve;
  s->ops->lastflag = last_flag;
  s->ops->free = free_solver;
  return s;
}

SecondOrderSolverCounts second_order_solver_counts(SUNLinearSolver s) { return content(s).counts; }

}  // namespace fourbar
