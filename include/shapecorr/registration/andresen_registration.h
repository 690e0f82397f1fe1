// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file andresen_registration.h
/// The baseline of Andresen & Nielsen 2001 (thesis chapter 6, "Andresen2001"): a nearest-point
/// displacement field on the template, smoothed by geometry-constrained diffusion, then applied.
#ifndef SHAPECORR_REGISTRATION_ANDRESEN_REGISTRATION_H
#define SHAPECORR_REGISTRATION_ANDRESEN_REGISTRATION_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/cotangent_operators.h>
#include <shapecorr/registration/internal/registration_problem.h>
#include <shapecorr/parameters.h>
#include <shapecorr/registration/registration_report.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrRegistration
/// The registration of Andresen & Nielsen 2001 ("Non-rigid registration by geometry-constrained
/// diffusion"), as the thesis runs it for comparison: deforms `tmpl` onto `target` and writes the
/// new vertex positions into `deformed` (a `WritablePropertyMap` from the template's
/// `vertex_descriptor` to its point type). The template should be roughly aligned first.
///
/// 1. **Initial displacement field**: u_i = c(x_i) − x_i, c the closest point of the target
///    surface (no feature lines, as in the thesis).
/// 2. **Geometry-constrained diffusion**, one step per iteration: u ← u + τ U u (τ the time
///    step, U the umbrella operator of the template: mean of the neighbours minus the vertex), then
///    the constraint: every displaced vertex is put back on the target surface,
///    u_i ← c(x_i + u_i) − x_i. The field becomes smooth along the surface while its vertices stay
///    on the target; they may slide along it.
/// 3. **Warp**: the result is x + u.
///
/// An iteration's record: energy = Σ_edges |u_i − u_j|² (the roughness the diffusion lowers),
/// step = the largest change of a displacement, rms_distance = RMS distance of the diffused
/// vertices to the target before they are put back (how far the diffusion pulls them off it). It stops after `number_of_iterations`
/// steps, when no displacement changes by more than 1e-7 of the target's bounding-box diagonal
/// (NO_MOTION), or when the callback returns false.
///
/// The method trusts the nearest points: where they are wrong (a template far from the target,
/// thin or folded parts) the diffusion smooths a wrong field, and vertices may fold over each
/// other on the target (the thesis's reading of its vertebra results).
///
/// | named parameter | pack | meaning | type | default |
/// |---|---|---|---|---|
/// | `time_step` | np1 | τ, in (0, 1] | `double` | 0.1 (the thesis) |
/// | `number_of_iterations` | np1 | diffusion steps, at most | `std::size_t` | 500 |
/// | `iteration_callback` | np1 | called after each step; false stops | `std::function<bool(const Iteration_record&)>` | none |
/// | `number_of_threads` | np1 | threads of the closest-point queries (0: all) | `unsigned` | 0 |
/// | `vertex_point_map`, `vertex_index_map` | np1, np2 | positions, indices | property maps | the mesh's |
///
/// \throws Invalid_input for a mesh without triangles or with a non-finite coordinate;
///         Invalid_argument for parameters out of range
template <typename TemplateMesh, typename TargetMesh, typename VertexPointMap, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Registration_report andresen_registration(const TemplateMesh& tmpl, const TargetMesh& target, VertexPointMap deformed,
                                          const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                          const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const internal::Registration_problem<TemplateMesh> problem(tmpl, target, np1, np2, "andresen_registration");
  const double tau = choose_parameter(get_parameter(np1, internal_np::time_step), 0.1);
  const std::size_t iterations = choose_parameter(get_parameter(np1, CGAL::internal_np::number_of_iterations), std::size_t(500));
  const auto callback = choose_parameter(get_parameter(np1, internal_np::iteration_callback), std::function<bool(const Iteration_record&)>());
  const unsigned threads = choose_parameter(get_parameter(np1, internal_np::number_of_threads), 0u);
  if(!(tau > 0 && tau <= 1)) throw Invalid_argument("andresen_registration: time_step must be in (0, 1]");
  if(iterations > 100000) throw Invalid_argument("andresen_registration: number_of_iterations above 100000");

  const internal::Triangle_arrays& R = problem.template_arrays();
  const std::size_t n = problem.template_size();
  const Eigen::MatrixXd x = R.V;
  // the combinatorial Laplacian L = D − A gives the umbrella operator U = −D⁻¹ L (mean of the
  // neighbours minus the vertex; 0 for a vertex without neighbours) and the roughness tr(uᵀ L u)
  const Eigen::SparseMatrix<double> L = internal::combinatorial_laplacian(R);
  Eigen::VectorXd inverse_degree = L.diagonal();
  for(Eigen::Index i = 0; i < inverse_degree.size(); ++i) inverse_degree(i) = inverse_degree(i) > 0 ? 1 / inverse_degree(i) : 0.0;
  const Eigen::SparseMatrix<double> U = -(inverse_degree.asDiagonal() * L);
  const internal::Closest_point_tree& tree = problem.target_tree();
  Eigen::MatrixXd u(x.rows(), 3);
  // u_i = c(moved_i) − x_i; returns the RMS distance of `moved` to the target
  auto project = [&](const Eigen::MatrixXd& moved) {
    std::vector<double> d(n);
    parallel_for(n, threads, [&](std::size_t i, unsigned) {
      const Eigen::Index r = static_cast<Eigen::Index>(i);
      const internal::Closest_point c = tree.closest(moved.row(r).transpose());
      u.row(r) = (c.point - x.row(r).transpose()).transpose();
      d[i] = c.distance;
    });
    double s = 0;
    for(double v : d) s += v * v;
    return std::sqrt(s / static_cast<double>(std::max<std::size_t>(n, 1)));
  };
  Registration_report report;
  report.initial_rms = project(x);
  report.final_rms = report.initial_rms;
  for(std::size_t f = 0; f < iterations; ++f) {
    const Eigen::MatrixXd before = u;
    const Eigen::MatrixXd diffused = u + tau * (U * u);
    Iteration_record rec;
    rec.iteration = f;
    rec.pairs = n;
    rec.rms_distance = project(x + diffused);
    rec.energy = (u.transpose() * (L * u)).trace(); // Σ_edges |u_i − u_j|²
    rec.step = (u - before).rowwise().norm().maxCoeff();
    if(!internal::record_iteration(report, rec, callback)) break;
    if(rec.step <= 1e-7 * problem.target_diagonal()) {
      report.stop = Stop_reason::NO_MOTION;
      break;
    }
  }
  report.final_rms = problem.rms_to_target(x + u, threads);
  problem.write(x + u, deformed);
  report.seconds = problem.seconds();
  return report;
}

} // namespace shapecorr

#endif
