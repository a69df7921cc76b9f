#include "sim/integrate/sundials_kernels.hpp"

#include <algorithm>
#include <cmath>

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace fourbar {

namespace {

// sunindextype and realtype as SUNDIALS defines them (long int, double).
inline sunindextype nv_length(N_Vector v) { return NV_LENGTH_S(v); }
inline realtype* nv_data(N_Vector v) { return NV_DATA_S(v); }

void nv_linear_sum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
  const realtype *xd = nv_data(x), *yd = nv_data(y);
  realtype* zd = nv_data(z);
  const sunindextype n = nv_length(x);
  for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
}

void nv_constant(realtype c, N_Vector z) { std::fill(nv_data(z), nv_data(z) + nv_length(z), c); }

void nv_prod(N_Vector x, N_Vector y, N_Vector z) {
  const realtype *xd = nv_data(x), *yd = nv_data(y);
  realtype* zd = nv_data(z);
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) zd[i] = xd[i] * yd[i];
}

void nv_div(N_Vector x, N_Vector y, N_Vector z) {
  const realtype *xd = nv_data(x), *yd = nv_data(y);
  realtype* zd = nv_data(z);
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) zd[i] = xd[i] / yd[i];
}

void nv_scale(realtype c, N_Vector x, N_Vector z) {
  const realtype* xd = nv_data(x);
  realtype* zd = nv_data(z);
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) zd[i] = c * xd[i];
}

void nv_abs_value(N_Vector x, N_Vector z) {
  const realtype* xd = nv_data(x);
  realtype* zd = nv_data(z);
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) zd[i] = std::abs(xd[i]);
}

void nv_inverse(N_Vector x, N_Vector z) {
  const realtype* xd = nv_data(x);
  realtype* zd = nv_data(z);
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) zd[i] = 1.0 / xd[i];
}

void nv_add_const(N_Vector x, realtype b, N_Vector z) {
  const realtype* xd = nv_data(x);
  realtype* zd = nv_data(z);
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) zd[i] = xd[i] + b;
}

realtype nv_dot(N_Vector x, N_Vector y) {
  const realtype *xd = nv_data(x), *yd = nv_data(y);
  realtype s = 0;
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) s += xd[i] * yd[i];
  return s;
}

realtype nv_max_norm(N_Vector x) {
  const realtype* xd = nv_data(x);
  realtype m = 0;
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) m = std::max(m, std::abs(xd[i]));
  return m;
}

realtype nv_weighted_square_sum(N_Vector x, N_Vector w) {
  const realtype *xd = nv_data(x), *wd = nv_data(w);
  realtype s = 0;
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) {
    const realtype p = xd[i] * wd[i];
    s += p * p;
  }
  return s;
}

realtype nv_wrms_norm(N_Vector x, N_Vector w) {
  return std::sqrt(nv_weighted_square_sum(x, w) / static_cast<realtype>(nv_length(x)));
}

realtype nv_weighted_square_sum_mask(N_Vector x, N_Vector w, N_Vector id) {
  const realtype *xd = nv_data(x), *wd = nv_data(w), *idd = nv_data(id);
  realtype s = 0;
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i)
    if (idd[i] > 0) {
      const realtype p = xd[i] * wd[i];
      s += p * p;
    }
  return s;
}

realtype nv_wrms_norm_mask(N_Vector x, N_Vector w, N_Vector id) {
  return std::sqrt(nv_weighted_square_sum_mask(x, w, id) / static_cast<realtype>(nv_length(x)));
}

realtype nv_minimum(N_Vector x) {
  const realtype* xd = nv_data(x);
  realtype m = xd[0];
  for (sunindextype i = 1, n = nv_length(x); i < n; ++i) m = std::min(m, xd[i]);
  return m;
}

realtype nv_l1_norm(N_Vector x) {
  const realtype* xd = nv_data(x);
  realtype s = 0;
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) s += std::abs(xd[i]);
  return s;
}

realtype nv_wl2_norm(N_Vector x, N_Vector w) { return std::sqrt(nv_weighted_square_sum(x, w)); }

void nv_compare(realtype c, N_Vector x, N_Vector z) {
  const realtype* xd = nv_data(x);
  realtype* zd = nv_data(z);
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}

booleantype nv_inv_test(N_Vector x, N_Vector z) {
  const realtype* xd = nv_data(x);
  realtype* zd = nv_data(z);
  booleantype ok = SUNTRUE;
  for (sunindextype i = 0, n = nv_length(x); i < n; ++i) {
    if (xd[i] == 0) {
      ok = SUNFALSE;
    } else {
      zd[i] = 1.0 / xd[i];
    }
  }
  return ok;
}

/// z = Σ c[j]·X[j], element by element (z may be X[0]).
int nv_linear_combination(int nvec, realtype* c, N_Vector* X, N_Vector z) {
  realtype* zd = nv_data(z);
  const sunindextype n = nv_length(z);
  if (nvec == 1) {
    nv_scale(c[0], X[0], z);
    return 0;
  }
  if (nvec == 2) {
    nv_linear_sum(c[0], X[0], c[1], X[1], z);
    return 0;
  }
  for (sunindextype i = 0; i < n; ++i) {
    realtype s = 0;
    for (int j = 0; j < nvec; ++j) s += c[j] * nv_data(X[j])[i];
    zd[i] = s;
  }
  return 0;
}

/// Z[j] = a[j]·x + Y[j] (Z[j] may be Y[j]).
int nv_scale_add_multi(int nvec, realtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  const realtype* xd = nv_data(x);
  const sunindextype n = nv_length(x);
  for (int j = 0; j < nvec; ++j) {
    const realtype* yd = nv_data(Y[j]);
    realtype* zd = nv_data(Z[j]);
    const realtype aj = a[j];
    for (sunindextype i = 0; i < n; ++i) zd[i] = aj * xd[i] + yd[i];
  }
  return 0;
}

int nv_dot_prod_multi(int nvec, N_Vector x, N_Vector* Y, realtype* d) {
  for (int j = 0; j < nvec; ++j) d[j] = nv_dot(x, Y[j]);
  return 0;
}

bool dense_same_shape(SUNMatrix a, SUNMatrix b) {
  return SM_ROWS_D(a) == SM_ROWS_D(b) && SM_COLUMNS_D(a) == SM_COLUMNS_D(b);
}

int dense_zero(SUNMatrix a) {
  std::fill(SM_DATA_D(a), SM_DATA_D(a) + SM_LDATA_D(a), 0.0);
  return SUNMAT_SUCCESS;
}

/// b = a
int dense_copy(SUNMatrix a, SUNMatrix b) {
  if (!dense_same_shape(a, b)) return SUNMAT_ILL_INPUT;
  std::copy(SM_DATA_D(a), SM_DATA_D(a) + SM_LDATA_D(a), SM_DATA_D(b));
  return SUNMAT_SUCCESS;
}

/// a = c·a + b
int dense_scale_add(realtype c, SUNMatrix a, SUNMatrix b) {
  if (!dense_same_shape(a, b)) return SUNMAT_ILL_INPUT;
  realtype* ad = SM_DATA_D(a);
  const realtype* bd = SM_DATA_D(b);
  for (sunindextype i = 0, n = SM_LDATA_D(a); i < n; ++i) ad[i] = c * ad[i] + bd[i];
  return SUNMAT_SUCCESS;
}

/// a = c·a + I
int dense_scale_add_identity(realtype c, SUNMatrix a) {
  realtype* ad = SM_DATA_D(a);
  for (sunindextype i = 0, n = SM_LDATA_D(a); i < n; ++i) ad[i] *= c;
  const sunindextype rows = SM_ROWS_D(a), diagonal = std::min(rows, SM_COLUMNS_D(a));
  for (sunindextype j = 0; j < diagonal; ++j) ad[j * rows + j] += 1.0;
  return SUNMAT_SUCCESS;
}

SUNMatrix dense_clone(SUNMatrix a) { return new_dense_matrix(SM_ROWS_D(a), SM_COLUMNS_D(a), a->sunctx); }

}  // namespace

void install_dense_matrix_ops(SUNMatrix a) {
  a->ops->clone = dense_clone;  // the linear-solver interface's saved Jacobian is a clone
  a->ops->zero = dense_zero;
  a->ops->copy = dense_copy;
  a->ops->scaleadd = dense_scale_add;
  a->ops->scaleaddi = dense_scale_add_identity;
}

void install_serial_vector_ops(N_Vector v) {
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = nv_linear_sum;
  o->nvconst = nv_constant;
  o->nvprod = nv_prod;
  o->nvdiv = nv_div;
  o->nvscale = nv_scale;
  o->nvabs = nv_abs_value;
  o->nvinv = nv_inverse;
  o->nvaddconst = nv_add_const;
  o->nvdotprod = nv_dot;
  o->nvmaxnorm = nv_max_norm;
  o->nvwrmsnorm = nv_wrms_norm;
  o->nvwrmsnormmask = nv_wrms_norm_mask;
  o->nvmin = nv_minimum;
  o->nvwl2norm = nv_wl2_norm;
  o->nvl1norm = nv_l1_norm;
  o->nvcompare = nv_compare;
  o->nvinvtest = nv_inv_test;
  o->nvlinearcombination = nv_linear_combination;
  o->nvscaleaddmulti = nv_scale_add_multi;
  o->nvdotprodmulti = nv_dot_prod_multi;
  // The local kernels the serial norms are built from.
  o->nvdotprodlocal = nv_dot;
  o->nvmaxnormlocal = nv_max_norm;
  o->nvminlocal = nv_minimum;
  o->nvl1normlocal = nv_l1_norm;
  o->nvinvtestlocal = nv_inv_test;
  o->nvwsqrsumlocal = nv_weighted_square_sum;
  o->nvwsqrsummasklocal = nv_weighted_square_sum_mask;
}

N_Vector new_serial_vector(sunindextype length, SUNContext ctx) {
  N_Vector v = N_VNew_Serial(length, ctx);
  if (v) install_serial_vector_ops(v);
  return v;
}

SUNMatrix new_dense_matrix(sunindextype rows, sunindextype columns, SUNContext ctx) {
  SUNMatrix a = SUNDenseMatrix(rows, columns, ctx);
  if (a) install_dense_matrix_ops(a);
  return a;
}

}  // namespace fourbar
