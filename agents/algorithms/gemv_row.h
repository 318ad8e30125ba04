#pragma once
// One row of a float row-major matrix-vector product, bit for bit as the product over all
// `rows` rows computes it (Eigen 3.4's general_matrix_vector_product<RowMajor>).
//
// Why: the index's distances (and so the simulation's matches and the golden files) are those
// of one Eigen GEMV over the whole store. A search that skips most rows must still give the
// rows it keeps exactly that value. Eigen sums a row differently depending on where it falls:
// rows in blocks of 8, 4 and 2 share one code path, the last row of an odd count takes another
// (half packets for the width's tail), and a 1-row product is a dot product. Rather than copy
// the kernel, this calls the same Eigen product on the smallest run of neighbouring rows that
// puts row `i` on the path it took in the full product; tests check it against the full
// product for widths with and without a tail.
#include <Eigen/Core>

#if defined(EIGEN_VECTORIZE_AVX) && defined(EIGEN_VECTORIZE_FMA) && !defined(EIGEN_VECTORIZE_AVX512)
#include <immintrin.h>
#define DVPR_GEMV_ROW_KERNEL 1
#else
#define DVPR_GEMV_ROW_KERNEL 0
#endif

namespace dvpr {

// Row `i` of (data as rows x dim, row-major) * query, as the full product computes it.
inline float GemvRowAsInFullProduct(const float* data, Eigen::Index rows, int dim, Eigen::Index i,
                                    const float* query) {
  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  // Eigen's row-major kernel: blocks of 8 rows (none when a row is wider than 32000 bytes),
  // then one block of 4, one of 2, and a last single row.
  const bool eights = static_cast<Eigen::Index>(dim) * static_cast<Eigen::Index>(sizeof(float)) <= 32000;
  const Eigen::Index in_eights = eights ? rows / 8 * 8 : 0;
  Eigen::Index first = 0;
  Eigen::Index count = 0;
  Eigen::Index at = 0;  // position of row i in the sub-product
  if (rows == 1) {
    count = 1;  // the product's own dot-product path
  } else if (i < in_eights) {
    first = i / 8 * 8, count = 8;
  } else {
    const Eigen::Index rest = rows - in_eights;  // 0..7 rows: blocks of 4, 2, then 1
    const Eigen::Index k = i - in_eights;
    if (rest >= 4 && k < 4) {
      first = in_eights, count = 4;
    } else {
      const Eigen::Index after4 = in_eights + (rest >= 4 ? 4 : 0);
      const Eigen::Index rest2 = rows - after4;  // 0..3
      if (i < after4 + rest2 / 2 * 2) {
        first = after4 + (i - after4) / 2 * 2, count = 2;
      } else {
        first = i - 2, count = 3;  // a 2-row block before it keeps the single row on its path
      }
    }
  }
  at = i - first;
  const Eigen::Map<const RowMajor> block(data + first * dim, count, dim);
  const Eigen::Map<const Eigen::VectorXf> q(query, dim);
  Eigen::Matrix<float, Eigen::Dynamic, 1, 0, 8, 1> out(count);
  out.noalias() = block * q;
  return out[at];
}

// Eigen's kernel itself, for the case where every row takes one path: with AVX and FMA (and no
// AVX-512: x86-64-v3) a float row-major product of at least 2 rows and a width that is a multiple
// of 8 computes each row as one chain of fused multiply-adds over packets of 8 values, in order,
// then adds the packet's lanes as predux<Packet8f> does, ((l0 + l4) + (l2 + l6)) + ((l1 + l5) +
// (l3 + l7)); the blocks of 8, 4, 2 and 1 rows differ only in how many chains run side by side.
// Where that holds, the kernel below gives 8 rows at a time for the cost of reading them once,
// with no Eigen call; tests check it against the full product bit for bit.
inline bool GemvRowKernelMatches(Eigen::Index rows, int dim) {
  return DVPR_GEMV_ROW_KERNEL != 0 && rows >= 2 && dim > 0 && dim % 8 == 0;
}

#if DVPR_GEMV_ROW_KERNEL
namespace gemv_detail {
// Lane r of the result: predux<Packet8f>(c[r]), as Eigen adds the lanes (additions commute exactly).
inline __m256 PreduxEight(const __m256 (&c)[8]) {
  __m256 p[4];  // rows r and r + 4: their low and high halves added, l_k + l_(k+4)
  for (int r = 0; r < 4; ++r) {
    p[r] = _mm256_add_ps(_mm256_permute2f128_ps(c[r], c[r + 4], 0x20), _mm256_permute2f128_ps(c[r], c[r + 4], 0x31));
  }
  // Per 128-bit lane, rows (0, 1) and (2, 3): (a0 + a2, a1 + a3) of each row.
  const __m256 t01 = _mm256_add_ps(_mm256_shuffle_ps(p[0], p[1], 0x44), _mm256_shuffle_ps(p[0], p[1], 0xEE));
  const __m256 t23 = _mm256_add_ps(_mm256_shuffle_ps(p[2], p[3], 0x44), _mm256_shuffle_ps(p[2], p[3], 0xEE));
  // (a0 + a2) + (a1 + a3), rows 0..3 in the low lane, 4..7 in the high one.
  return _mm256_add_ps(_mm256_shuffle_ps(t01, t23, 0x88), _mm256_shuffle_ps(t01, t23, 0xDD));
}
}  // namespace gemv_detail

// rows[r] . query for r = 0..7 (each `dim` floats, dim a multiple of 8) into out[0..7], as the
// product computes them where GemvRowKernelMatches.
inline void GemvEightRows(const float* const* rows, const float* query, int dim, float* out) {
  __m256 c[8];
  for (auto& x : c) x = _mm256_setzero_ps();
  for (int j = 0; j < dim; j += 8) {
    const __m256 b = _mm256_loadu_ps(query + j);
    for (int r = 0; r < 8; ++r) c[r] = _mm256_fmadd_ps(_mm256_loadu_ps(rows[r] + j), b, c[r]);
  }
  // The product adds each row's sum to a zeroed result: + 0.0f turns a -0 into +0 as it does.
  _mm256_storeu_ps(out, _mm256_add_ps(gemv_detail::PreduxEight(c), _mm256_setzero_ps()));
}

// Whether this CPU runs GemvSixteenRows (AVX-512 F and DQ), asked once. The build targets
// x86-64-v3; the wider kernel is compiled for AVX-512 on its own and only called where it runs.
inline bool HasGemvSixteenRows() {
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  return has;
}

// GemvEightRows for 16 rows, bit for bit: each 512-bit register holds the 8-lane chains of rows
// r (low half) and r + 8 (high half), with the query's packet in both halves, so every lane sees
// the same fused multiply-adds in the same order as in GemvEightRows; the lanes are then added
// with the same reduction. Half the multiply-add instructions for the same rows.
__attribute__((target("avx512f,avx512dq"))) inline void GemvSixteenRows(const float* const* rows, const float* query,
                                                                       int dim, float* out) {
  // Halves joined and split with __builtin_shufflevector: GCC 12's AVX-512 intrinsics for that
  // (broadcast, cast, extract) trip its own -Wuninitialized on their undefined pass-through.
  __m512 c[8];
  for (auto& x : c) x = _mm512_setzero_ps();
  for (int j = 0; j < dim; j += 8) {
    const __m256 q = _mm256_loadu_ps(query + j);
    const __m512 b = __builtin_shufflevector(q, q, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7);
    for (int r = 0; r < 8; ++r) {
      const __m256 low = _mm256_loadu_ps(rows[r] + j);
      const __m256 high = _mm256_loadu_ps(rows[r + 8] + j);
      const __m512 x = __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
      c[r] = _mm512_fmadd_ps(x, b, c[r]);
    }
  }
  __m256 low[8];
  __m256 high[8];
  for (int r = 0; r < 8; ++r) {
    low[r] = __builtin_shufflevector(c[r], c[r], 0, 1, 2, 3, 4, 5, 6, 7);
    high[r] = __builtin_shufflevector(c[r], c[r], 8, 9, 10, 11, 12, 13, 14, 15);
  }
  _mm256_storeu_ps(out, _mm256_add_ps(gemv_detail::PreduxEight(low), _mm256_setzero_ps()));
  _mm256_storeu_ps(out + 8, _mm256_add_ps(gemv_detail::PreduxEight(high), _mm256_setzero_ps()));
}

// row . query alone, as GemvEightRows gives it.
inline float GemvOneRow(const float* row, const float* query, int dim) {
  __m256 c = _mm256_setzero_ps();
  for (int j = 0; j < dim; j += 8) c = _mm256_fmadd_ps(_mm256_loadu_ps(row + j), _mm256_loadu_ps(query + j), c);
  const __m128 a = _mm_add_ps(_mm256_castps256_ps128(c), _mm256_extractf128_ps(c, 1));
  const __m128 t = _mm_add_ps(a, _mm_movehl_ps(a, a));
  return _mm_cvtss_f32(_mm_add_ss(t, _mm_shuffle_ps(t, t, 1))) + 0.0f;
}
#endif

}  // namespace dvpr
