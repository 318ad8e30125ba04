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

}  // namespace dvpr
