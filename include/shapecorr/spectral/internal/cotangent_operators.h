// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: cotangent Laplacian and lumped mass matrix from an intrinsic triangulation.
// Sign convention (one for the whole library): L is positive semi-definite,
//   (L u)_i = 1/2 sum_j (cot a_ij + cot b_ij) (u_i - u_j),   L 1 = 0.
// Mass: lumped barycentric, M_ii = sum over incident faces of area/3.
#ifndef SHAPECORR_SPECTRAL_INTERNAL_COTANGENT_OPERATORS_H
#define SHAPECORR_SPECTRAL_INTERNAL_COTANGENT_OPERATORS_H

#include <shapecorr/mesh/internal/intrinsic_triangulation.h>

#include <Eigen/Sparse>

namespace shapecorr {
namespace internal {

inline Eigen::SparseMatrix<double> cotangent_laplacian(const Intrinsic_triangulation& t) {
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(12 * t.number_of_faces());
  for(int h = 0; h < static_cast<int>(t.length.size()); ++h) {
    const double w = 0.5 * t.cotan_opposite(h);
    const int i = t.tail(h), j = t.head(h);
    trip.emplace_back(i, j, -w);
    trip.emplace_back(j, i, -w);
    trip.emplace_back(i, i, w);
    trip.emplace_back(j, j, w);
  }
  const auto n = static_cast<Eigen::Index>(t.n_vertices);
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(trip.begin(), trip.end());
  return L;
}

inline Eigen::VectorXd lumped_mass(const Intrinsic_triangulation& t) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(t.n_vertices));
  for(std::size_t f = 0; f < t.number_of_faces(); ++f) {
    const double a = t.area(f) / 3.0;
    for(int k = 0; k < 3; ++k) m[t.faces[f][static_cast<std::size_t>(k)]] += a;
  }
  return m;
}

} // namespace internal
} // namespace shapecorr

#endif
