#pragma once
// The deployment sample the team shares at start (docs/strategies.md): every kSampleStride-th
// deployment frame, about 5% of the sequence. The load-balanced tables take their expected loads
// from it (nearest-centroid counts), the sample_* tables cluster it.
#include "agents/algorithms/descriptors.h"

namespace dvpr {

inline constexpr int kSampleStride = 20;

// Rows 0, kSampleStride, 2 kSampleStride, ... of the deployment descriptors.
DescriptorMatrix DeploymentSample(const DescriptorMatrix& deployment);

}  // namespace dvpr
