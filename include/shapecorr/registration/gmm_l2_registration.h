// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file gmm_l2_registration.h
/// The baseline of Jian & Vemuri 2011 (thesis chapter 6, "Jian2011"): the L2 distance between two
/// Gaussian mixtures, minimized over a thin-plate-spline warp with control points. Optimized by
/// L-BFGS (Debian's `liblbfgs`: link `-llbfgs`, which the `ShapeCorr::ShapeCorr` target does).
#ifndef SHAPECORR_REGISTRATION_GMM_L2_REGISTRATION_H
#define SHAPECORR_REGISTRATION_GMM_L2_REGISTRATION_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/gauss_sum.h>
#include <shapecorr/internal/low_rank_kernel.h>
#include <shapecorr/registration/internal/registration_problem.h>
#include <shapecorr/parameters.h>
#include <shapecorr/registration/cpd_registration.h>
#include <shapecorr/registration/registration_report.h>

#include <lbfgs.h>

#include <Eigen/Core>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace shapecorr {
namespace internal {

/// A thin-plate-spline warp of R³ with control points c_k: t(y) = [1 y] A + Σ_k u(|y − c_k|) w_k,
/// u(r) = −r (the 3-D kernel), Σ_k w_k = 0 and Σ_k c_k w_kᵀ = 0 (the warp is affine at infinity).
/// The constraint is built in: w = N γ, N an orthonormal basis of the null space of [1 c]ᵀ. For
/// fixed points y (rows of Y) the warp is linear in θ = [A; γ]: T = B θ. The bending energy is
/// tr(γᵀ R γ), R = Nᵀ U(c, c) N (positive semi-definite: −r is conditionally positive definite).
struct Thin_plate_spline_basis {
  Eigen::MatrixXd B; // M × (4 + columns of N)
  Eigen::MatrixXd R; // bending form on γ
  Eigen::Index affine_columns = 4;

  Thin_plate_spline_basis(const Eigen::MatrixXd& Y, const Eigen::MatrixXd& C) {
    const Eigen::Index M = Y.rows(), K = C.rows();
    Eigen::MatrixXd P(K, 4);
    P.col(0).setOnes();
    P.rightCols(3) = C;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(P);
    const Eigen::Index rank = qr.rank();
    const Eigen::MatrixXd full_q = qr.householderQ() * Eigen::MatrixXd::Identity(K, K);
    const Eigen::MatrixXd Nb = full_q.rightCols(K - rank);
    Eigen::MatrixXd Uyc(M, K), Ucc(K, K);
    for(Eigen::Index k = 0; k < K; ++k) {
      Uyc.col(k) = -(Y.rowwise() - C.row(k)).rowwise().norm();
      Ucc.col(k) = -(C.rowwise() - C.row(k)).rowwise().norm();
    }
    B.resize(M, 4 + Nb.cols());
    B.col(0).setOnes();
    B.block(0, 1, M, 3) = Y;
    B.rightCols(Nb.cols()) = Uyc * Nb;
    R = Nb.transpose() * Ucc * Nb;
    R = 0.5 * (R + R.transpose());
  }
  /// θ of the identity warp.
  Eigen::MatrixXd identity() const {
    Eigen::MatrixXd theta = Eigen::MatrixXd::Zero(B.cols(), 3);
    theta.block(1, 0, 3, 3).setIdentity();
    return theta;
  }
};

/// One level of GMM-L2: the relative L2 distance between the mixtures of the moved template and
/// of the target, plus λ × the bending energy, as a function of θ (and its gradient).
struct Gmm_l2_level {
  const Thin_plate_spline_basis& tps;
  const Eigen::MatrixXd& X;
  const Gauss_sum& target_sum; // over X, weights 1, vector weights X
  double s, lambda, self_target; // bandwidth, weight, S_XX / N²
  unsigned threads;

  // E(θ) and ∂E/∂θ; T = B θ
  double evaluate(const Eigen::MatrixXd& theta, Eigen::MatrixXd& gradient) const {
    const Eigen::MatrixXd T = tps.B * theta;
    const Eigen::Index M = T.rows(), N = X.rows();
    const Gauss_sum template_sum(T, Eigen::VectorXd::Ones(M), T, s);
    Eigen::VectorXd a(M), c(M);
    Eigen::MatrixXd b(M, 3), d(M, 3);
    parallel_for(static_cast<std::size_t>(M), threads, [&](std::size_t i, unsigned) {
      const Eigen::Index r = static_cast<Eigen::Index>(i);
      const Eigen::Vector3d t = T.row(r).transpose();
      Eigen::Vector3d v;
      a(r) = template_sum(t, &v);
      b.row(r) = v.transpose();
      c(r) = target_sum(t, &v);
      d.row(r) = v.transpose();
    });
    const double m2 = static_cast<double>(M) * static_cast<double>(M), mn = static_cast<double>(M) * static_cast<double>(N);
    const double data = (a.sum() / m2 - 2 * c.sum() / mn + self_target) / self_target;
    // ∂/∂t_m: S_TT gives −(2/s²)(t_m a_m − b_m), S_TX gives −(1/s²)(t_m c_m − d_m)
    const Eigen::MatrixXd gT = ((-2 / (s * s)) * (a.asDiagonal() * T - b) / m2 + (2 / (s * s)) * (c.asDiagonal() * T - d) / mn) / self_target;
    gradient = tps.B.transpose() * gT;
    const Eigen::Index g = tps.R.rows();
    const Eigen::MatrixXd gamma = theta.bottomRows(g);
    gradient.bottomRows(g) += 2 * lambda * tps.R * gamma;
    return data + lambda * (gamma.transpose() * tps.R * gamma).trace();
  }
};

} // namespace internal

/// \ingroup PkgShapeCorrRegistration
/// GMM-L2 registration with a thin-plate-spline warp (Jian & Vemuri, "Robust point set
/// registration using Gaussian mixture models", PAMI 2011; the thesis's "Jian2011"), on the
/// vertices of the two meshes: moves the template's vertices to fit the target's and writes them
/// into `deformed` (a `WritablePropertyMap` from the template's `vertex_descriptor` to its point
/// type). The template should be roughly aligned first. Like CPD it assumes that the two vertex
/// sets sample the surfaces alike.
///
/// Both vertex sets are moved and scaled by one similarity (the target's centroid to 0, its RMS
/// radius to 1). Each is a mixture of equal isotropic Gaussians on its vertices; the warp is a
/// thin-plate spline whose control points are `number_of_control_points` template vertices by
/// furthest point sampling. For each level ℓ of the schedules, with bandwidth s = `scale_schedule`[ℓ]
/// (the Gaussians have standard deviation s/√2, so that the product of two is a Gaussian of width
/// s) and λ = `regularization_schedule`[ℓ], L-BFGS minimizes
///   E = |f_T − g_X|² / |g_X|² + λ × bending energy,
/// the L2 distance between the mixtures relative to the target's own norm (so that λ does not
/// depend on the number of points), from where the previous level ended. The mixture sums are
/// fast Gauss sums (truncated at 1e-6, clustered into cells of s/4 while s is wide against the
/// spacing).
///
/// An iteration is one L-BFGS iteration (of any level): energy = E; rms_distance (to the target
/// surface) and step as in `Iteration_record`; pairs = number of target vertices. Each level stops
/// after `number_of_iterations` L-BFGS iterations or when L-BFGS converges or can make no progress
/// (its line search fails); the report's stop is ITERATION_LIMIT when the last level ran out of
/// iterations, CONVERGED otherwise, CANCELLED when the callback returned false.
///
/// | named parameter | pack | meaning | type | default |
/// |---|---|---|---|---|
/// | `scale_schedule` | np1 | s per level (normalized units) | `std::vector<double>` | {0.5, 0.2, 0.1, 0.05} |
/// | `regularization_schedule` | np1 | λ per level (as many as scales) | `std::vector<double>` | {1e-2, 1e-3, 1e-4, 1e-5} |
/// | `number_of_control_points` | np1 | control points of the spline | `std::size_t` | 300 |
/// | `number_of_iterations` | np1 | L-BFGS iterations per level, at most | `std::size_t` | 50 |
/// | `iteration_callback` | np1 | called after each iteration; false stops | `std::function<bool(const Iteration_record&)>` | none |
/// | `number_of_threads` | np1 | threads (0: all) | `unsigned` | 0 |
/// | `vertex_point_map`, `vertex_index_map` | np1, np2 | positions, indices | property maps | the mesh's |
///
/// \throws Invalid_input for a mesh without triangles or with a non-finite coordinate;
///         Invalid_argument for parameters out of range
template <typename TemplateMesh, typename TargetMesh, typename VertexPointMap, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Registration_report gmm_l2_registration(const TemplateMesh& tmpl, const TargetMesh& target, VertexPointMap deformed,
                                        const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                        const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const internal::Registration_problem<TemplateMesh> problem(tmpl, target, np1, np2, "gmm_l2_registration");
  const std::vector<double> scales = choose_parameter(get_parameter(np1, internal_np::scale_schedule), std::vector<double>{0.5, 0.2, 0.1, 0.05});
  const std::vector<double> lambdas = choose_parameter(get_parameter(np1, internal_np::regularization_schedule), std::vector<double>{1e-2, 1e-3, 1e-4, 1e-5});
  const std::size_t controls = choose_parameter(get_parameter(np1, internal_np::number_of_control_points), std::size_t(300));
  const std::size_t iterations = choose_parameter(get_parameter(np1, CGAL::internal_np::number_of_iterations), std::size_t(50));
  const auto callback = choose_parameter(get_parameter(np1, internal_np::iteration_callback), std::function<bool(const Iteration_record&)>());
  const unsigned threads = choose_parameter(get_parameter(np1, internal_np::number_of_threads), 0u);
  if(scales.empty() || scales.size() != lambdas.size()) throw Invalid_argument("gmm_l2_registration: scale_schedule and regularization_schedule need the same, non-zero length");
  for(double s : scales)
    if(!(s > 0) || !std::isfinite(s)) throw Invalid_argument("gmm_l2_registration: every scale must be positive and finite");
  for(double l : lambdas)
    if(!(l >= 0) || !std::isfinite(l)) throw Invalid_argument("gmm_l2_registration: every regularization weight must be finite and non-negative");
  if(controls < 1 || controls > 5000) throw Invalid_argument("gmm_l2_registration: number_of_control_points must be in [1, 5000]");
  if(iterations > 10000) throw Invalid_argument("gmm_l2_registration: number_of_iterations above 10000");

  const internal::Point_set_normalization norm(problem.target_arrays().V);
  const Eigen::MatrixXd X = norm.apply(problem.target_arrays().V);
  const Eigen::MatrixXd Y = norm.apply(problem.template_arrays().V);
  const std::vector<std::size_t> chosen = internal::euclidean_furthest_points(Y, controls);
  Eigen::MatrixXd C(static_cast<Eigen::Index>(chosen.size()), 3);
  for(std::size_t k = 0; k < chosen.size(); ++k) C.row(static_cast<Eigen::Index>(k)) = Y.row(static_cast<Eigen::Index>(chosen[k]));
  const internal::Thin_plate_spline_basis tps(Y, C);
  Eigen::MatrixXd theta = tps.identity();
  Eigen::MatrixXd T = Y;

  Registration_report report;
  report.initial_rms = problem.rms_to_target(norm.undo(T), threads);
  report.final_rms = report.initial_rms;
  report.stop = Stop_reason::CONVERGED;
  const Eigen::Index N = X.rows();
  struct Context {
    const internal::Gmm_l2_level* level;
    Eigen::Index rows;
    Registration_report* report;
    const internal::Registration_problem<TemplateMesh>* problem;
    const internal::Point_set_normalization* norm;
    Eigen::MatrixXd* T;
    const std::function<bool(const Iteration_record&)>* callback;
    std::size_t pairs;
    unsigned threads;
    bool cancelled;
  };
  auto evaluate = [](void* instance, const lbfgsfloatval_t* x, lbfgsfloatval_t* g, const int n, const lbfgsfloatval_t) -> lbfgsfloatval_t {
    Context& ctx = *static_cast<Context*>(instance);
    const Eigen::Map<const Eigen::MatrixXd> theta(x, ctx.rows, 3);
    Eigen::MatrixXd gradient;
    const double e = ctx.level->evaluate(theta, gradient);
    Eigen::Map<Eigen::MatrixXd>(g, ctx.rows, 3) = gradient;
    (void)n;
    return e;
  };
  auto progress = [](void* instance, const lbfgsfloatval_t* x, const lbfgsfloatval_t*, const lbfgsfloatval_t fx, const lbfgsfloatval_t,
                     const lbfgsfloatval_t, const lbfgsfloatval_t, int, int, int) -> int {
    Context& ctx = *static_cast<Context*>(instance);
    const Eigen::Map<const Eigen::MatrixXd> theta(x, ctx.rows, 3);
    const Eigen::MatrixXd Tn = ctx.level->tps.B * theta;
    Iteration_record rec;
    rec.iteration = ctx.report->iterations.size();
    rec.pairs = ctx.pairs;
    rec.energy = fx;
    rec.step = (Tn - *ctx.T).rowwise().norm().maxCoeff() * ctx.norm->scale;
    *ctx.T = Tn;
    rec.rms_distance = ctx.problem->rms_to_target(ctx.norm->undo(Tn), ctx.threads);
    if(!internal::record_iteration(*ctx.report, rec, *ctx.callback)) {
      ctx.cancelled = true;
      return 1;
    }
    return 0;
  };
  const std::function<bool(const Iteration_record&)> no_callback;
  for(std::size_t l = 0; l < scales.size() && iterations > 0; ++l) {
    const double s = scales[l];
    const internal::Gauss_sum target_sum(X, Eigen::VectorXd::Ones(N), X, s);
    double self = 0;
    for(Eigen::Index n = 0; n < N; ++n) self += target_sum(X.row(n).transpose());
    self /= static_cast<double>(N) * static_cast<double>(N);
    const internal::Gmm_l2_level level{tps, X, target_sum, s, lambdas[l], self, threads};
    Context ctx{&level, theta.rows(), &report, &problem, &norm, &T, callback ? &callback : &no_callback, static_cast<std::size_t>(N), threads, false};
    lbfgs_parameter_t param;
    lbfgs_parameter_init(&param);
    param.max_iterations = static_cast<int>(iterations);
    param.epsilon = 1e-6;
    param.past = 3;
    param.delta = 1e-7;
    std::vector<lbfgsfloatval_t> x(static_cast<std::size_t>(theta.size()));
    Eigen::Map<Eigen::MatrixXd>(x.data(), theta.rows(), 3) = theta;
    lbfgsfloatval_t fx = 0;
    const int status = lbfgs(static_cast<int>(x.size()), x.data(), &fx, evaluate, progress, &ctx, &param);
    theta = Eigen::Map<Eigen::MatrixXd>(x.data(), theta.rows(), 3);
    T = tps.B * theta;
    if(!T.allFinite()) throw Solver_failure("gmm_l2_registration: the warp of level " + std::to_string(l) + " is not finite");
    if(ctx.cancelled) {
      report.stop = Stop_reason::CANCELLED;
      break;
    }
    report.stop = status == LBFGSERR_MAXIMUMITERATION ? Stop_reason::ITERATION_LIMIT : Stop_reason::CONVERGED;
  }
  if(iterations == 0) report.stop = Stop_reason::ITERATION_LIMIT;
  report.final_rms = problem.rms_to_target(norm.undo(T), threads);
  problem.write(norm.undo(T), deformed);
  report.seconds = problem.seconds();
  return report;
}

} // namespace shapecorr

#endif
