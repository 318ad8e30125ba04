#include "agents/algorithms/kmeans_dots.h"

#if DVPR_KMEANS_DOTS
#include <immintrin.h>
#endif

namespace dvpr {

using EigenIndex = Eigen::Index;

bool DotsReplicable(EigenIndex k, EigenIndex d) {
  return DVPR_KMEANS_DOTS && d % 8 == 0 && d >= 16 && d <= kMaxDotsDim && k >= 2 && k * d * 12 <= 32768;
}

#if DVPR_KMEANS_DOTS

namespace {

// Where the chain orders change among the k centroid rows (ChainOf): [0, one) one chain,
// [one, even_odd) even and odd chains, the rest eight chains.
struct ChainRanges {
  EigenIndex one;
  EigenIndex even_odd;
};

ChainRanges RangesOf(EigenIndex k) {
  ChainRanges r{0, 0};
  while (r.one < k && ChainOf(r.one, k) == DotChain::kOne) ++r.one;
  r.even_odd = r.one;
  while (r.even_odd < k && ChainOf(r.even_odd, k) == DotChain::kEvenOdd) ++r.even_odd;
  return r;
}

// 8 x 8 floats: row r of the input becomes lane r of r[0..7].
void Transpose8(__m256 r[8]) {
  const __m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
  const __m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
  const __m256 t4 = _mm256_unpacklo_ps(r[4], r[5]), t5 = _mm256_unpackhi_ps(r[4], r[5]);
  const __m256 t6 = _mm256_unpacklo_ps(r[6], r[7]), t7 = _mm256_unpackhi_ps(r[6], r[7]);
  const __m256 u0 = _mm256_shuffle_ps(t0, t2, 0x44), u1 = _mm256_shuffle_ps(t0, t2, 0xEE);
  const __m256 u2 = _mm256_shuffle_ps(t1, t3, 0x44), u3 = _mm256_shuffle_ps(t1, t3, 0xEE);
  const __m256 u4 = _mm256_shuffle_ps(t4, t6, 0x44), u5 = _mm256_shuffle_ps(t4, t6, 0xEE);
  const __m256 u6 = _mm256_shuffle_ps(t5, t7, 0x44), u7 = _mm256_shuffle_ps(t5, t7, 0xEE);
  r[0] = _mm256_permute2f128_ps(u0, u4, 0x20), r[1] = _mm256_permute2f128_ps(u1, u5, 0x20);
  r[2] = _mm256_permute2f128_ps(u2, u6, 0x20), r[3] = _mm256_permute2f128_ps(u3, u7, 0x20);
  r[4] = _mm256_permute2f128_ps(u0, u4, 0x31), r[5] = _mm256_permute2f128_ps(u1, u5, 0x31);
  r[6] = _mm256_permute2f128_ps(u2, u6, 0x31), r[7] = _mm256_permute2f128_ps(u3, u7, 0x31);
}

// The product adds each sum to a zeroed result (a fused multiply-add by alpha = 1): + 0 turns
// a -0 into +0 as it does.
__m256 Finish(__m256 sum) { return _mm256_add_ps(sum, _mm256_setzero_ps()); }

// AVX: the 16 lanes as two registers (low and high). One chain a centroid, C centroids side by side.
template <int C>
void OneChain256(const float* xt, EigenIndex d, const float* c, float* out) {
  __m256 lo[C], hi[C];
  for (int j = 0; j < C; ++j) lo[j] = _mm256_setzero_ps(), hi[j] = _mm256_setzero_ps();
  for (EigenIndex p = 0; p < d; ++p) {
    const __m256 xl = _mm256_load_ps(xt + 16 * p);
    const __m256 xh = _mm256_load_ps(xt + 16 * p + 8);
    for (int j = 0; j < C; ++j) {
      const __m256 b = _mm256_broadcast_ss(c + j * d + p);
      lo[j] = _mm256_fmadd_ps(xl, b, lo[j]);
      hi[j] = _mm256_fmadd_ps(xh, b, hi[j]);
    }
  }
  for (int j = 0; j < C; ++j) {
    _mm256_storeu_ps(out + 16 * j, Finish(lo[j]));
    _mm256_storeu_ps(out + 16 * j + 8, Finish(hi[j]));
  }
}

// Even and odd dimensions in two chains, added at the end (Eigen's 1- and half-packet panels).
template <int C>
void EvenOdd256(const float* xt, EigenIndex d, const float* c, float* out) {
  __m256 el[C], eh[C], ol[C], oh[C];
  for (int j = 0; j < C; ++j) {
    el[j] = _mm256_setzero_ps(), eh[j] = el[j], ol[j] = el[j], oh[j] = el[j];
  }
  for (EigenIndex p = 0; p < d; p += 2) {
    const __m256 x0l = _mm256_load_ps(xt + 16 * p), x0h = _mm256_load_ps(xt + 16 * p + 8);
    const __m256 x1l = _mm256_load_ps(xt + 16 * p + 16), x1h = _mm256_load_ps(xt + 16 * p + 24);
    for (int j = 0; j < C; ++j) {
      const __m256 b0 = _mm256_broadcast_ss(c + j * d + p);
      const __m256 b1 = _mm256_broadcast_ss(c + j * d + p + 1);
      el[j] = _mm256_fmadd_ps(x0l, b0, el[j]), eh[j] = _mm256_fmadd_ps(x0h, b0, eh[j]);
      ol[j] = _mm256_fmadd_ps(x1l, b1, ol[j]), oh[j] = _mm256_fmadd_ps(x1h, b1, oh[j]);
    }
  }
  for (int j = 0; j < C; ++j) {
    _mm256_storeu_ps(out + 16 * j, Finish(_mm256_add_ps(el[j], ol[j])));
    _mm256_storeu_ps(out + 16 * j + 8, Finish(_mm256_add_ps(eh[j], oh[j])));
  }
}

// Eight chains by dimension mod 8 (Eigen's single-row path), for the 8 lanes from xt on.
void EightHalf256(const float* xt, EigenIndex d, const float* c, float* out) {
  __m256 s[8];
  for (auto& v : s) v = _mm256_setzero_ps();
  for (EigenIndex p = 0; p < d; p += 8) {
    for (int m = 0; m < 8; ++m) s[m] = _mm256_fmadd_ps(_mm256_load_ps(xt + 16 * (p + m)), _mm256_broadcast_ss(c + p + m), s[m]);
  }
  const __m256 low = _mm256_add_ps(_mm256_add_ps(s[0], s[2]), _mm256_add_ps(s[4], s[6]));
  const __m256 high = _mm256_add_ps(_mm256_add_ps(s[1], s[3]), _mm256_add_ps(s[5], s[7]));
  _mm256_storeu_ps(out, Finish(_mm256_add_ps(low, high)));
}

void GroupDots256(const float* xt, EigenIndex d, const float* centroids, EigenIndex k, float* dots) {
  const ChainRanges r = RangesOf(k);
  EigenIndex c = 0;
  for (; c + 4 <= r.one; c += 4) OneChain256<4>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c < r.one; ++c) OneChain256<1>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c + 2 <= r.even_odd; c += 2) EvenOdd256<2>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c < r.even_odd; ++c) EvenOdd256<1>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c < k; ++c) {
    EightHalf256(xt, d, centroids + c * d, dots + 16 * c);
    EightHalf256(xt + 8, d, centroids + c * d, dots + 16 * c + 8);
  }
}

// AVX-512: the 16 lanes in one register, the same sums (compiled for AVX-512 on its own and only
// called where the CPU runs it).
#define DVPR_AVX512 __attribute__((target("avx512f")))

DVPR_AVX512 __m512 Finish512(__m512 sum) { return _mm512_add_ps(sum, _mm512_setzero_ps()); }

template <int C>
DVPR_AVX512 void OneChain512(const float* xt, EigenIndex d, const float* c, float* out) {
  __m512 s[C];
  for (int j = 0; j < C; ++j) s[j] = _mm512_setzero_ps();
  for (EigenIndex p = 0; p < d; ++p) {
    const __m512 x = _mm512_load_ps(xt + 16 * p);
    for (int j = 0; j < C; ++j) s[j] = _mm512_fmadd_ps(x, _mm512_set1_ps(c[j * d + p]), s[j]);
  }
  for (int j = 0; j < C; ++j) _mm512_storeu_ps(out + 16 * j, Finish512(s[j]));
}

template <int C>
DVPR_AVX512 void EvenOdd512(const float* xt, EigenIndex d, const float* c, float* out) {
  __m512 e[C], o[C];
  for (int j = 0; j < C; ++j) e[j] = _mm512_setzero_ps(), o[j] = e[j];
  for (EigenIndex p = 0; p < d; p += 2) {
    const __m512 x0 = _mm512_load_ps(xt + 16 * p);
    const __m512 x1 = _mm512_load_ps(xt + 16 * p + 16);
    for (int j = 0; j < C; ++j) {
      e[j] = _mm512_fmadd_ps(x0, _mm512_set1_ps(c[j * d + p]), e[j]);
      o[j] = _mm512_fmadd_ps(x1, _mm512_set1_ps(c[j * d + p + 1]), o[j]);
    }
  }
  for (int j = 0; j < C; ++j) _mm512_storeu_ps(out + 16 * j, Finish512(_mm512_add_ps(e[j], o[j])));
}

DVPR_AVX512 void Eight512(const float* xt, EigenIndex d, const float* c, float* out) {
  __m512 s[8];
  for (auto& v : s) v = _mm512_setzero_ps();
  for (EigenIndex p = 0; p < d; p += 8) {
    for (int m = 0; m < 8; ++m) s[m] = _mm512_fmadd_ps(_mm512_load_ps(xt + 16 * (p + m)), _mm512_set1_ps(c[p + m]), s[m]);
  }
  const __m512 low = _mm512_add_ps(_mm512_add_ps(s[0], s[2]), _mm512_add_ps(s[4], s[6]));
  const __m512 high = _mm512_add_ps(_mm512_add_ps(s[1], s[3]), _mm512_add_ps(s[5], s[7]));
  _mm512_storeu_ps(out, Finish512(_mm512_add_ps(low, high)));
}

DVPR_AVX512 void GroupDots512(const float* xt, EigenIndex d, const float* centroids, EigenIndex k, float* dots) {
  const ChainRanges r = RangesOf(k);
  EigenIndex c = 0;
  for (; c + 8 <= r.one; c += 8) OneChain512<8>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c < r.one; ++c) OneChain512<1>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c + 4 <= r.even_odd; c += 4) EvenOdd512<4>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c < r.even_odd; ++c) EvenOdd512<1>(xt, d, centroids + c * d, dots + 16 * c);
  for (; c < k; ++c) Eight512(xt, d, centroids + c * d, dots + 16 * c);
}

#undef DVPR_AVX512

}  // namespace

bool HasAvx512Dots() {
  static const bool has = __builtin_cpu_supports("avx512f");
  return has;
}

void TransposeGroup(const float* const* rows, int count, EigenIndex d, float* xt) {
  alignas(32) static constexpr float kZeros[kMaxDotsDim] = {};
  const float* from[kGroupPoints];  // missing points read zeros: no branch in the loop
  for (int lane = 0; lane < kGroupPoints; ++lane) from[lane] = lane < count ? rows[lane] : kZeros;
  for (int half = 0; half < 2; ++half) {
    for (EigenIndex p = 0; p < d; p += 8) {
      __m256 r[8];
      for (int lane = 0; lane < 8; ++lane) r[lane] = _mm256_loadu_ps(from[8 * half + lane] + p);
      Transpose8(r);
      for (int q = 0; q < 8; ++q) _mm256_store_ps(xt + 16 * (p + q) + 8 * half, r[q]);
    }
  }
}

void GroupDots(const float* xt, EigenIndex d, const float* centroids, EigenIndex k, float* dots, DotsKernel kernel) {
  const bool wide = kernel == DotsKernel::kAvx512 || (kernel == DotsKernel::kBest && HasAvx512Dots());
  if (wide) {
    GroupDots512(xt, d, centroids, k, dots);
  } else {
    GroupDots256(xt, d, centroids, k, dots);
  }
}

#else

bool HasAvx512Dots() { return false; }
void TransposeGroup(const float* const*, int, EigenIndex, float*) {}
void GroupDots(const float*, EigenIndex, const float*, EigenIndex, float*, DotsKernel) {}

#endif

}  // namespace dvpr
