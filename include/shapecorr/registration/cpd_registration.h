// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file cpd_registration.h
/// The baseline CPD (Myronenko & Song 2010, non-rigid, thesis chapter 6 "CPD2010"): the template's
/// vertices are the centroids of a Gaussian mixture that moves coherently to fit the target's
/// vertices, with a low-rank kernel and a fast Gauss sum.
#ifndef SHAPECORR_REGISTRATION_CPD_REGISTRATION_H
#define SHAPECORR_REGISTRATION_CPD_REGISTRATION_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/gauss_sum.h>
#include <shapecorr/internal/low_rank_kernel.h>
#include <shapecorr/registration/internal/registration_problem.h>
#include <shapecorr/parameters.h>
#include <shapecorr/registration/registration_report.h>

#include <Eigen/Core>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace shapecorr {
namespace internal {

/// Both point sets moved and scaled by the same similarity: the target's centroid to the origin,
/// its RMS radius to 1 (CPD works in such units; one transform for both keeps the pre-alignment).
struct Point_set_normalization {
  Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
  double scale = 1;
  explicit Point_set_normalization(const Eigen::MatrixXd& X) {
    centre = X.colwise().mean();
    scale = std::sqrt((X.rowwise() - centre).rowwise().squaredNorm().mean());
    if(!(scale > 0) || !std::isfinite(scale)) scale = 1;
  }
  Eigen::MatrixXd apply(const Eigen::MatrixXd& P) const { return (P.rowwise() - centre) / scale; }
  Eigen::MatrixXd undo(const Eigen::MatrixXd& P) const { return (P * scale).rowwise() + centre; }
};

} // namespace internal

/// \ingroup PkgShapeCorrRegistration
/// Non-rigid Coherent Point Drift (Myronenko & Song, "Point set registration: coherent point
/// drift", PAMI 2010) with its low-rank kernel and a fast Gauss sum, on the vertices of the two
/// meshes (the thesis's use): moves the template's vertices Y (M) to fit the target's vertices X
/// (N) and writes them into `deformed` (a `WritablePropertyMap` from the template's
/// `vertex_descriptor` to its point type). The template should be roughly aligned first. Like
/// every CPD, it assumes that the two vertex sets sample the surfaces alike: with very different
/// densities it fits the densities, not the surfaces (the thesis's Figure 6.6).
///
/// Both sets are first moved and scaled by one similarity (the target's centroid to 0, its RMS
/// radius to 1), so β and σ are in those units. The moved template is T = Y + G W, G the Gaussian
/// kernel of Y of width β. One iteration is one EM step:
/// - **E**: P_mn = exp(−|x_n − t_m|²/(2σ²)) / (Σ_k exp(−|x_n − t_k|²/(2σ²)) + c), c = (2πσ²)^{3/2}
///   w/(1 − w) M/N — through the fast Gauss sum: terms below 1e-6 of their weight dropped (a k-d tree), and
///   sources clustered into cells of σ/4 while σ is wide against the spacing;
/// - **M**: (G + λσ² d(P1)⁻¹) W = d(P1)⁻¹ P X − Y with G ≈ Q Λ Qᵀ (its `kernel_rank` leading
///   eigenpairs, from a Nyström approximation on 4 × `kernel_rank` furthest-point landmarks), solved
///   by the Woodbury identity in O(M K²); then σ² from the weighted residual.
///
/// σ² starts at Σ_mn |x_n − y_m|² / (3MN). It stops when the negative log-likelihood plus
/// λ/2 tr(Wᵀ G W) changes by less than `convergence_tolerance` relatively (CONVERGED), when σ²
/// falls below 1e-10 (CONVERGED), after `number_of_iterations`, or by the callback. An
/// iteration's record: energy = that objective; pairs = N (every target vertex counts); rms_distance
/// (to the target surface) and step as in `Iteration_record`. Memory is O((M + N) K); time per
/// iteration O((M + N) × sources within reach).
///
/// | named parameter | pack | meaning | type | default |
/// |---|---|---|---|---|
/// | `kernel_width` | np1 | β (normalized units) | `double` | 2 (CPD's) |
/// | `regularization_weight` | np1 | λ | `double` | 3 (CPD's) |
/// | `outlier_weight` | np1 | w in [0, 1) | `double` | 0.1 (CPD's) |
/// | `kernel_rank` | np1 | K, eigenpairs of G | `std::size_t` | 50 |
/// | `number_of_iterations` | np1 | EM iterations, at most | `std::size_t` | 150 (CPD's) |
/// | `convergence_tolerance` | np1 | relative change of the objective | `double` | 1e-5 (CPD's) |
/// | `iteration_callback` | np1 | called after each iteration; false stops | `std::function<bool(const Iteration_record&)>` | none |
/// | `number_of_threads` | np1 | threads (0: all) | `unsigned` | 0 |
/// | `vertex_point_map`, `vertex_index_map` | np1, np2 | positions, indices | property maps | the mesh's |
///
/// \throws Invalid_input for a mesh without triangles or with a non-finite coordinate;
///         Invalid_argument for parameters out of range
template <typename TemplateMesh, typename TargetMesh, typename VertexPointMap, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Registration_report cpd_registration(const TemplateMesh& tmpl, const TargetMesh& target, VertexPointMap deformed,
                                     const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                     const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const internal::Registration_problem<TemplateMesh> problem(tmpl, target, np1, np2, "cpd_registration");
  const double beta = choose_parameter(get_parameter(np1, internal_np::kernel_width), 2.0);
  const double lambda = choose_parameter(get_parameter(np1, internal_np::regularization_weight), 3.0);
  const double w = choose_parameter(get_parameter(np1, internal_np::outlier_weight), 0.1);
  const std::size_t rank = choose_parameter(get_parameter(np1, internal_np::kernel_rank), std::size_t(50));
  const std::size_t iterations = choose_parameter(get_parameter(np1, CGAL::internal_np::number_of_iterations), std::size_t(150));
  const double tolerance = choose_parameter(get_parameter(np1, internal_np::convergence_tolerance), 1e-5);
  const auto callback = choose_parameter(get_parameter(np1, internal_np::iteration_callback), std::function<bool(const Iteration_record&)>());
  const unsigned threads = choose_parameter(get_parameter(np1, internal_np::number_of_threads), 0u);
  if(!(beta > 0) || !std::isfinite(beta)) throw Invalid_argument("cpd_registration: kernel_width must be positive and finite");
  if(!(lambda > 0) || !std::isfinite(lambda)) throw Invalid_argument("cpd_registration: regularization_weight must be positive and finite");
  if(!(w >= 0 && w < 1)) throw Invalid_argument("cpd_registration: outlier_weight must be in [0, 1)");
  if(rank < 1 || rank > 5000) throw Invalid_argument("cpd_registration: kernel_rank must be in [1, 5000]");
  if(iterations > 10000) throw Invalid_argument("cpd_registration: number_of_iterations above 10000");
  if(!(tolerance >= 0)) throw Invalid_argument("cpd_registration: convergence_tolerance must be non-negative");

  const internal::Point_set_normalization norm(problem.target_arrays().V);
  const Eigen::MatrixXd X = norm.apply(problem.target_arrays().V);
  const Eigen::MatrixXd Y = norm.apply(problem.template_arrays().V);
  const Eigen::Index M = Y.rows(), N = X.rows();
  const std::size_t m = static_cast<std::size_t>(M), nn = static_cast<std::size_t>(N);
  const internal::Low_rank_kernel G = internal::gaussian_kernel_eigenpairs(Y, beta, rank, 4 * rank);
  const Eigen::MatrixXd& Q = G.Q;
  const Eigen::VectorXd& S = G.lambda;

  // σ² = Σ_mn |x_n − y_m|² / (3MN), from the means and second moments
  double sigma2 = (static_cast<double>(M) * X.rowwise().squaredNorm().sum() + static_cast<double>(N) * Y.rowwise().squaredNorm().sum() -
                   2 * X.colwise().sum().dot(Y.colwise().sum())) /
                  (3.0 * static_cast<double>(M) * static_cast<double>(N));
  Eigen::MatrixXd T = Y;
  Eigen::MatrixXd QtW = Eigen::MatrixXd::Zero(Q.cols(), 3); // Qᵀ W
  Registration_report report;
  report.initial_rms = problem.rms_to_target(norm.undo(T), threads);
  report.final_rms = report.initial_rms;
  double previous = std::numeric_limits<double>::quiet_NaN();
  for(std::size_t f = 0; f < iterations; ++f) {
    if(!(sigma2 > 1e-10)) {
      report.stop = Stop_reason::CONVERGED;
      break;
    }
    const double c = std::pow(2 * M_PI * sigma2, 1.5) * w / (1 - w) * static_cast<double>(M) / static_cast<double>(N);
    const double s = std::sqrt(sigma2);
    // E step: den_n = Σ_m k(x_n, t_m) + c; then P1, PX from the target side with weights 1/den
    Eigen::VectorXd den(N);
    {
      const internal::Gauss_sum to_template(T, Eigen::VectorXd::Ones(M), Eigen::MatrixXd(), s);
      parallel_for(nn, threads, [&](std::size_t n, unsigned) { den(static_cast<Eigen::Index>(n)) = to_template(X.row(static_cast<Eigen::Index>(n)).transpose()) + c; });
    }
    // a target vertex beyond every template point's reach with no outlier term (w = 0) takes no part
    Eigen::VectorXd inv_den(N), Pt1(N);
    double log_sum = 0;
    for(Eigen::Index n = 0; n < N; ++n) {
      const bool reached = den(n) > 0;
      inv_den(n) = reached ? 1 / den(n) : 0.0;
      Pt1(n) = reached ? std::max(0.0, 1 - c / den(n)) : 0.0;
      if(reached) log_sum += std::log(den(n));
    }
    Eigen::VectorXd P1(M);
    Eigen::MatrixXd PX(M, 3);
    {
      const internal::Gauss_sum to_target(X, inv_den, inv_den.asDiagonal() * X, s);
      parallel_for(m, threads, [&](std::size_t i, unsigned) {
        Eigen::Vector3d v;
        const Eigen::Index r = static_cast<Eigen::Index>(i);
        P1(r) = to_target(T.row(r).transpose(), &v);
        PX.row(r) = v.transpose();
      });
    }
    const double Np = P1.sum();
    const double neg_log_likelihood = -log_sum + 3.0 * static_cast<double>(N) * std::log(sigma2) / 2;
    if(!(Np > 0)) {
      Iteration_record rec;
      rec.iteration = f;
      report.iterations.push_back(rec);
      report.stop = Stop_reason::TOO_FEW_PAIRS;
      break;
    }
    // M step (low rank, Woodbury): W = 1/(λσ²) [F − d(P1) Q (λσ² Λ⁻¹ + Qᵀ d(P1) Q)⁻¹ Qᵀ F],
    // F = P X − d(P1) Y; T = Y + Q Λ Qᵀ W
    const Eigen::MatrixXd F = PX - P1.asDiagonal() * Y;
    const Eigen::MatrixXd dPQ = P1.asDiagonal() * Q;
    Eigen::MatrixXd inner = Q.transpose() * dPQ;
    inner.diagonal() += lambda * sigma2 * S.cwiseInverse();
    const Eigen::MatrixXd Wm = (F - dPQ * inner.ldlt().solve(Q.transpose() * F)) / (lambda * sigma2);
    QtW = Q.transpose() * Wm;
    const Eigen::MatrixXd Tn = Y + Q * (S.asDiagonal() * QtW);
    if(!Tn.allFinite()) throw Solver_failure("cpd_registration: the M step of iteration " + std::to_string(f) + " is not finite");
    const double trace_PX_T = (PX.cwiseProduct(Tn)).sum();
    sigma2 = std::abs(Pt1.dot(X.rowwise().squaredNorm()) - 2 * trace_PX_T + P1.dot(Tn.rowwise().squaredNorm())) / (3 * Np);
    const double objective = neg_log_likelihood + lambda / 2 * (QtW.transpose() * S.asDiagonal() * QtW).trace();

    Iteration_record rec;
    rec.iteration = f;
    rec.pairs = nn;
    rec.energy = objective;
    rec.step = (Tn - T).rowwise().norm().maxCoeff() * norm.scale;
    T = Tn;
    rec.rms_distance = problem.rms_to_target(norm.undo(T), threads);
    if(!internal::record_iteration(report, rec, callback)) break;
    if(std::abs(objective - previous) <= tolerance * std::abs(objective)) {
      report.stop = Stop_reason::CONVERGED;
      break;
    }
    previous = objective;
  }
  problem.write(norm.undo(T), deformed);
  report.seconds = problem.seconds();
  return report;
}

} // namespace shapecorr

#endif
