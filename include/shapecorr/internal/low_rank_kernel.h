// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the leading eigenpairs of a Gaussian kernel matrix G_ij = exp(−|y_i − y_j|² / (2 β²))
// without forming G (M × M), by the Nyström method: L landmark points (furthest point sampling,
// from point 0), C = G(all, landmarks) (M × L), G ≈ C W⁺ Cᵀ with W = G(landmarks, landmarks);
// then the exact eigenpairs of that low-rank matrix. With L = M it is G's own decomposition.
// Why not Lanczos on G itself (Spectra): every product G v is an M² Gauss sum at a bandwidth that
// covers most of the shape (β = 2 in CPD's normalized units), so hundreds of them cost more than
// the whole registration; the kernel is smooth at that scale, and a few hundred landmarks capture
// its leading eigenpairs (tests compare with the dense decomposition).
#ifndef SHAPECORR_INTERNAL_LOW_RANK_KERNEL_H
#define SHAPECORR_INTERNAL_LOW_RANK_KERNEL_H

#include <shapecorr/internal/furthest_point_order.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shapecorr {
namespace internal {

/// G ≈ Q diag(lambda) Qᵀ, Q with orthonormal columns, lambda decreasing.
struct Low_rank_kernel {
  Eigen::MatrixXd Q;
  Eigen::VectorXd lambda;
};

/// Indices of `count` points of the rows of Y by Euclidean furthest point sampling from row 0.
inline std::vector<std::size_t> euclidean_furthest_points(const Eigen::MatrixXd& Y, std::size_t count) {
  const std::size_t n = static_cast<std::size_t>(Y.rows());
  return furthest_point_sampling_indices(n, std::min(count, n), 0, true, [&](std::size_t i) {
    return Eigen::VectorXd((Y.rowwise() - Y.row(static_cast<Eigen::Index>(i))).rowwise().norm());
  });
}

/// The `rank` leading eigenpairs of the Gaussian kernel of the rows of Y (M × 3) with width beta,
/// from `samples` landmarks (clamped to [rank, M]).
inline Low_rank_kernel gaussian_kernel_eigenpairs(const Eigen::MatrixXd& Y, double beta, std::size_t rank, std::size_t samples) {
  const std::size_t M = static_cast<std::size_t>(Y.rows());
  rank = std::min(rank, M);
  samples = std::min(std::max(samples, rank), M);
  const std::vector<std::size_t> landmark = euclidean_furthest_points(Y, samples);
  const Eigen::Index L = static_cast<Eigen::Index>(landmark.size());
  const double inverse_two_b2 = 1.0 / (2 * beta * beta);
  Eigen::MatrixXd C(static_cast<Eigen::Index>(M), L);
  for(Eigen::Index l = 0; l < L; ++l) {
    const Eigen::RowVector3d z = Y.row(static_cast<Eigen::Index>(landmark[static_cast<std::size_t>(l)]));
    C.col(l) = (-(Y.rowwise() - z).rowwise().squaredNorm() * inverse_two_b2).array().exp().matrix();
  }
  Eigen::MatrixXd W(L, L);
  for(Eigen::Index l = 0; l < L; ++l) W.row(l) = C.row(static_cast<Eigen::Index>(landmark[static_cast<std::size_t>(l)]));
  W = 0.5 * (W + W.transpose());
  // W⁺^{1/2} on its numerically non-zero eigenvalues
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> we(W);
  const double top = we.eigenvalues().maxCoeff();
  std::vector<Eigen::Index> keep;
  for(Eigen::Index k = 0; k < L; ++k)
    if(we.eigenvalues()(k) > 1e-12 * top) keep.push_back(k);
  Eigen::MatrixXd root(L, static_cast<Eigen::Index>(keep.size())); // U_r S_r^{-1/2}
  for(std::size_t k = 0; k < keep.size(); ++k) root.col(static_cast<Eigen::Index>(k)) = we.eigenvectors().col(keep[k]) / std::sqrt(we.eigenvalues()(keep[k]));
  const Eigen::MatrixXd Z = C * root; // G̃ = Z Zᵀ
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ze(Z.transpose() * Z);
  const Eigen::Index r = std::min<Eigen::Index>(static_cast<Eigen::Index>(rank), Z.cols());
  Low_rank_kernel out;
  out.Q.resize(static_cast<Eigen::Index>(M), r);
  out.lambda.resize(r);
  const Eigen::Index last = Z.cols() - 1;
  Eigen::Index used = 0;
  for(Eigen::Index k = 0; k < r; ++k) {
    const double s = ze.eigenvalues()(last - k); // ascending order: the largest last
    if(!(s > 0)) break;
    out.lambda(k) = s;
    out.Q.col(k) = Z * ze.eigenvectors().col(last - k) / std::sqrt(s);
    ++used;
  }
  out.Q.conservativeResize(Eigen::NoChange, used);
  out.lambda.conservativeResize(used);
  return out;
}

} // namespace internal
} // namespace shapecorr

#endif
