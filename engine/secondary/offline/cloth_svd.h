#pragma once
// Randomized truncated SVD of a tall data matrix read in column blocks (Halko, Martinsson and
// Tropp 2011: random projection, power iterations, QR, small SVD). The matrix is never held
// whole: every pass streams its columns, so memory is rows × (rank + oversampling) plus one block.
#include <cstdint>
#include <functional>

#include <Eigen/Dense>

namespace throng::secondary {

// Columns [first, first + block.cols()) of a rows × cols matrix, written into `block` (already
// sized rows × count). Called many times with the same columns: it must be deterministic.
struct ColumnSource {
  uint32_t rows = 0;
  uint32_t cols = 0;
  uint32_t blockColumns = 256;
  std::function<void(uint32_t first, Eigen::MatrixXf& block)> read;
};

struct SvdOptions {
  uint32_t rank = 64;            // bases wanted
  uint32_t oversampling = 10;    // extra random directions (Halko's p)
  uint32_t powerIterations = 1;  // sharpen the spectrum (Halko's q)
  uint64_t seed = 1;
  unsigned threads = 0;  // 0: hardware concurrency
};

// D ≈ U · C: U (rows × r) has orthonormal columns sorted by decreasing singular value, and
// C = Uᵀ D (r × cols), the exact projection of D on U. r = min(rank, rows, cols).
struct TruncatedSvd {
  Eigen::MatrixXf bases;         // U
  Eigen::MatrixXf coefficients;  // C
  Eigen::VectorXf singularValues;
};

TruncatedSvd randomizedSvd(const ColumnSource& source, const SvdOptions& options);

// Runs `body(first, block)` over every column block, in parallel over `threads`; blocks are
// independent. `body` is called with a thread-local block holding the source's columns.
void forEachColumnBlock(
    const ColumnSource& source, unsigned threads,
    const std::function<void(uint32_t first, const Eigen::MatrixXf& block)>& body);

}  // namespace throng::secondary
