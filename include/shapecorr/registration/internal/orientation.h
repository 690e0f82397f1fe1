// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The orientation of a map between two oriented triangle meshes. Of a dense vertex map: a source
// triangle whose corners go to three distinct target vertices keeps its turning sense when the
// image triangle's normal agrees with the target's normals there; a mirror map flips it. Of
// matched features (any resolution): the turning sense of each triple of features around the
// centre of the triple, from the gradients of their distance fields.
#ifndef SHAPECORR_REGISTRATION_INTERNAL_ORIENTATION_H
#define SHAPECORR_REGISTRATION_INTERNAL_ORIENTATION_H

#include <shapecorr/internal/indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace shapecorr {
namespace internal {

inline Eigen::Vector3d twice_area_normal(const Triangle_arrays& a, Eigen::Index f) {
  const Eigen::Vector3d p = a.V.row(a.F(f, 0)), q = a.V.row(a.F(f, 1)), r = a.V.row(a.F(f, 2));
  return (q - p).cross(r - p);
}

// Unit area-weighted vertex normals (the faces' orientation defines the outside).
inline Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> vertex_normals(const Triangle_arrays& a) {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> normals = Eigen::MatrixXd::Zero(a.V.rows(), 3);
  for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
    const Eigen::Vector3d n = twice_area_normal(a, f);
    for(int c = 0; c < 3; ++c) normals.row(a.F(f, c)) += n.transpose();
  }
  for(Eigen::Index v = 0; v < normals.rows(); ++v) {
    const double l = normals.row(v).norm();
    if(l > 0) normals.row(v) /= l;
  }
  return normals;
}

// The faces around each vertex.
inline std::vector<std::vector<int>> vertex_faces(const Triangle_arrays& a) {
  std::vector<std::vector<int>> incident(a.number_of_vertices());
  for(Eigen::Index f = 0; f < a.F.rows(); ++f)
    for(int c = 0; c < 3; ++c) incident[std::size_t(a.F(f, c))].push_back(int(f));
  return incident;
}

// The gradient at vertex v of a piecewise-linear field (the area-weighted mean of its faces'),
// projected onto the tangent plane of the unit normal n and normalized; zero where it vanishes.
inline Eigen::Vector3d unit_tangent_gradient(const Triangle_arrays& a, const std::vector<int>& faces_of_v, const Eigen::Vector3d& n,
                                             const Eigen::VectorXd& field) {
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for(int f : faces_of_v) {
    const Eigen::Vector3d n2 = twice_area_normal(a, f); // 2A N
    const double twice_area = n2.norm();
    if(!(twice_area > 0)) continue;
    const Eigen::Vector3d N = n2 / twice_area;
    for(int c = 0; c < 3; ++c) { // the face's gradient Σ f_c N × e_c / (2A) (e_c: the edge opposite c), weighted by A
      const Eigen::Vector3d e = a.V.row(a.F(f, (c + 2) % 3)) - a.V.row(a.F(f, (c + 1) % 3));
      g += 0.5 * field[a.F(f, c)] * N.cross(e);
    }
  }
  g -= n.dot(g) * n;
  const double l = g.norm();
  return l > 0 ? Eigen::Vector3d(g / l) : Eigen::Vector3d::Zero();
}

// The turning sense of each triple of features (a, b, c), intrinsically: at the vertex x that
// minimizes max(d_a, d_b, d_c) (the centre of the triple's smallest enclosing geodesic disc,
// defined by distances alone, so an isometry takes it to the image triple's centre),
// O(a, b, c) = n_x · (g_a × g_b + g_b × g_c + g_c × g_a) with g the unit gradients of the
// distance fields at x: twice the signed area of the triangle of the three directions, positive
// when the features turn counter-clockwise around x seen from outside. Kept by an
// orientation-preserving isometry, flipped by a reflection. Returns the n × n × n table
// (row-major, antisymmetric: a permutation of (a, b, c) multiplies it by its sign).
inline std::vector<double> triple_orientations(const Triangle_arrays& a, const std::vector<std::vector<int>>& faces_of,
                                               const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& normals,
                                               const std::vector<const Eigen::VectorXd*>& fields) {
  const std::size_t n = fields.size(), V = a.number_of_vertices();
  std::vector<double> O(n * n * n, 0.0);
  auto at = [&](std::size_t i, std::size_t j, std::size_t k) -> double& { return O[(i * n + j) * n + k]; };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      for(std::size_t k = j + 1; k < n; ++k) {
        const Eigen::VectorXd &fi = *fields[i], &fj = *fields[j], &fk = *fields[k];
        std::size_t x = 0;
        double best = std::numeric_limits<double>::infinity();
        for(std::size_t v = 0; v < V; ++v) {
          const double r = std::max({fi[long(v)], fj[long(v)], fk[long(v)]});
          if(r < best) { best = r; x = v; }
        }
        const Eigen::Vector3d nx = normals.row(long(x)).transpose();
        const Eigen::Vector3d gi = unit_tangent_gradient(a, faces_of[x], nx, fi), gj = unit_tangent_gradient(a, faces_of[x], nx, fj),
                              gk = unit_tangent_gradient(a, faces_of[x], nx, fk);
        const double o = nx.dot(gi.cross(gj) + gj.cross(gk) + gk.cross(gi));
        at(i, j, k) = at(j, k, i) = at(k, i, j) = o;
        at(j, i, k) = at(i, k, j) = at(k, j, i) = -o;
      }
  return O;
}

// The orientation score of matches (s_m, t_m) (positions in the two tables' feature lists): over
// the triples of matches, Σ Os(s) Ot(t) / Σ |Os(s) Ot(t)|, in [-1, 1] (+1: every triple turns the
// same way on both shapes; -1: a mirror); 0 when no triple is informative.
inline double triple_orientation_score(const std::vector<double>& Os, std::size_t ns, const std::vector<double>& Ot, std::size_t nt,
                                       const std::vector<std::size_t>& s, const std::vector<std::size_t>& t) {
  double sum = 0, weight = 0;
  for(std::size_t a = 0; a < s.size(); ++a)
    for(std::size_t b = a + 1; b < s.size(); ++b)
      for(std::size_t c = b + 1; c < s.size(); ++c) {
        const double p = Os[(s[a] * ns + s[b]) * ns + s[c]] * Ot[(t[a] * nt + t[b]) * nt + t[c]];
        sum += p;
        weight += std::abs(p);
      }
  return weight > 0 ? sum / weight : 0.0;
}

// The orientation agreement of a vertex map (`map[v]`: the target vertex of source vertex v):
// over the source faces whose corners go to three distinct target vertices, the source-area-weighted mean of the sign of (image triangle's normal) · (sum of the
// target's normals at its corners), in [-1, 1]; +1 orientation-preserving, -1 a mirror; 0 when
// no face counts.
inline double orientation_agreement(const Triangle_arrays& s, const Triangle_arrays& t,
                                    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& target_normals,
                                    const std::vector<std::size_t>& map) {
  double sum = 0, weight = 0;
  for(Eigen::Index f = 0; f < s.F.rows(); ++f) {
    const std::size_t U = map[std::size_t(s.F(f, 0))], V = map[std::size_t(s.F(f, 1))], W = map[std::size_t(s.F(f, 2))];
    if(U == V || V == W || U == W) continue;
    const Eigen::Vector3d pu = t.V.row(long(U)), pv = t.V.row(long(V)), pw = t.V.row(long(W));
    const Eigen::Vector3d ref = (target_normals.row(long(U)) + target_normals.row(long(V)) + target_normals.row(long(W))).transpose();
    const double d = (pv - pu).cross(pw - pu).dot(ref);
    if(d == 0) continue;
    const double area = 0.5 * twice_area_normal(s, f).norm();
    sum += d > 0 ? area : -area;
    weight += area;
  }
  return weight > 0 ? sum / weight : 0.0;
}

} // namespace internal
} // namespace shapecorr

#endif
