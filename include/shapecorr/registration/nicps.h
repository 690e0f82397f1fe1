// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file nicps.h
/// NICPS: non-rigid ICP with multiple two-way correspondences (thesis chapter 6; ALGORITHMS.md).
/// The template keeps its connectivity; its vertices move to minimize, at iteration f,
/// D(x) + α_f G(x): D the squared distances of the correspondence pairs (both ways), G a
/// regularizer, α_f = α₀ / γ^f.
#ifndef SHAPECORR_REGISTRATION_NICPS_H
#define SHAPECORR_REGISTRATION_NICPS_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/closest_point_tree.h>
#include <shapecorr/internal/cotangent_operators.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/internal/kd_tree.h>
#include <shapecorr/parallel.h>
#include <shapecorr/parameters.h>
#include <shapecorr/registration/registration_report.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrRegistration
/// The regularizer G of NICPS (named parameter `nicps_regularizer`).
enum class Nicps_regularizer {
  COMBINATORIAL_LAPLACIAN, ///< G = Σ_i |Δ_i x − Δ_i x⁰|², Δ_i x = Σ_{j∈N(i)} (x_j − x_i) (the thesis's choice)
  COTANGENT_LAPLACIAN,     ///< the same with Δ_i the cotangent Laplacian of x⁰ divided by the vertex area, times the mean vertex area (scale-free)
  EDGE                     ///< G = Σ_edges |(x_j − x_i) − (x_j⁰ − x_i⁰)|² (Pauly et al. 2005)
};

/// \ingroup PkgShapeCorrRegistration
/// One NICPS iteration: the common record (pairs = forward + inverse + landmark pairs; energy =
/// D + α G at the new positions; rms_distance = root mean square distance of the template's
/// vertices to the target after the update; step = the largest vertex displacement) and NICPS's own.
struct Nicps_iteration_record : Iteration_record {
  double alpha = 0;              ///< α_f
  std::size_t forward_pairs = 0; ///< template vertex → target surface point
  std::size_t inverse_pairs = 0; ///< target vertex → template surface point (barycentric in the unknowns)
  double seconds = 0;               ///< wall time of the iteration
  double search_seconds = 0;        ///< of which the correspondence search (both ways)
  double factorization_seconds = 0; ///< of which the numeric sparse Cholesky factorization
};

/// \ingroup PkgShapeCorrRegistration
/// The result of `nicps()`.
struct Nicps_report {
  std::vector<Nicps_iteration_record> iterations; ///< one per iteration
  Stop_reason stop = Stop_reason::ITERATION_LIMIT; ///< why it stopped
  double initial_rms = 0; ///< RMS distance of the template's vertices to the target before
  double final_rms = 0;   ///< and after
  double seconds = 0;     ///< wall time
};

namespace internal {

/// The closest point to p on the triangle (a, b, c) and its barycentric coordinates (Ericson,
/// Real-Time Collision Detection, 5.1.5).
inline Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                 const Eigen::Vector3d& c, Eigen::Vector3d& bary) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if(d1 <= 0 && d2 <= 0) {
    bary = Eigen::Vector3d(1, 0, 0);
    return a;
  }
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if(d3 >= 0 && d4 <= d3) {
    bary = Eigen::Vector3d(0, 1, 0);
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    bary = Eigen::Vector3d(1 - v, v, 0);
    return Eigen::Vector3d(a + v * ab);
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if(d6 >= 0 && d5 <= d6) {
    bary = Eigen::Vector3d(0, 0, 1);
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    bary = Eigen::Vector3d(1 - w, 0, w);
    return Eigen::Vector3d(a + w * ac);
  }
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    bary = Eigen::Vector3d(0, 1 - w, w);
    return Eigen::Vector3d(b + w * (c - b));
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  bary = Eigen::Vector3d(1 - v - w, v, w);
  return a + v * ab + w * ac;
}

/// A mesh's per-vertex data for the correspondence search: positions, area-weighted normals,
/// incident triangles, boundary flags, and a kd-tree over the positions.
struct Search_side {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> V;
  Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> F;
  std::vector<Eigen::Vector3d> normal;
  std::vector<std::vector<std::uint32_t>> triangles; // incident triangles of each vertex
  std::vector<char> boundary;                  // the vertex is on a boundary edge
  std::vector<std::array<char, 3>> border_edge; // edge k of triangle f (opposite its corner k) is a boundary edge
  Kd_tree<3> tree;

  void set(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& positions, const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>& faces) {
    V = positions;
    F = faces;
    const std::size_t n = static_cast<std::size_t>(V.rows());
    normal.assign(n, Eigen::Vector3d::Zero());
    if(triangles.size() != n) {
      triangles.assign(n, {});
      for(Eigen::Index f = 0; f < F.rows(); ++f)
        for(int k = 0; k < 3; ++k) triangles[static_cast<std::size_t>(F(f, k))].push_back(static_cast<std::uint32_t>(f));
      // boundary: an edge with one incident triangle (edge k of triangle f: opposite its corner k)
      std::vector<std::pair<std::pair<int, int>, std::pair<Eigen::Index, int>>> edges;
      for(Eigen::Index f = 0; f < F.rows(); ++f)
        for(int k = 0; k < 3; ++k) {
          const int a = F(f, (k + 1) % 3), b = F(f, (k + 2) % 3);
          edges.push_back({{std::min(a, b), std::max(a, b)}, {f, k}});
        }
      std::sort(edges.begin(), edges.end());
      boundary.assign(n, 0);
      border_edge.assign(static_cast<std::size_t>(F.rows()), {{0, 0, 0}});
      for(std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while(j < edges.size() && edges[j].first == edges[i].first) ++j;
        if(j - i == 1) {
          boundary[static_cast<std::size_t>(edges[i].first.first)] = boundary[static_cast<std::size_t>(edges[i].first.second)] = 1;
          border_edge[static_cast<std::size_t>(edges[i].second.first)][static_cast<std::size_t>(edges[i].second.second)] = 1;
        }
        i = j;
      }
    }
    for(Eigen::Index f = 0; f < F.rows(); ++f) {
      const Eigen::Vector3d a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(), c = V.row(F(f, 2)).transpose();
      const Eigen::Vector3d w = (b - a).cross(c - a);
      for(int k = 0; k < 3; ++k) normal[static_cast<std::size_t>(F(f, k))] += w;
    }
    for(auto& v : normal) {
      const double l = v.norm();
      if(l > 0) v /= l;
    }
    std::vector<Kd_tree<3>::Point> pts(n);
    for(std::size_t i = 0; i < n; ++i) pts[i] = {V(static_cast<Eigen::Index>(i), 0), V(static_cast<Eigen::Index>(i), 1), V(static_cast<Eigen::Index>(i), 2)};
    tree = Kd_tree<3>(std::move(pts));
  }
  Eigen::Vector3d point(std::size_t i) const { return V.row(static_cast<Eigen::Index>(i)).transpose(); }
  // The point of triangle t with barycentric coordinates w lies on the boundary: on a boundary
  // edge (the weight of the opposite corner is 0) or at a boundary vertex (weight 1).
  bool on_boundary(std::uint32_t t, const Eigen::Vector3d& w) const {
    for(int k = 0; k < 3; ++k) {
      if(w(k) == 0 && border_edge[t][static_cast<std::size_t>(k)]) return true;
      if(w(k) == 1 && boundary[static_cast<std::size_t>(F(t, k))]) return true;
    }
    return false;
  }
};

/// A correspondence pair: a point of the template (a vertex, or a barycentric point of a
/// triangle) and its partner on the target.
struct Nicps_pair {
  int face = -1; // the template triangle of an inverse pair; -1: a vertex (v[0], weight 1)
  int v[3] = {0, 0, 0};
  double w[3] = {1, 0, 0};
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
};

/// The two-step search from vertex a of `from` (position p, normal n) to the surface of `to`:
/// among the k nearest vertices of `to`, b0 = the nearest whose normal is within 90° of n (none:
/// no pair); then for every vertex b of `to` within 2 |p − b0| (b0 included) with a normal within
/// 90°, the closest point on b's incident triangles. At most `cap` vertices b (the nearest).
/// With `skip_boundary`: no pair at all when the closest of these points lies on the boundary (a
/// boundary edge or vertex: p is beyond a cut or over a hole, and would be pulled onto it), and
/// no pair whose point lies on the boundary. Calls emit(triangle, point, barycentric) for each pair.
template <typename Emit>
void two_step_search(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const Search_side& to, std::size_t k, bool skip_boundary, std::size_t cap,
                     Emit&& emit) {
  const Kd_tree<3>::Point q = {p.x(), p.y(), p.z()};
  std::size_t b0 = to.normal.size();
  double d2 = 0;
  // the first compatible vertex of the k nearest: asked for 2, 8, 32, ... nearest until found or k
  // reached (the same vertex as scanning all k, with far fewer neighbours fetched: most find one
  // among the first two)
  for(std::size_t asked = 0, ask = std::min<std::size_t>(k, 2); b0 == to.normal.size() && asked < k; asked = ask, ask = std::min(k, 4 * ask)) {
    const auto nearest = to.tree.k_nearest(q, ask);
    for(std::size_t i = asked; i < nearest.size(); ++i)
      if(to.normal[nearest[i].first].dot(n) > 0) {
        b0 = nearest[i].first;
        d2 = nearest[i].second;
        break;
      }
    if(nearest.size() < ask) break; // fewer vertices than asked for
  }
  if(b0 == to.normal.size()) return;
  std::vector<std::pair<double, std::size_t>> near;
  to.tree.for_each_within(q, 2.0 * std::sqrt(d2), [&](std::size_t b, double e2) {
    if(to.normal[b].dot(n) > 0) near.emplace_back(e2, b);
  });
  if(near.empty()) near.emplace_back(d2, b0);
  if(near.size() > cap) {
    std::nth_element(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(cap), near.end());
    near.resize(cap);
  }
  struct Candidate {
    std::uint32_t t;
    Eigen::Vector3d point, w;
    double d2;
  };
  std::vector<Candidate> found; // per vertex of `near`, the closest point of its incident triangles
  found.reserve(near.size());
  for(const auto& e : near) {
    Candidate best{0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity()};
    for(std::uint32_t t : to.triangles[e.second]) {
      Eigen::Vector3d w;
      const Eigen::Vector3d c = closest_point_on_triangle(p, to.point(static_cast<std::size_t>(to.F(t, 0))), to.point(static_cast<std::size_t>(to.F(t, 1))),
                                                          to.point(static_cast<std::size_t>(to.F(t, 2))), w);
      const double dd = (c - p).squaredNorm();
      if(dd < best.d2) best.t = t, best.point = c, best.w = w, best.d2 = dd;
    }
    if(std::isfinite(best.d2)) found.push_back(best);
  }
  if(found.empty()) return;
  if(skip_boundary) {
    const auto closest = std::min_element(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) { return a.d2 < b.d2; });
    if(to.on_boundary(closest->t, closest->w)) return;
  }
  for(const auto& c : found)
    if(!(skip_boundary && to.on_boundary(c.t, c.w))) emit(c.t, c.point, c.w);
}

} // namespace internal

/// \ingroup PkgShapeCorrRegistration
/// NICPS (thesis chapter 6): deforms `tmpl` towards `target`, keeping the template's
/// connectivity, and writes the new vertex positions into `deformed` (a `WritablePropertyMap`
/// from the template's `vertex_descriptor` to its point type). The template should be roughly
/// aligned to the target first (`align_rigidly()`).
///
/// Iteration f (0-based):
/// 1. **Correspondences, both ways** (the two-step multiple two-way search): from every template
///    vertex to the target (forward) and from every target vertex to the template (inverse), with
///    k = f + 1 nearest candidates, b0 the nearest with a normal within 90°, then every vertex
///    within 2 |a − b0| with a compatible normal gives the closest point on its incident triangles
///    (at most 16 per point). Inverse pairs are barycentric points of the template's triangles,
///    whose positions are the unknowns. With `reject_boundary_pairs` (default true), target
///    boundary vertices neither give nor seek pairs and forward pairs whose target point lies on
///    a boundary edge are dropped, so an open or cut target (a hole, a cut bone) does not pull the
///    template onto its cut: the regularizer carries the template across holes and past cuts.
///    A target of several components is one surface to the search: every target vertex seeks
///    the template (the inverse pairs), so a distant extra part or outliers pull it; give
///    `maximum_pair_distance` (e.g. a few times the expected residual after the rigid alignment)
///    to ignore them.
/// 2. **Solve** min_x D(x) + α_f G(x) (+ landmark terms), α_f = α₀ / γ^f: one sparse symmetric
///    positive definite system shared by x, y and z. Its pattern is fixed by the template (pairs
///    couple the vertices of one triangle; G the 1- or 2-ring), analysed once and factored
///    numerically every iteration. A damping of 1e-9 of the mean diagonal ties vertices without
///    pairs to their current position.
/// 3. **Stop** when the RMS distance of the template's vertices to the target is below
///    `distance_threshold` (converged), when no vertex moves by more than 1e-7 of the target's
///    bounding-box diagonal (no motion), without any pair, or after `number_of_iterations`; the
///    iteration callback may also stop it (returning false).
///
/// | named parameter | pack | meaning | type | default |
/// |---|---|---|---|---|
/// | `nicps_regularizer` | np1 | G | `Nicps_regularizer` | `COMBINATORIAL_LAPLACIAN` |
/// | `alpha_initial`, `alpha_decay` | np1 | α₀, γ | `double` | 100, 1.1 |
/// | `number_of_iterations` | np1 | iterations, at most | `std::size_t` | 50 |
/// | `distance_threshold` | np1 | ε (mesh units) | `double` | 1e-4 × the target's bounding-box diagonal |
/// | `reject_boundary_pairs` | np1 | no pairs onto the target's boundary (see 1.) | `bool` | `true` |
/// | `maximum_pair_distance` | np1 | pairs longer than this are dropped (mesh units) | `double` | ∞ (the thesis: every pair counts) |
/// | `landmark_correspondences` | np1 | (template vertex index, target point) pairs | `std::vector<std::pair<std::size_t, Eigen::Vector3d>>` | none |
/// | `landmark_weight` | np1 | weight of each landmark pair (a pair of D counts 1) | `double` | 10 |
/// | `iteration_callback` | np1 | called after each iteration; false stops | `std::function<bool(const Nicps_iteration_record&)>` | none |
/// | `number_of_threads` | np1 | threads of the search (0: all) | `unsigned` | 0 |
/// | `vertex_point_map`, `vertex_index_map` | np1, np2 | positions, indices | property maps | the mesh's |
///
/// \throws Invalid_input for a mesh without triangles or with a non-finite coordinate;
///         Invalid_argument for parameters out of range or landmarks out of range;
///         Solver_failure when the system cannot be factored
template <typename TemplateMesh, typename TargetMesh, typename VertexPointMap, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Nicps_report nicps(const TemplateMesh& tmpl, const TargetMesh& target, VertexPointMap deformed,
                   const NamedParameters1& np1 = CGAL::parameters::default_values(),
                   const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef Eigen::SparseMatrix<double> Sparse;
  const auto t0 = std::chrono::steady_clock::now();
  const internal::Indexed_mesh<TemplateMesh> indexed(tmpl, np1);
  const internal::Triangle_arrays& R0 = indexed.arrays();
  internal::require_finite_triangles(R0, "nicps", "the template");
  const internal::Triangle_arrays T = internal::finite_triangle_arrays(target, np2, "nicps", "the target");
  const std::size_t n = R0.number_of_vertices();

  const Nicps_regularizer reg = choose_parameter(get_parameter(np1, internal_np::nicps_regularizer), Nicps_regularizer::COMBINATORIAL_LAPLACIAN);
  const double alpha0 = choose_parameter(get_parameter(np1, internal_np::alpha_initial), 100.0);
  const double gamma = choose_parameter(get_parameter(np1, internal_np::alpha_decay), 1.1);
  const std::size_t iterations = choose_parameter(get_parameter(np1, CGAL::internal_np::number_of_iterations), std::size_t(50));
  const double diagonal = (T.V.colwise().maxCoeff() - T.V.colwise().minCoeff()).norm();
  const double epsilon = choose_parameter(get_parameter(np1, internal_np::distance_threshold), 1e-4 * diagonal);
  const bool skip_boundary = choose_parameter(get_parameter(np1, internal_np::reject_boundary_pairs), true);
  const double max_pair = choose_parameter(get_parameter(np1, internal_np::maximum_pair_distance), std::numeric_limits<double>::infinity());
  const auto landmarks = choose_parameter(get_parameter(np1, internal_np::landmark_correspondences), std::vector<std::pair<std::size_t, Eigen::Vector3d>>());
  const double landmark_weight = choose_parameter(get_parameter(np1, internal_np::landmark_weight), 10.0);
  const auto callback = choose_parameter(get_parameter(np1, internal_np::iteration_callback), std::function<bool(const Nicps_iteration_record&)>());
  const unsigned threads = choose_parameter(get_parameter(np1, internal_np::number_of_threads), 0u);
  if(!(alpha0 >= 0) || !std::isfinite(alpha0)) throw Invalid_argument("nicps: alpha_initial must be finite and non-negative");
  if(!(gamma >= 1) || !std::isfinite(gamma)) throw Invalid_argument("nicps: alpha_decay must be at least 1");
  if(iterations > 10000) throw Invalid_argument("nicps: number_of_iterations above 10000");
  if(!(epsilon >= 0)) throw Invalid_argument("nicps: distance_threshold must be non-negative");
  if(!(max_pair > 0)) throw Invalid_argument("nicps: maximum_pair_distance must be positive");
  if(!(landmark_weight >= 0) || !std::isfinite(landmark_weight)) throw Invalid_argument("nicps: landmark_weight must be finite and non-negative");
  for(const auto& l : landmarks) {
    if(l.first >= n) throw Invalid_argument("nicps: landmark vertex " + std::to_string(l.first) + " out of range (" + std::to_string(n) + " vertices)");
    if(!l.second.allFinite()) throw Invalid_argument("nicps: landmark of vertex " + std::to_string(l.first) + " has a non-finite target point");
  }

  // the regularizer's quadratic form Q: G(x) = (x − x⁰)ᵀ Q (x − x⁰), per coordinate
  const Sparse Lc = internal::combinatorial_laplacian(R0);
  Sparse Q;
  if(reg == Nicps_regularizer::EDGE) {
    Q = Lc; // Σ_edges |d_ij − d⁰_ij|² = (x − x⁰)ᵀ L (x − x⁰)
  } else if(reg == Nicps_regularizer::COMBINATORIAL_LAPLACIAN) {
    Q = Sparse(Lc.transpose()) * Lc;
  } else {
    const internal::Intrinsic_triangulation tri = internal::Intrinsic_triangulation::from_arrays(R0);
    const Sparse L = internal::cotangent_laplacian(tri);
    const Eigen::VectorXd area = internal::lumped_mass(tri);
    const double mean_area = area.sum() / static_cast<double>(n);
    Eigen::VectorXd scale(static_cast<Eigen::Index>(n));
    for(Eigen::Index i = 0; i < scale.size(); ++i) scale(i) = area(i) > 0 ? mean_area / area(i) : 0.0;
    const Sparse D = Sparse(scale.asDiagonal()) * L;
    Q = Sparse(D.transpose()) * D;
  }
  // the fixed pattern: Q, the vertices of every triangle, the diagonal
  std::vector<Eigen::Triplet<double>> pattern;
  for(Eigen::Index f = 0; f < R0.F.rows(); ++f)
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b) pattern.emplace_back(R0.F(f, a), R0.F(f, b), 0.0);
  for(Eigen::Index i = 0; i < static_cast<Eigen::Index>(n); ++i) pattern.emplace_back(i, i, 0.0);
  for(int k = 0; k < Q.outerSize(); ++k)
    for(Sparse::InnerIterator it(Q, k); it; ++it) pattern.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), 0.0);
  Sparse A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  A.setFromTriplets(pattern.begin(), pattern.end());
  A.makeCompressed();
  Eigen::SimplicialLDLT<Sparse> solver;
  solver.analyzePattern(A);
  // where each entry of the pattern is stored: every iteration writes the values in place
  auto slot = [&](int row, int col) -> std::size_t {
    const int* inner = A.innerIndexPtr();
    const int* begin = inner + A.outerIndexPtr()[col];
    const int* end = inner + A.outerIndexPtr()[col + 1];
    return static_cast<std::size_t>(std::lower_bound(begin, end, row) - inner);
  };
  std::vector<std::size_t> diagonal_slot(n), face_slot(static_cast<std::size_t>(9 * R0.F.rows())), q_slot;
  for(std::size_t i = 0; i < n; ++i) diagonal_slot[i] = slot(static_cast<int>(i), static_cast<int>(i));
  for(Eigen::Index f = 0; f < R0.F.rows(); ++f)
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b) face_slot[static_cast<std::size_t>(9 * f + 3 * a + b)] = slot(R0.F(f, a), R0.F(f, b));
  for(int k = 0; k < Q.outerSize(); ++k)
    for(Sparse::InnerIterator it(Q, k); it; ++it) q_slot.push_back(slot(static_cast<int>(it.row()), static_cast<int>(it.col())));

  Eigen::MatrixXd x0(static_cast<Eigen::Index>(n), 3), x;
  x0 = R0.V;
  x = x0;
  const Eigen::MatrixXd Qx0 = Q * x0;
  internal::Search_side tside, rside;
  tside.set(T.V, T.F);
  const internal::Closest_point_tree ttree(T);
  auto rms_to_target = [&](const Eigen::MatrixXd& pos) {
    std::vector<double> d(n);
    parallel_for(n, threads, [&](std::size_t i, unsigned) { d[i] = ttree.distance(pos.row(static_cast<Eigen::Index>(i)).transpose()); });
    double s = 0;
    for(double v : d) s += v * v;
    return std::sqrt(s / static_cast<double>(n));
  };

  Nicps_report report;
  report.initial_rms = rms_to_target(x);
  report.final_rms = report.initial_rms;
  report.stop = Stop_reason::ITERATION_LIMIT;
  const std::size_t cap = 16;
  for(std::size_t f = 0; f < iterations; ++f) {
    if(report.final_rms < epsilon) {
      report.stop = Stop_reason::CONVERGED;
      break;
    }
    const auto iteration_start = std::chrono::steady_clock::now();
    auto seconds_since = [](std::chrono::steady_clock::time_point t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
    Nicps_iteration_record rec;
    rec.iteration = f;
    rec.alpha = alpha0 / std::pow(gamma, static_cast<double>(f));
    const std::size_t k = f + 1;
    rside.set(Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>(x), R0.F);

    // forward: template vertex i -> target surface points
    std::vector<std::vector<internal::Nicps_pair>> fwd(n);
    parallel_for(n, threads, [&](std::size_t i, unsigned) {
      internal::two_step_search(rside.point(i), rside.normal[i], tside, k, skip_boundary, cap,
                                [&](std::uint32_t, const Eigen::Vector3d& t, const Eigen::Vector3d&) {
                                  if((t - rside.point(i)).norm() > max_pair) return;
                                  internal::Nicps_pair pr;
                                  pr.v[0] = static_cast<int>(i);
                                  pr.target = t;
                                  fwd[i].push_back(pr);
                                });
    });
    // inverse: target vertex a -> template surface points (barycentric in the unknowns)
    const std::size_t m = T.number_of_vertices();
    std::vector<std::vector<internal::Nicps_pair>> inv(m);
    parallel_for(m, threads, [&](std::size_t a, unsigned) {
      if(skip_boundary && tside.boundary[a]) return;
      internal::two_step_search(tside.point(a), tside.normal[a], rside, k, false, cap,
                                [&](std::uint32_t t, const Eigen::Vector3d& on_template, const Eigen::Vector3d& w) {
                                  if((on_template - tside.point(a)).norm() > max_pair) return;
                                  internal::Nicps_pair pr;
                                  pr.face = static_cast<int>(t);
                                  for(int c = 0; c < 3; ++c) {
                                    pr.v[c] = R0.F(static_cast<Eigen::Index>(t), c);
                                    pr.w[c] = w(c);
                                  }
                                  pr.target = tside.point(a);
                                  inv[a].push_back(pr);
                                });
    });
    rec.search_seconds = seconds_since(iteration_start);
    std::vector<internal::Nicps_pair> pairs;
    for(auto& v : fwd) rec.forward_pairs += v.size(), pairs.insert(pairs.end(), v.begin(), v.end());
    for(auto& v : inv) rec.inverse_pairs += v.size(), pairs.insert(pairs.end(), v.begin(), v.end());
    rec.pairs = pairs.size() + landmarks.size();
    if(rec.pairs == 0) {
      report.stop = Stop_reason::TOO_FEW_PAIRS;
      report.iterations.push_back(rec);
      break;
    }

    // assemble A = Σ w wᵀ + α Q + damping, B = Σ w t + α Q x⁰ + damping x
    // (the values written in place into the fixed pattern)
    double* value = A.valuePtr();
    std::fill(value, value + A.nonZeros(), 0.0);
    for(std::size_t k = 0; k < q_slot.size(); ++k) value[q_slot[k]] += rec.alpha * Q.valuePtr()[k];
    Eigen::MatrixXd B = rec.alpha * Qx0;
    for(const auto& pr : pairs) {
      if(pr.face < 0) {
        value[diagonal_slot[static_cast<std::size_t>(pr.v[0])]] += 1.0;
        B.row(pr.v[0]) += pr.target.transpose();
        continue;
      }
      for(int a = 0; a < 3; ++a) {
        B.row(pr.v[a]) += pr.w[a] * pr.target.transpose();
        for(int b = 0; b < 3; ++b) value[face_slot[static_cast<std::size_t>(9 * pr.face + 3 * a + b)]] += pr.w[a] * pr.w[b];
      }
    }
    for(const auto& l : landmarks) {
      value[diagonal_slot[l.first]] += landmark_weight;
      B.row(static_cast<Eigen::Index>(l.first)) += landmark_weight * l.second.transpose();
    }
    double mean_diagonal = 0;
    for(std::size_t i = 0; i < n; ++i) mean_diagonal += std::abs(value[diagonal_slot[i]]) / static_cast<double>(n);
    const double damping = 1e-9 * std::max(1e-300, mean_diagonal);
    for(std::size_t i = 0; i < n; ++i) value[diagonal_slot[i]] += damping;
    B += damping * x;
    const auto factorization_start = std::chrono::steady_clock::now();
    solver.factorize(A);
    rec.factorization_seconds = seconds_since(factorization_start);
    if(solver.info() != Eigen::Success) throw Solver_failure("nicps: the sparse system of iteration " + std::to_string(f) + " could not be factored");
    const Eigen::MatrixXd X = solver.solve(B);
    if(!X.allFinite()) throw Solver_failure("nicps: the solution of iteration " + std::to_string(f) + " is not finite");

    // energy at the solution, step, distance
    double D = 0;
    for(const auto& pr : pairs) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for(int a = 0; a < 3; ++a) p += pr.w[a] * X.row(pr.v[a]).transpose();
      D += (p - pr.target).squaredNorm();
    }
    for(const auto& l : landmarks) D += landmark_weight * (X.row(static_cast<Eigen::Index>(l.first)).transpose() - l.second).squaredNorm();
    const Eigen::MatrixXd dx = X - x0;
    rec.energy = D + rec.alpha * (dx.transpose() * (Q * dx)).trace();
    rec.step = (X - x).rowwise().norm().maxCoeff();
    x = X;
    rec.rms_distance = rms_to_target(x);
    report.final_rms = rec.rms_distance;
    rec.seconds = seconds_since(iteration_start);
    report.iterations.push_back(rec);
    if(callback && !callback(rec)) {
      report.stop = Stop_reason::CANCELLED;
      break;
    }
    if(rec.rms_distance < epsilon) {
      report.stop = Stop_reason::CONVERGED;
      break;
    }
    if(rec.step <= 1e-7 * diagonal) {
      report.stop = Stop_reason::NO_MOTION;
      break;
    }
  }

  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  for(std::size_t i = 0; i < n; ++i)
    put(deformed, indexed.vertex(i), Point(x(static_cast<Eigen::Index>(i), 0), x(static_cast<Eigen::Index>(i), 1), x(static_cast<Eigen::Index>(i), 2)));
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

} // namespace shapecorr

#endif
