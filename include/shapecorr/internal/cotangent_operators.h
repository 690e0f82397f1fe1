// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: cotangent Laplacian and lumped mass matrix from an intrinsic triangulation.
// Sign convention (one for the whole library): L is positive semi-definite,
//   (L u)_i = 1/2 sum_j (cot a_ij + cot b_ij) (u_i - u_j),   L 1 = 0.
// Mass: lumped barycentric, M_ii = sum over incident faces of area/3, or mixed Voronoi (Meyer,
// Desbrun, Schroeder & Barr 2003). Graph Laplacian: degree - adjacency over the mesh edges.
#ifndef SHAPECORR_INTERNAL_COTANGENT_OPERATORS_H
#define SHAPECORR_INTERNAL_COTANGENT_OPERATORS_H

#include <shapecorr/internal/intrinsic_triangulation.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

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

/// Mixed Voronoi areas (Meyer et al. 2003): in a non-obtuse triangle each corner gets its Voronoi
/// region, 1/8 (l_ij^2 cot(angle k) + l_ik^2 cot(angle j)); in an obtuse one the obtuse corner gets
/// half the area and the two others a quarter. The areas sum to the surface area.
inline Eigen::VectorXd mixed_voronoi_mass(const Intrinsic_triangulation& t) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(t.n_vertices));
  for(std::size_t f = 0; f < t.number_of_faces(); ++f) {
    const double A = t.area(f);
    if(!(A > 0)) continue;
    // halfedge 3f+k runs from corner k to corner k+1; the angle at corner k is opposite 3f+(k+1)%3
    std::array<double, 3> cot, sq;
    for(int k = 0; k < 3; ++k) {
      cot[static_cast<std::size_t>(k)] = t.cotan_opposite(static_cast<int>(3 * f) + (k + 1) % 3);
      const double l = t.length[3 * f + static_cast<std::size_t>(k)];
      sq[static_cast<std::size_t>(k)] = l * l; // edge k -> k+1
    }
    int obtuse = -1;
    for(int k = 0; k < 3; ++k)
      if(cot[static_cast<std::size_t>(k)] < 0) obtuse = k;
    for(int k = 0; k < 3; ++k) {
      const std::size_t kk = static_cast<std::size_t>(k), k1 = static_cast<std::size_t>((k + 1) % 3),
                        k2 = static_cast<std::size_t>((k + 2) % 3);
      double a;
      if(obtuse < 0) a = 0.125 * (sq[kk] * cot[k2] + sq[k2] * cot[k1]); // edges k->k+1 (opposite k+2), k+2->k (opposite k+1)
      else a = (obtuse == k) ? 0.5 * A : 0.25 * A;
      m[t.faces[f][kk]] += a;
    }
  }
  return m;
}

/// Graph Laplacian L = D - A of the mesh edges (each undirected edge once, weight 1): positive
/// semi-definite, L 1 = 0.
/// The edges of the triangles, each once as (smaller index, larger index), sorted; edges whose
/// ends coincide are left out.
inline std::vector<std::pair<int, int>> unique_edges(const Triangle_arrays& a) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * a.number_of_faces());
  for(Eigen::Index f = 0; f < a.F.rows(); ++f)
    for(int k = 0; k < 3; ++k) {
      const int i = a.F(f, k), j = a.F(f, (k + 1) % 3);
      if(i != j) edges.emplace_back(std::min(i, j), std::max(i, j));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

inline Eigen::SparseMatrix<double> combinatorial_laplacian(const Triangle_arrays& a) {
  const std::vector<std::pair<int, int>> edges = unique_edges(a);
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(4 * edges.size());
  for(const auto& e : edges) {
    trip.emplace_back(e.first, e.second, -1.0);
    trip.emplace_back(e.second, e.first, -1.0);
    trip.emplace_back(e.first, e.first, 1.0);
    trip.emplace_back(e.second, e.second, 1.0);
  }
  const auto n = static_cast<Eigen::Index>(a.number_of_vertices());
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(trip.begin(), trip.end());
  return L;
}

} // namespace internal
} // namespace shapecorr

#endif
