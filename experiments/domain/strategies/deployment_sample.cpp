#include "experiments/domain/strategies/deployment_sample.h"

namespace dvpr {

DescriptorMatrix DeploymentSample(const DescriptorMatrix& deployment) {
  const Eigen::Index rows = (deployment.rows() + kSampleStride - 1) / kSampleStride;
  DescriptorMatrix sample(rows, deployment.cols());
  for (Eigen::Index i = 0; i < rows; ++i) sample.row(i) = deployment.row(i * kSampleStride);
  return sample;
}

}  // namespace dvpr
