#pragma once
// Exact L2 nearest neighbour in batches. Squared distances come from one matrix product,
// ||a||^2 - 2 a.b + ||b||^2 (float GEMM through Eigen), which is what makes the static protocol
// and k-means fast; where a decision must not depend on float rounding (which centroid or frame
// is nearest), the few candidates that float arithmetic cannot tell apart are re-decided with
// distances accumulated in double (see NearestRows).
#include <vector>

#include <Eigen/Core>

#include "agents/algorithms/descriptors.h"

namespace dvpr {

// Squared distances, row i = a query, column j = a reference; row-major float.
using DistanceMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// ||row||^2 of every row.
Eigen::VectorXf SquaredNorms(const DescriptorMatrix& m);

// All squared distances between the rows of `a` (N x d) and of `b` (M x d): N x M, clamped at 0.
// Throws std::invalid_argument if the widths differ.
DistanceMatrix SquaredL2(const DescriptorMatrix& a, const DescriptorMatrix& b);

// Rows [first, first + count) of SquaredL2(a, b) into `out` (resized to count x M), given the
// precomputed SquaredNorms of both: the building block for streaming over a large `a`.
void SquaredL2Rows(const DescriptorMatrix& a, const Eigen::VectorXf& a_norms, Eigen::Index first,
                   Eigen::Index count, const DescriptorMatrix& b, const Eigen::VectorXf& b_norms,
                   DistanceMatrix& out);

// Squared distance of two d-vectors accumulated in double (the reference every float result is
// checked against). Fixed summation order, so the value does not depend on the thread or build.
double ExactSquaredL2(const float* a, const float* b, Eigen::Index dim);

// A bound on |GEMM distance - exact distance| for vectors of squared norms `sq_norm_a`,
// `sq_norm_b` and width `dim`: the worst-case rounding of a float dot product of `dim` terms
// (whatever the summation order), doubled for the norms and the two additions.
float GemmErrorBound(float sq_norm_a, float sq_norm_b, Eigen::Index dim);

// True when no value is NaN or +-Inf. Vectorised (Eigen's allFinite is a scalar loop, which
// costs as much as several k-means iterations on 20 000 x 128 descriptors).
bool AllFinite(const DescriptorMatrix& m);

// For each row of `queries`, the index of the nearest row of `references` in exact arithmetic,
// ties to the lowest index (as numpy.argmin). Float GEMM screens; candidates within
// 2 x GemmErrorBound of the float minimum are compared with ExactSquaredL2.
std::vector<int> NearestRows(const DescriptorMatrix& queries, const DescriptorMatrix& references);

}  // namespace dvpr
