#include "agents/algorithms/l2.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dvpr {

Eigen::VectorXf SquaredNorms(const DescriptorMatrix& m) { return m.rowwise().squaredNorm(); }

DistanceMatrix SquaredL2(const DescriptorMatrix& a, const DescriptorMatrix& b) {
  DistanceMatrix out;
  SquaredL2Rows(a, SquaredNorms(a), 0, a.rows(), b, SquaredNorms(b), out);
  return out;
}

void SquaredL2Rows(const DescriptorMatrix& a, const Eigen::VectorXf& a_norms, Eigen::Index first,
                   Eigen::Index count, const DescriptorMatrix& b, const Eigen::VectorXf& b_norms,
                   DistanceMatrix& out) {
  if (a.cols() != b.cols()) {
    throw std::invalid_argument("SquaredL2: descriptor widths differ (" + std::to_string(a.cols()) +
                                " vs " + std::to_string(b.cols()) + ")");
  }
  if (first < 0 || count < 0 || first + count > a.rows()) {
    throw std::out_of_range("SquaredL2Rows: rows out of range");
  }
  out.resize(count, b.rows());
  out.noalias() = a.middleRows(first, count) * b.transpose();
  for (Eigen::Index i = 0; i < count; ++i) {
    const float na = a_norms[first + i];
    float* row = out.row(i).data();
    for (Eigen::Index j = 0; j < b.rows(); ++j) {
      row[j] = std::max(0.0f, na - 2.0f * row[j] + b_norms[j]);
    }
  }
}

double ExactSquaredL2(const float* a, const float* b, Eigen::Index dim) {
  // Eight independent partial sums in a fixed order: vectorisable, yet deterministic.
  constexpr int kLanes = 8;
  double acc[kLanes] = {};
  Eigen::Index j = 0;
  for (; j + kLanes <= dim; j += kLanes) {
    for (int l = 0; l < kLanes; ++l) {
      const double diff = static_cast<double>(a[j + l]) - static_cast<double>(b[j + l]);
      acc[l] += diff * diff;
    }
  }
  for (int l = 0; j < dim; ++j, ++l) {
    const double diff = static_cast<double>(a[j]) - static_cast<double>(b[j]);
    acc[l] += diff * diff;
  }
  return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

float GemmErrorBound(float sq_norm_a, float sq_norm_b, Eigen::Index dim) {
  // |fl(x.y) - x.y| <= gamma_dim ||x|| ||y||, gamma_dim ~ dim * 2^-24; the three terms of
  // ||a||^2 - 2ab + ||b||^2 sum to at most (||a|| + ||b||)^2 in magnitude. Factor 2 for safety.
  const double scale = std::sqrt(static_cast<double>(sq_norm_a)) +
                       std::sqrt(static_cast<double>(sq_norm_b));
  return static_cast<float>(2.0 * static_cast<double>(dim + 4) * 0x1.0p-24 * scale * scale);
}

bool AllFinite(const DescriptorMatrix& m) {
  // x * 0 is 0 for finite x and NaN otherwise; independent lanes keep the sum vectorisable.
  constexpr int kLanes = 16;
  float acc[kLanes] = {};
  const float* p = m.data();
  const Eigen::Index n = m.size();
  Eigen::Index i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    for (int l = 0; l < kLanes; ++l) acc[l] += p[i + l] * 0.0f;
  }
  for (int l = 0; i < n; ++i, ++l) acc[l] += p[i] * 0.0f;
  float total = 0;
  for (float a : acc) total += a;
  return total == 0.0f;
}

std::vector<int> NearestRows(const DescriptorMatrix& queries, const DescriptorMatrix& references) {
  if (references.rows() == 0) throw std::invalid_argument("NearestRows: no references");
  const Eigen::VectorXf q_norms = SquaredNorms(queries);
  const Eigen::VectorXf r_norms = SquaredNorms(references);
  const float r_max = r_norms.maxCoeff();
  DistanceMatrix d;
  SquaredL2Rows(queries, q_norms, 0, queries.rows(), references, r_norms, d);
  std::vector<int> nearest(static_cast<std::size_t>(queries.rows()));
  for (Eigen::Index i = 0; i < queries.rows(); ++i) {
    Eigen::Index best_float = 0;
    const float min_float = d.row(i).minCoeff(&best_float);
    const float limit = min_float + 2.0f * GemmErrorBound(q_norms[i], r_max, queries.cols());
    int best = static_cast<int>(best_float);
    double best_exact = std::numeric_limits<double>::infinity();
    for (Eigen::Index j = 0; j < references.rows(); ++j) {
      if (d(i, j) > limit) continue;
      const double exact = ExactSquaredL2(queries.row(i).data(), references.row(j).data(),
                                          queries.cols());
      if (exact < best_exact) {  // strict: ties keep the lowest index
        best_exact = exact;
        best = static_cast<int>(j);
      }
    }
    nearest[static_cast<std::size_t>(i)] = best;
  }
  return nearest;
}

}  // namespace dvpr
