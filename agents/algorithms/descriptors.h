#pragma once
// The one batch layout of descriptors: N rows (frames) x d columns, row-major,
// float32 as NetVLAD emits them. Centroids use the same layout (k x d).
#include <Eigen/Core>

namespace dvpr {

using DescriptorMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using CentroidMatrix = DescriptorMatrix;
using DescriptorRow = Eigen::Ref<const Eigen::RowVectorXf>;

}  // namespace dvpr
