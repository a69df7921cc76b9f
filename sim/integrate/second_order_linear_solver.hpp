#pragma once
// A SUNDIALS linear solver for the Newton matrix A = I − γ·J of the linkage
// model's scaled state (SIM-DESIGN-NOTES §5 OdeProblem): y = (q, q̇, quadratures)
// with q and q̇ of `n` components each, where dq/dt = S·q̇ (S diagonal: the
// position rows only scale the rates) and the quadratures (work, losses,
// impulses) feed no right-hand side. Then
//   A = [ I     A12   0 ]      A12 = −γS diagonal
//       [ A21   A22   0 ]
//       [ Aq1   Aq2   I ]
// and A·x = b is solved through the n×n Schur complement R = A22 − A21·A12
// (LU with partial pivoting): x2 = R⁻¹(b2 − A21·b1), x1 = b1 − A12·x2,
// xq = bq − Aq1·x1 − Aq2·x2. That is one 12×12 factor instead of a 30×30 one
// for the elastic 4+4-mode case. setup() checks the structure entry by entry
// (exact zeros and ones, as the difference-quotient Jacobian gives them) and
// falls back to a dense LU of the whole A when it does not hold.

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <cstddef>

namespace fourbar {

/// A new solver for states of `size` components whose first 2·`half` are (q, q̇).
/// Free with SUNLinSolFree.
SUNLinearSolver second_order_linear_solver(SUNContext ctx, std::size_t size, std::size_t half);

/// How many setups used the Schur complement and how many fell back to the dense LU.
struct SecondOrderSolverCounts {
  long structured = 0, dense = 0;
};
SecondOrderSolverCounts second_order_solver_counts(SUNLinearSolver s);

}  // namespace fourbar
