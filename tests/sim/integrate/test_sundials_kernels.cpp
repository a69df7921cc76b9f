// fourbar's serial-vector and dense-matrix kernels (sim/integrate/
// sundials_kernels.hpp) against SUNDIALS' own on the same seeded data: every
// operation installed, with the aliasings SUNDIALS' contract allows (the
// result in an operand), agreeing to a few ulps of the operands' scale; and
// clones keep the kernels (CVODE's internal vectors and its saved Jacobian
// are clones).
#include <gtest/gtest.h>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <random>
#include <vector>

#include "sim/integrate/sundials_kernels.hpp"

namespace fourbar {
namespace {

constexpr sunindextype kKernelLength = 31;  // odd: a vectorised loop's remainder is exercised
constexpr double kKernelTolerance = 8 * 2.220446049250313e-16;

class SundialsKernels : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(SUNContext_Create(nullptr, &ctx), 0);
    std::mt19937 rng(20261202);
    std::uniform_real_distribution<double> u(-2, 2);
    for (auto* set : {&ours, &theirs}) {
      set->clear();
      for (int k = 0; k < 5; ++k) set->push_back(N_VNew_Serial(kKernelLength, ctx));
    }
    install_serial_vector_ops(ours[0]);
    for (int k = 1; k < 5; ++k) {
      N_VDestroy(ours[static_cast<std::size_t>(k)]);
      ours[static_cast<std::size_t>(k)] = N_VClone(ours[0]);  // clones carry the kernels
    }
    for (int k = 0; k < 5; ++k)
      for (sunindextype i = 0; i < kKernelLength; ++i) {
        double v = u(rng);
        if (k == 3) v = std::abs(v) + 0.1;  // weights and divisors: positive
        NV_Ith_S(ours[static_cast<std::size_t>(k)], i) = NV_Ith_S(theirs[static_cast<std::size_t>(k)], i) = v;
      }
  }
  void TearDown() override {
    for (auto* set : {&ours, &theirs})
      for (N_Vector v : *set) N_VDestroy(v);
    SUNContext_Free(&ctx);
  }
  /// Both sets element by element, relative to the largest magnitude.
  void expect_same(std::size_t k) const {
    double scale = 0;
    for (sunindextype i = 0; i < kKernelLength; ++i) scale = std::max(scale, std::abs(NV_Ith_S(theirs[k], i)));
    for (sunindextype i = 0; i < kKernelLength; ++i)
      EXPECT_NEAR(NV_Ith_S(ours[k], i), NV_Ith_S(theirs[k], i), kKernelTolerance * std::max(scale, 1.0))
          << "vector " << k << " element " << i;
  }
  SUNContext ctx = nullptr;
  std::vector<N_Vector> ours, theirs;
};

TEST_F(SundialsKernels, ClonesCarryTheKernels) {
  EXPECT_EQ(ours[1]->ops->nvlinearsum, ours[0]->ops->nvlinearsum);
  EXPECT_NE(ours[0]->ops->nvlinearsum, theirs[0]->ops->nvlinearsum);
  EXPECT_NE(ours[0]->ops->nvlinearcombination, nullptr);
}

TEST_F(SundialsKernels, ElementwiseOperationsAgreeWithAliasing) {
  for (auto* set : {&ours, &theirs}) {
    auto& v = *set;
    N_VLinearSum(0.7, v[0], -1.3, v[1], v[2]);
    N_VLinearSum(2.0, v[2], 0.5, v[0], v[2]);  // z = x
    N_VLinearSum(1.0, v[1], 1.0, v[2], v[2]);  // z = y
    N_VProd(v[0], v[2], v[4]);
    N_VDiv(v[4], v[3], v[4]);
    N_VScale(-0.25, v[4], v[4]);
    N_VAbs(v[1], v[1]);
    N_VAddConst(v[1], 0.5, v[1]);
    N_VInv(v[1], v[1]);
    N_VCompare(0.6, v[0], v[0]);
  }
  for (std::size_t k = 0; k < 5; ++k) expect_same(k);
  N_VConst(3.5, ours[2]);
  N_VConst(3.5, theirs[2]);
  expect_same(2);
}

TEST_F(SundialsKernels, NormsAndReductionsAgree) {
  auto close = [](double a, double b) { EXPECT_NEAR(a, b, kKernelTolerance * std::max(1.0, std::abs(b))); };
  close(N_VDotProd(ours[0], ours[1]), N_VDotProd(theirs[0], theirs[1]));
  close(N_VMaxNorm(ours[0]), N_VMaxNorm(theirs[0]));
  close(N_VWrmsNorm(ours[0], ours[3]), N_VWrmsNorm(theirs[0], theirs[3]));
  close(N_VWL2Norm(ours[0], ours[3]), N_VWL2Norm(theirs[0], theirs[3]));
  close(N_VL1Norm(ours[0]), N_VL1Norm(theirs[0]));
  close(N_VMin(ours[1]), N_VMin(theirs[1]));
  close(N_VWSqrSumLocal(ours[0], ours[3]), N_VWSqrSumLocal(theirs[0], theirs[3]));
  // The mask: elements where id > 0 count.
  close(N_VWrmsNormMask(ours[0], ours[3], ours[1]), N_VWrmsNormMask(theirs[0], theirs[3], theirs[1]));
  close(N_VWSqrSumMaskLocal(ours[0], ours[3], ours[1]), N_VWSqrSumMaskLocal(theirs[0], theirs[3], theirs[1]));
  // Inverse test: true without zeros, false with one, the others inverted either way.
  EXPECT_EQ(N_VInvTest(ours[3], ours[4]), N_VInvTest(theirs[3], theirs[4]));
  expect_same(4);
  NV_Ith_S(ours[3], 5) = NV_Ith_S(theirs[3], 5) = 0.0;
  EXPECT_FALSE(N_VInvTest(ours[3], ours[4]));
  EXPECT_FALSE(N_VInvTest(theirs[3], theirs[4]));
  for (sunindextype i = 0; i < kKernelLength; ++i)
    if (i != 5) EXPECT_DOUBLE_EQ(NV_Ith_S(ours[4], i), NV_Ith_S(theirs[4], i));
}

TEST_F(SundialsKernels, FusedOperationsAgreeWithRepeatedLinearSums) {
  // SUNDIALS' serial vectors emulate the fused operations (fused ops off);
  // ours run them in one pass. z = X[0] is allowed, and Z[j] = Y[j].
  for (int nvec : {1, 2, 4}) {
    std::vector<double> c = {0.3, -1.1, 2.0, 0.75};
    for (auto* set : {&ours, &theirs}) {
      auto& v = *set;
      std::vector<N_Vector> x = {v[4], v[1], v[2], v[3]};  // z = X[0]
      ASSERT_EQ(N_VLinearCombination(nvec, c.data(), x.data(), v[4]), 0);
    }
    expect_same(4);
  }
  std::vector<double> a = {0.5, -2.0, 1.25};
  for (auto* set : {&ours, &theirs}) {
    auto& v = *set;
    std::vector<N_Vector> y = {v[1], v[2], v[4]}, z = {v[1], v[2], v[4]};
    ASSERT_EQ(N_VScaleAddMulti(3, a.data(), v[0], y.data(), z.data()), 0);
  }
  for (std::size_t k : {1U, 2U, 4U}) expect_same(k);
  std::vector<double> dots_ours(3), dots_theirs(3);
  std::vector<N_Vector> yo = {ours[1], ours[2], ours[3]}, yt = {theirs[1], theirs[2], theirs[3]};
  ASSERT_EQ(N_VDotProdMulti(3, ours[0], yo.data(), dots_ours.data()), 0);
  ASSERT_EQ(N_VDotProdMulti(3, theirs[0], yt.data(), dots_theirs.data()), 0);
  for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(dots_ours[j], dots_theirs[j], kKernelTolerance * 10);
}

TEST_F(SundialsKernels, DenseMatrixOperationsAgreeAndClonesCarryThem) {
  const sunindextype rows = 7, cols = 7;
  SUNMatrix a = SUNDenseMatrix(rows, cols, ctx), b = SUNDenseMatrix(rows, cols, ctx);
  SUNMatrix ref_a = SUNDenseMatrix(rows, cols, ctx), ref_b = SUNDenseMatrix(rows, cols, ctx);
  install_dense_matrix_ops(a);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (sunindextype i = 0; i < rows * cols; ++i) {
    SUNDenseMatrix_Data(a)[i] = SUNDenseMatrix_Data(ref_a)[i] = u(rng);
    SUNDenseMatrix_Data(b)[i] = SUNDenseMatrix_Data(ref_b)[i] = u(rng);
  }
  SUNMatrix clone = SUNMatClone(a);
  ASSERT_NE(clone, nullptr);
  EXPECT_EQ(clone->ops->copy, a->ops->copy);
  EXPECT_NE(a->ops->copy, ref_a->ops->copy);
  auto same = [&](SUNMatrix x, SUNMatrix y) {
    for (sunindextype i = 0; i < rows * cols; ++i)
      EXPECT_NEAR(SUNDenseMatrix_Data(x)[i], SUNDenseMatrix_Data(y)[i], kKernelTolerance) << "entry " << i;
  };
  ASSERT_EQ(SUNMatScaleAddI(-0.37, a), 0);
  ASSERT_EQ(SUNMatScaleAddI(-0.37, ref_a), 0);
  same(a, ref_a);
  ASSERT_EQ(SUNMatScaleAdd(1.5, a, b), 0);
  ASSERT_EQ(SUNMatScaleAdd(1.5, ref_a, ref_b), 0);
  same(a, ref_a);
  ASSERT_EQ(SUNMatCopy(a, clone), 0);
  same(clone, ref_a);
  ASSERT_EQ(SUNMatZero(clone), 0);
  for (sunindextype i = 0; i < rows * cols; ++i) EXPECT_EQ(SUNDenseMatrix_Data(clone)[i], 0.0);
  SUNMatrix other = SUNDenseMatrix(rows, cols + 1, ctx);
  EXPECT_NE(SUNMatCopy(a, other), 0);  // shapes differ: refused, as SUNDIALS' own
  for (SUNMatrix m : {a, b, ref_a, ref_b, clone, other}) SUNMatDestroy(m);
}

}  // namespace
}  // namespace fourbar
