#include "secondary/offline/cloth_svd.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "core/error.h"
#include "core/rng.h"

namespace throng::secondary {

namespace {
unsigned threadCount(unsigned requested) {
  if (requested) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

// Row j of the Gaussian test matrix Ω: seeded by the column index alone, so the sketch does not
// depend on the block size or on which thread reads the block.
void gaussianRow(uint64_t seed, uint32_t column, float* out, uint32_t count) {
  Rng rng(seed, uint64_t(column) + 1);
  for (uint32_t i = 0; i < count; i += 2) {
    float u1 = std::max(rng.uniform(), 1e-7f);
    float u2 = rng.uniform();
    float radius = std::sqrt(-2.0f * std::log(u1));
    out[i] = radius * std::cos(6.2831853f * u2);
    if (i + 1 < count) out[i + 1] = radius * std::sin(6.2831853f * u2);
  }
}

Eigen::MatrixXd orthonormalColumns(const Eigen::MatrixXd& m) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(m);
  return qr.householderQ() * Eigen::MatrixXd::Identity(m.rows(), m.cols());
}

// Y = D · X where X (cols × l) is given by rows; accumulated per thread, then summed.
Eigen::MatrixXd multiplyRight(
    const ColumnSource& source, unsigned threads, uint32_t l,
    const std::function<void(uint32_t first, Eigen::MatrixXf& xBlock)>& rowsOfX) {
  std::mutex mutex;
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(source.rows, l);
  forEachColumnBlock(source, threads, [&](uint32_t first, const Eigen::MatrixXf& block) {
    Eigen::MatrixXf x(block.cols(), l);
    rowsOfX(first, x);
    Eigen::MatrixXd part = (block * x).cast<double>();
    std::lock_guard<std::mutex> lock(mutex);
    y += part;
  });
  return y;
}

// Z = Dᵀ · Q (cols × l): disjoint rows per block.
Eigen::MatrixXd multiplyLeftTransposed(const ColumnSource& source, unsigned threads,
                                       const Eigen::MatrixXd& q) {
  Eigen::MatrixXf qf = q.cast<float>();
  Eigen::MatrixXd z(source.cols, q.cols());
  forEachColumnBlock(source, threads, [&](uint32_t first, const Eigen::MatrixXf& block) {
    z.middleRows(first, block.cols()) = (block.transpose() * qf).cast<double>();
  });
  return z;
}
}  // namespace

void forEachColumnBlock(
    const ColumnSource& source, unsigned threads,
    const std::function<void(uint32_t first, const Eigen::MatrixXf& block)>& body) {
  THRONG_CHECK(source.read && source.blockColumns > 0, "column source without a reader");
  const uint32_t blocks = (source.cols + source.blockColumns - 1) / source.blockColumns;
  std::atomic<uint32_t> next{0};
  std::mutex errorMutex;
  std::exception_ptr error;
  auto worker = [&] {
    Eigen::MatrixXf block;
    for (uint32_t b = next++; b < blocks; b = next++) {
      try {
        uint32_t first = b * source.blockColumns;
        uint32_t count = std::min(source.blockColumns, source.cols - first);
        block.resize(source.rows, count);
        source.read(first, block);
        body(first, block);
      } catch (...) {
        std::lock_guard<std::mutex> lock(errorMutex);
        if (!error) error = std::current_exception();
        next = blocks;
      }
    }
  };
  unsigned n = std::min<unsigned>(threadCount(threads), std::max(1u, blocks));
  std::vector<std::thread> pool;
  pool.reserve(n);
  for (unsigned t = 1; t < n; ++t) {
    try {  // a thread that cannot start: the shared counter lets the others take its blocks
      pool.emplace_back(worker);
    } catch (const std::system_error&) {
      break;
    }
  }
  worker();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

TruncatedSvd randomizedSvd(const ColumnSource& source, const SvdOptions& options) {
  if (source.rows == 0 || source.cols == 0)
    fail("SVD of an empty matrix (", source.rows, " × ", source.cols, ")");
  if (options.rank == 0) fail("SVD: the rank must be at least 1");
  const unsigned threads = threadCount(options.threads);
  const uint32_t l = std::min({options.rank + options.oversampling, source.rows, source.cols});
  const uint32_t rank = std::min(options.rank, l);

  // Sketch: Y = D Ω, then power iterations Y = D (Dᵀ Q) with re-orthonormalization.
  Eigen::MatrixXd y = multiplyRight(source, threads, l, [&](uint32_t first, Eigen::MatrixXf& x) {
    std::vector<float> row(l);
    for (Eigen::Index j = 0; j < x.rows(); ++j) {
      gaussianRow(options.seed, first + uint32_t(j), row.data(), l);
      for (uint32_t i = 0; i < l; ++i) x(j, i) = row[i];
    }
  });
  for (uint32_t it = 0; it < options.powerIterations; ++it) {
    Eigen::MatrixXd z =
        orthonormalColumns(multiplyLeftTransposed(source, threads, orthonormalColumns(y)));
    Eigen::MatrixXf zf = z.cast<float>();
    y = multiplyRight(source, threads, l, [&](uint32_t first, Eigen::MatrixXf& x) {
      x = zf.middleRows(first, x.rows());
    });
  }
  Eigen::MatrixXd q = orthonormalColumns(y);

  // Small problem: S = Qᵀ D (l × cols); its left singular vectors from the Gram matrix S Sᵀ.
  Eigen::MatrixXd small = multiplyLeftTransposed(source, threads, q).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(small * small.transpose());
  if (eigen.info() != Eigen::Success)
    fail("SVD: the eigen-solver of the small problem did not converge");
  // Eigenvalues come in increasing order: take the largest `rank`.
  Eigen::MatrixXd smallU(l, rank);
  TruncatedSvd out;
  out.singularValues.resize(rank);
  for (uint32_t i = 0; i < rank; ++i) {
    Eigen::Index src = Eigen::Index(l) - 1 - i;
    smallU.col(i) = eigen.eigenvectors().col(src);
    out.singularValues[i] = float(std::sqrt(std::max(0.0, eigen.eigenvalues()[src])));
  }
  out.bases = (q * smallU).cast<float>();
  out.coefficients = (smallU.transpose() * small).cast<float>();
  return out;
}

}  // namespace throng::secondary
