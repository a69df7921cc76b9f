#pragma once
// Serial N_Vector and dense SUNMatrix kernels compiled with fourbar's
// optimisation, installed in place of SUNDIALS' own through their documented
// ops tables (user-supplied NVECTOR / SUNMATRIX operations, SUNDIALS user
// guide, "Description of the NVECTOR module" and "... the SUNMATRIX module"). Debian 12's libsundials 6.4.1+dfsg1-3 is built without
// optimisation (its N_VLinearSum_Serial keeps its loop counter on the stack:
// ~20 instructions an element), and CVODE's vector arithmetic on the linkage
// model's 30-component state was a quarter of a step's instructions
// (callgrind, docs/linkage-model.md). The kernels do what SUNDIALS' serial
// ones do, element by element, so every aliasing the SUNDIALS contract
// allows (z the same vector as x or y, Z[j] as Y[j], z as X[0]) is safe.
// Clones made by the integrators copy the table, so installing it on the
// vector given to CVodeInit/ARKStepCreate covers every internal vector, and
// on the Jacobian matrix the saved copy the linear-solver interface keeps.

#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

namespace fourbar {

/// Replaces the arithmetic, norm and fused operations of the serial vector
/// `v` (N_VNew_Serial) by fourbar's; the constructors and the data stay
/// SUNDIALS'. Turns the fused operations on (linear combination, scale-add
/// multi, dot-product multi), which SUNDIALS otherwise emulates by repeated
/// linear sums.
void install_serial_vector_ops(N_Vector v);

/// Replaces zero, copy, scale-add and scale-add-identity of the dense matrix
/// `a` (SUNDenseMatrix): what CVODE's linear-solver interface does to the
/// Newton matrix at every step.
void install_dense_matrix_ops(SUNMatrix a);

/// N_VNew_Serial / SUNDenseMatrix with the kernels above installed: how the
/// integrators make their vectors and Jacobian (null when SUNDIALS cannot
/// allocate them).
N_Vector new_serial_vector(sunindextype length, SUNContext ctx);
SUNMatrix new_dense_matrix(sunindextype rows, sunindextype columns, SUNContext ctx);

}  // namespace fourbar
