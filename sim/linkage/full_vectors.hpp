#pragma once
// Fixed-capacity vectors and matrices over the linkage's full coordinates
// z = (q, θ2) (at most kMaxFullCoordinates): sized at run time, never
// allocated (sim/linkage/linkage_dynamics.hpp).

#include <Eigen/Core>

#include "sim/linkage/linkage_model.hpp"

namespace fourbar {

inline constexpr int kMaxFull = kMaxFullCoordinates;
using ZVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxFull, 1>;
using ZRow = Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, kMaxFull>;
using ZJac = Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxFull>;
using ZMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxFull, kMaxFull>;

}  // namespace fourbar
