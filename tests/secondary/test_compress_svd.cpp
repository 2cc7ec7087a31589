// The streaming randomized SVD against Eigen's exact SVD.
#include <doctest/doctest.h>

#include "core/error.h"
#include "core/rng.h"
#include "secondary/offline/cloth_svd.h"

using namespace throng;
using namespace throng::secondary;

namespace {
// A rows × cols matrix with singular values 2^-k (k < rank) plus small noise.
Eigen::MatrixXf lowRankMatrix(int rows, int cols, int rank, float noise, uint64_t seed) {
  Rng rng(seed);
  auto random = [&](int r, int c) {
    Eigen::MatrixXf m(r, c);
    for (int j = 0; j < c; ++j)
      for (int i = 0; i < r; ++i) m(i, j) = rng.uniform(-1.0f, 1.0f);
    return m;
  };
  Eigen::HouseholderQR<Eigen::MatrixXf> qu(random(rows, rank)), qv(random(cols, rank));
  Eigen::MatrixXf u = qu.householderQ() * Eigen::MatrixXf::Identity(rows, rank);
  Eigen::MatrixXf v = qv.householderQ() * Eigen::MatrixXf::Identity(cols, rank);
  Eigen::VectorXf s(rank);
  for (int k = 0; k < rank; ++k) s[k] = 10.0f * std::pow(0.5f, float(k));
  return u * s.asDiagonal() * v.transpose() + noise * random(rows, cols);
}

ColumnSource sourceOf(const Eigen::MatrixXf& m, uint32_t blockColumns) {
  ColumnSource s;
  s.rows = uint32_t(m.rows());
  s.cols = uint32_t(m.cols());
  s.blockColumns = blockColumns;
  s.read = [&m](uint32_t first, Eigen::MatrixXf& block) {
    block = m.middleCols(first, block.cols());
  };
  return s;
}

// All singular values of d, largest first, exactly (to double precision): the square roots of
// the eigenvalues of d dᵀ. (Eigen's SVD classes would give the same at several times the
// compile time of this whole test.)
Eigen::VectorXd exactSingularValues(const Eigen::MatrixXf& d) {
  const Eigen::MatrixXd m = d.cast<double>();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(m * m.transpose(), Eigen::EigenvaluesOnly);
  REQUIRE(eigen.info() == Eigen::Success);
  return eigen.eigenvalues().reverse().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace

TEST_CASE("randomized SVD: singular values and subspace match the exact SVD") {
  Eigen::MatrixXf d = lowRankMatrix(180, 700, 12, 1e-4f, 3);
  SvdOptions options;
  options.rank = 8;
  options.threads = 2;
  TruncatedSvd svd = randomizedSvd(sourceOf(d, 64), options);
  REQUIRE(svd.bases.rows() == 180);
  REQUIRE(svd.bases.cols() == 8);
  REQUIRE(svd.coefficients.rows() == 8);
  REQUIRE(svd.coefficients.cols() == 700);
  const Eigen::VectorXd exact = exactSingularValues(d);
  for (int k = 0; k < 8; ++k)
    CHECK(svd.singularValues[k] == doctest::Approx(exact[k]).epsilon(1e-3));
  // Orthonormal bases, C = Uᵀ D, and the rank-8 residual equals the exact one (σ_9.. energy).
  CHECK(
      (svd.bases.transpose() * svd.bases - Eigen::MatrixXf::Identity(8, 8)).cwiseAbs().maxCoeff() <
      1e-4f);
  CHECK((svd.coefficients - svd.bases.transpose() * d).cwiseAbs().maxCoeff() < 1e-3f);
  float residual = (d - svd.bases * svd.coefficients).norm();
  const float best = float(exact.tail(exact.size() - 8).norm());
  CHECK(residual <= best * 1.01f + 1e-4f);
}

TEST_CASE("randomized SVD: deterministic, independent of the block size and thread count") {
  Eigen::MatrixXf d = lowRankMatrix(60, 300, 6, 1e-3f, 5);
  SvdOptions options;
  options.rank = 5;
  options.threads = 1;
  TruncatedSvd a = randomizedSvd(sourceOf(d, 7), options);
  options.threads = 2;
  TruncatedSvd b = randomizedSvd(sourceOf(d, 64), options);
  for (int k = 0; k < 5; ++k)
    CHECK(a.singularValues[k] == doctest::Approx(b.singularValues[k]).epsilon(1e-4));
  // Same subspace: the projections agree (bases may differ in sign).
  Eigen::MatrixXf pa = a.bases * a.bases.transpose(), pb = b.bases * b.bases.transpose();
  CHECK((pa - pb).cwiseAbs().maxCoeff() < 1e-3f);
}

TEST_CASE("randomized SVD: rank is capped by the matrix and bad input is reported") {
  Eigen::MatrixXf d = lowRankMatrix(30, 4, 3, 0.0f, 1);
  SvdOptions options;
  options.rank = 20;
  TruncatedSvd svd = randomizedSvd(sourceOf(d, 2), options);
  CHECK(svd.bases.cols() == 4);
  CHECK((d - svd.bases * svd.coefficients).cwiseAbs().maxCoeff() < 1e-4f);
  ColumnSource empty;
  empty.read = [](uint32_t, Eigen::MatrixXf&) {};
  CHECK_THROWS_WITH_AS(randomizedSvd(empty, options), doctest::Contains("empty matrix"), Error);
  ColumnSource failing = sourceOf(d, 2);
  failing.read = [](uint32_t first, Eigen::MatrixXf&) {
    if (first >= 2) throw Error("state 2 cannot be read");
  };
  CHECK_THROWS_WITH_AS(randomizedSvd(failing, options), doctest::Contains("state 2"), Error);
}
