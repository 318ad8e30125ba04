#pragma once
// Dot products of a group of points with all k-means centroids, bit for bit as Eigen 3.4's GEMM
// computes the same entries of points x centroids^T (a row-major product, so Eigen's kernel runs
// on centroids x points: the centroids are its packed rows, the points its columns in groups of 4).
//
// Why: k-means labels each point by the nearest centroid in that product, and its labels (so the
// paper sweep's numbers) depend on each entry's rounding. Eigen's kernel sums a centroid row in
// one of three orders, fixed by where the row falls among the k rows (the kernel's peeled panels;
// x86-64-v3: AVX, FMA, packets of 8 floats); every point in a full group of 4 columns gets the
// same order:
//   - rows in panels of 24 or 16: one fused multiply-add chain over the dimensions, in order;
//   - rows in panels of 8 or 4: two chains (even and odd dimensions), added at the end;
//   - the last k mod 4 rows: eight chains (dimension mod 8), added as
//     ((s0 + s2) + (s4 + s6)) + ((s1 + s3) + (s5 + s7)).
// Points in the last (columns mod 4) of a product (and a 1-column product, Eigen's GEMV) take
// other paths; they stay with Eigen. Knowing the order, the kernel below scores 16 points a step
// with the points in the vector lanes: no packing, and the centroids read straight from their
// rows. tests/agents/test_kmeans_dots.cpp checks every entry against Eigen's product.
#include <Eigen/Core>

#if defined(EIGEN_VECTORIZE_AVX) && defined(EIGEN_VECTORIZE_FMA) && !defined(EIGEN_VECTORIZE_AVX512)
#define DVPR_KMEANS_DOTS 1
#else
#define DVPR_KMEANS_DOTS 0
#endif

namespace dvpr {

enum class DotChain { kOne, kEvenOdd, kEight };

// The summation order Eigen's kernel gives centroid row c of k: its panels of 3, 2 and 1
// packets of 8 rows, then of 4, then single rows.
inline DotChain ChainOf(Eigen::Index c, Eigen::Index k) {
  const Eigen::Index in24 = k / 24 * 24;
  const Eigen::Index in16 = in24 + (k - in24) / 16 * 16;
  const Eigen::Index in8 = in16 + (k - in16) / 8 * 8;
  const Eigen::Index in4 = in8 + (k - in8) / 4 * 4;
  if (c < in16) return DotChain::kOne;
  if (c < in4) return DotChain::kEvenOdd;
  return DotChain::kEight;
}

// Whether GroupDots reproduces Eigen here: this build has the kernel (AVX, FMA, no AVX-512), the
// width d is a multiple of 8 within [16, 128] (one depth block, no peeling remainder, never a
// coefficient-wise product), and 2 <= k with 12 k d <= 32768 bytes (the centroids are never cut
// into row blocks, whatever the caches).
bool DotsReplicable(Eigen::Index k, Eigen::Index d);

constexpr int kGroupPoints = 16;         // points scored together (one AVX-512 or two AVX registers)
constexpr Eigen::Index kMaxDotsDim = 128;

// A group's points, transposed: value p of point `lane` at xt[16 p + lane] (d x 16 floats,
// 64-byte aligned); lanes from `count` on are zero. d a multiple of 8, at most kMaxDotsDim.
void TransposeGroup(const float* const* rows, int count, Eigen::Index d, float* xt);

// Which instructions GroupDots uses; both give the same bits (each lane is its own sum).
enum class DotsKernel { kBest, kAvx2, kAvx512 };
bool HasAvx512Dots();  // this CPU runs DotsKernel::kAvx512

// dots[16 c + lane] = (point `lane` of xt) . (centroid c), c < k, each summed in the order of
// ChainOf(c, k), as Eigen's product gives it for a point in a full group of 4 columns.
// `centroids`: k x d, row-major. DotsReplicable(k, d) must hold.
void GroupDots(const float* xt, Eigen::Index d, const float* centroids, Eigen::Index k, float* dots,
               DotsKernel kernel = DotsKernel::kBest);

}  // namespace dvpr
