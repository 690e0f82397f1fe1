// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file pauly_registration.h
/// The baseline of Pauly et al. 2005 (thesis chapter 6, "Pauly2005"): single closest-point pairs
/// weighted by bidirectional consistency, an area-weighted edge energy.
#ifndef SHAPECORR_REGISTRATION_PAULY_REGISTRATION_H
#define SHAPECORR_REGISTRATION_PAULY_REGISTRATION_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/cotangent_operators.h>
#include <shapecorr/registration/internal/registration_problem.h>
#include <shapecorr/parameters.h>
#include <shapecorr/registration/nicps.h>
#include <shapecorr/registration/registration_report.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace shapecorr {
namespace internal {

/// Σ_edges a_ij |(x_j − x_i) − (x_j⁰ − x_i⁰)|² = (x − x⁰)ᵀ Q (x − x⁰), per coordinate, with
/// a_ij = (A_i + A_j) / |x_j⁰ − x_i⁰|² (A the vertex areas, a third of the incident triangles'),
/// scaled so that the mean a_ij is 1. Degenerate edges (zero length) get weight 0.
inline Eigen::SparseMatrix<double> area_weighted_edge_form(const Triangle_arrays& a) {
  const std::size_t n = a.number_of_vertices();
  std::vector<double> area(n, 0.0);
  for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
    const Eigen::Vector3d p = a.point(static_cast<std::size_t>(a.F(f, 0))), q = a.point(static_cast<std::size_t>(a.F(f, 1))),
                          r = a.point(static_cast<std::size_t>(a.F(f, 2)));
    const double A = 0.5 * (q - p).cross(r - p).norm();
    for(int k = 0; k < 3; ++k) area[static_cast<std::size_t>(a.F(f, k))] += A / 3;
  }
  const std::vector<std::pair<int, int>> edges = unique_edges(a);
  std::vector<double> weight(edges.size(), 0.0);
  double sum = 0;
  std::size_t counted = 0;
  for(std::size_t e = 0; e < edges.size(); ++e) {
    const std::size_t i = static_cast<std::size_t>(edges[e].first), j = static_cast<std::size_t>(edges[e].second);
    const double len2 = (a.point(j) - a.point(i)).squaredNorm();
    if(len2 > 0 && std::isfinite((area[i] + area[j]) / len2)) {
      weight[e] = (area[i] + area[j]) / len2;
      sum += weight[e];
      ++counted;
    }
  }
  const double mean = counted ? sum / static_cast<double>(counted) : 1.0;
  std::vector<Eigen::Triplet<double>> t;
  for(std::size_t e = 0; e < edges.size(); ++e) {
    const double w = mean > 0 ? weight[e] / mean : 0.0;
    const int i = edges[e].first, j = edges[e].second;
    t.emplace_back(i, i, w);
    t.emplace_back(j, j, w);
    t.emplace_back(i, j, -w);
    t.emplace_back(j, i, -w);
  }
  for(std::size_t i = 0; i < n; ++i) t.emplace_back(static_cast<int>(i), static_cast<int>(i), 0.0); // the whole diagonal in the pattern
  Eigen::SparseMatrix<double> Q(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  Q.setFromTriplets(t.begin(), t.end());
  return Q;
}

} // namespace internal

/// \ingroup PkgShapeCorrRegistration
/// The registration of Pauly et al. 2005 ("Example-based 3D scan completion", its warping
/// stage), as the thesis compares with: deforms `tmpl` towards `target` and writes the new vertex
/// positions into `deformed` (a `WritablePropertyMap` from the template's `vertex_descriptor` to
/// its point type). The template should be roughly aligned first. It differs from `nicps()` in
/// exactly what the thesis names: one pair per template vertex, weighted, and an area-weighted
/// edge energy.
///
/// Iteration f (0-based):
/// 1. **Pairs**: every template vertex x_i gets its closest point c_i on the target surface. Its
///    confidence comes from the closest point back: b_i, the closest point of c_i on the current
///    template surface, gives w_i = exp(−|b_i − x_i|² / (2 h²)), h the template's mean edge length
///    (a consistent pair returns to its vertex: w ≈ 1). With `reject_boundary_pairs` (default
///    true) a pair whose c_i lies on the target's boundary gets w_i = 0.
/// 2. **Solve** min_x Σ_i w_i |x_i − c_i|² + α_f Σ_edges a_ij |(x_j − x_i) − (x_j⁰ − x_i⁰)|²,
///    α_f = α₀ / γ^f, a_ij = (A_i + A_j) / |x_j⁰ − x_i⁰|² (vertex areas A), scaled to mean 1: one
///    sparse SPD system for x, y and z, its pattern analysed once.
/// 3. **Stop** as `nicps()`: RMS distance below `distance_threshold`, no vertex moving by more
///    than 1e-7 of the target's bounding-box diagonal, all weights 0, `number_of_iterations`, or
///    the callback.
///
/// An iteration's record: pairs = the pairs with a weight above 1e-3; energy = the minimized
/// objective at the new positions; rms_distance and step as in `Iteration_record`.
///
/// | named parameter | pack | meaning | type | default |
/// |---|---|---|---|---|
/// | `alpha_initial`, `alpha_decay` | np1 | α₀, γ | `double` | 100, 1.1 (as `nicps()`) |
/// | `number_of_iterations` | np1 | iterations, at most | `std::size_t` | 50 |
/// | `distance_threshold` | np1 | ε (mesh units) | `double` | 1e-4 × the target's bounding-box diagonal |
/// | `reject_boundary_pairs` | np1 | no pairs onto the target's boundary | `bool` | `true` |
/// | `iteration_callback` | np1 | called after each iteration; false stops | `std::function<bool(const Iteration_record&)>` | none |
/// | `number_of_threads` | np1 | threads of the closest-point queries (0: all) | `unsigned` | 0 |
/// | `vertex_point_map`, `vertex_index_map` | np1, np2 | positions, indices | property maps | the mesh's |
///
/// \throws Invalid_input for a mesh without triangles or with a non-finite coordinate;
///         Invalid_argument for parameters out of range; Solver_failure when the system cannot be factored
template <typename TemplateMesh, typename TargetMesh, typename VertexPointMap, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Registration_report pauly_registration(const TemplateMesh& tmpl, const TargetMesh& target, VertexPointMap deformed,
                                       const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                       const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef Eigen::SparseMatrix<double> Sparse;
  const internal::Registration_problem<TemplateMesh> problem(tmpl, target, np1, np2, "pauly_registration");
  const double alpha0 = choose_parameter(get_parameter(np1, internal_np::alpha_initial), 100.0);
  const double gamma = choose_parameter(get_parameter(np1, internal_np::alpha_decay), 1.1);
  const std::size_t iterations = choose_parameter(get_parameter(np1, CGAL::internal_np::number_of_iterations), std::size_t(50));
  const double epsilon = choose_parameter(get_parameter(np1, internal_np::distance_threshold), 1e-4 * problem.target_diagonal());
  const bool skip_boundary = choose_parameter(get_parameter(np1, internal_np::reject_boundary_pairs), true);
  const auto callback = choose_parameter(get_parameter(np1, internal_np::iteration_callback), std::function<bool(const Iteration_record&)>());
  const unsigned threads = choose_parameter(get_parameter(np1, internal_np::number_of_threads), 0u);
  if(!(alpha0 >= 0) || !std::isfinite(alpha0)) throw Invalid_argument("pauly_registration: alpha_initial must be finite and non-negative");
  if(!(gamma >= 1) || !std::isfinite(gamma)) throw Invalid_argument("pauly_registration: alpha_decay must be at least 1");
  if(iterations > 10000) throw Invalid_argument("pauly_registration: number_of_iterations above 10000");
  if(!(epsilon >= 0)) throw Invalid_argument("pauly_registration: distance_threshold must be non-negative");

  const internal::Triangle_arrays& R0 = problem.template_arrays();
  const internal::Triangle_arrays& T = problem.target_arrays();
  const std::size_t n = problem.template_size();
  const Sparse Q = internal::area_weighted_edge_form(R0);
  double h = 0;
  for(Eigen::Index f = 0; f < R0.F.rows(); ++f)
    for(int k = 0; k < 3; ++k) h += (R0.V.row(R0.F(f, k)) - R0.V.row(R0.F(f, (k + 1) % 3))).norm();
  h /= static_cast<double>(3 * std::max<Eigen::Index>(R0.F.rows(), 1));
  if(!(h > 0)) throw Invalid_input(Mesh_defect::degenerate_face, "pauly_registration: the template's edges all have length 0");
  internal::Search_side target_side; // for the boundary of the target
  target_side.set(T.V, T.F);
  const internal::Closest_point_tree& ttree = problem.target_tree();

  Sparse I(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  I.setIdentity();
  Eigen::SimplicialLDLT<Sparse> solver;
  solver.analyzePattern(Sparse(Q + I));
  const Eigen::MatrixXd x0 = R0.V;
  const Eigen::MatrixXd Qx0 = Q * x0;
  Eigen::MatrixXd x = x0;

  Registration_report report;
  // the closest target points of the current vertices: the pairs of the next iteration and the
  // RMS distance of the last one, from one query per vertex
  std::vector<internal::Closest_point> closest(n);
  auto find_closest = [&]() {
    parallel_for(n, threads, [&](std::size_t i, unsigned) { closest[i] = ttree.closest(x.row(static_cast<Eigen::Index>(i)).transpose()); });
    double sum = 0;
    for(const auto& c : closest) sum += c.distance * c.distance;
    return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(n, 1)));
  };
  report.initial_rms = find_closest();
  report.final_rms = report.initial_rms;
  for(std::size_t f = 0; f < iterations; ++f) {
    if(report.final_rms < epsilon) {
      report.stop = Stop_reason::CONVERGED;
      break;
    }
    const double alpha = alpha0 / std::pow(gamma, static_cast<double>(f));
    internal::Triangle_arrays current;
    current.V = x;
    current.F = R0.F;
    const internal::Closest_point_tree rtree(current);
    Eigen::MatrixXd c(x.rows(), 3);
    Eigen::VectorXd w(x.rows());
    parallel_for(n, threads, [&](std::size_t i, unsigned) {
      const Eigen::Index r = static_cast<Eigen::Index>(i);
      const Eigen::Vector3d p = x.row(r).transpose();
      const internal::Closest_point& cp = closest[i];
      c.row(r) = cp.point.transpose();
      w(r) = std::exp(-(rtree.closest(cp.point).point - p).squaredNorm() / (2 * h * h));
      if(skip_boundary) {
        const auto t = static_cast<std::uint32_t>(cp.triangle);
        Eigen::Vector3d bary;
        internal::closest_point_on_triangle(p, T.point(static_cast<std::size_t>(T.F(t, 0))), T.point(static_cast<std::size_t>(T.F(t, 1))),
                                            T.point(static_cast<std::size_t>(T.F(t, 2))), bary);
        if(target_side.on_boundary(t, bary)) w(r) = 0;
      }
    });
    Iteration_record rec;
    rec.iteration = f;
    rec.pairs = static_cast<std::size_t>((w.array() > 1e-3).count());
    if(w.maxCoeff() <= 0) {
      report.stop = Stop_reason::TOO_FEW_PAIRS;
      report.iterations.push_back(rec);
      break;
    }
    const double damping = 1e-9 * std::max(1e-300, (w.sum() + alpha * Q.diagonal().sum()) / static_cast<double>(n));
    const Sparse A = alpha * Q + Sparse((w.array() + damping).matrix().asDiagonal());
    const Eigen::MatrixXd B = alpha * Qx0 + w.asDiagonal() * c + damping * x;
    solver.factorize(A);
    if(solver.info() != Eigen::Success) throw Solver_failure("pauly_registration: the sparse system of iteration " + std::to_string(f) + " could not be factored");
    const Eigen::MatrixXd X = solver.solve(B);
    if(!X.allFinite()) throw Solver_failure("pauly_registration: the solution of iteration " + std::to_string(f) + " is not finite");
    const Eigen::MatrixXd dx = X - x0;
    rec.energy = w.dot((X - c).rowwise().squaredNorm()) + alpha * (dx.transpose() * (Q * dx)).trace();
    rec.step = (X - x).rowwise().norm().maxCoeff();
    x = X;
    rec.rms_distance = find_closest();
    if(!internal::record_iteration(report, rec, callback)) break;
    if(rec.rms_distance < epsilon) {
      report.stop = Stop_reason::CONVERGED;
      break;
    }
    if(rec.step <= 1e-7 * problem.target_diagonal()) {
      report.stop = Stop_reason::NO_MOTION;
      break;
    }
  }
  problem.write(x, deformed);
  report.seconds = problem.seconds();
  return report;
}

} // namespace shapecorr

#endif
