// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file shape_model_quality.h
/// The quality measures of statistical shape models (Davies 2002; Styner et al. 2003): compactness,
/// generalization (leave-one-out) and specificity, each a curve over the number of modes M.
#ifndef SHAPECORR_SHAPE_MODEL_SHAPE_MODEL_QUALITY_H
#define SHAPECORR_SHAPE_MODEL_SHAPE_MODEL_QUALITY_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parallel.h>
#include <shapecorr/parameters.h>
#include <shapecorr/shape_model/Statistical_shape_model.h>

#include <Eigen/Core>

#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <random>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrShapeModel
/// A quality curve: `value[M − 1]` for M = 1, 2, … modes, with its `standard_error`.
struct Shape_model_curve {
  std::vector<double> value;          ///< the measure with M modes, at M − 1
  std::vector<double> standard_error; ///< its standard error
  /// Generalization only: `per_sample[i][M − 1]`, training shape i's own leave-one-out error (a
  /// shape the others do not describe, e.g. a poor fit, stands out here). Empty otherwise.
  std::vector<std::vector<double>> per_sample;
};

/// \ingroup PkgShapeCorrShapeModel
/// Compactness C(M) = Σ_{i ≤ M} λ_i, the variance the first M modes hold (squared mesh units), for
/// M = 1 … k; `standard_error` holds σ(C(M)) = Σ_{i ≤ M} λ_i √(2/N) (Davies 2002), 0 without training
/// shapes. Divide by `total_variance()` for the explained fraction. A compact model holds most
/// variance in few modes.
inline Shape_model_curve shape_model_compactness(const Statistical_shape_model& model) {
  Shape_model_curve c;
  const double N = static_cast<double>(model.number_of_training_shapes());
  double sum = 0;
  for(Eigen::Index i = 0; i < model.variances().size(); ++i) {
    sum += model.variances()[i];
    c.value.push_back(sum);
    c.standard_error.push_back(N > 0 ? sum * std::sqrt(2.0 / N) : 0.0);
  }
  return c;
}

namespace internal {

inline void require_training_shapes(const Statistical_shape_model& model, const char* what, std::size_t at_least) {
  if(model.number_of_training_shapes() < at_least)
    throw Invalid_argument(std::string(what) + ": the model keeps " + std::to_string(model.number_of_training_shapes()) + " training shapes, " +
                           std::to_string(at_least) + " are needed");
  if(!model.keeps_all_variance())
    throw Invalid_argument(std::string(what) + ": the model does not keep all the training variance (a truncated model): its training shapes cannot be recovered");
}

inline std::vector<Eigen::Matrix3Xd> training_shapes(const Statistical_shape_model& model) {
  std::vector<Eigen::Matrix3Xd> shapes;
  const Eigen::Index n = static_cast<Eigen::Index>(model.number_of_vertices());
  for(std::size_t i = 0; i < model.number_of_training_shapes(); ++i) {
    const Eigen::VectorXd x = model.training_shape(i);
    shapes.push_back(Eigen::Map<const Eigen::Matrix3Xd>(x.data(), 3, n));
  }
  return shapes;
}

inline Shape_model_curve mean_and_standard_error(const std::vector<std::vector<double>>& samples) {
  // samples[j][M − 1]: sample j's value with M modes
  Shape_model_curve c;
  if(samples.empty()) return c;
  const std::size_t count = samples.size(), modes = samples[0].size();
  for(std::size_t m = 0; m < modes; ++m) {
    double mean = 0, square = 0;
    for(const auto& s : samples) mean += s[m] / static_cast<double>(count);
    for(const auto& s : samples) square += (s[m] - mean) * (s[m] - mean);
    c.value.push_back(mean);
    c.standard_error.push_back(count > 1 ? std::sqrt(square / static_cast<double>(count - 1)) / std::sqrt(static_cast<double>(count)) : 0.0);
  }
  return c;
}

} // namespace internal

/// \ingroup PkgShapeCorrShapeModel
/// Generalization G(M) (leave-one-out): for each training shape, a model is built from the others
/// (the same Procrustes alignment, scale or not), the left-out shape is reconstructed with that
/// model's first M modes (`reconstruct()`: aligned, projected, moved back) and compared with
/// itself by the mean vertex distance; G(M) is the mean over the N shapes and `standard_error` its
/// standard error, for M = 1 … N − 2; `per_sample` keeps each shape's own errors. A model that generalizes well describes unseen shapes with
/// few modes. In mesh units.
/// \param model a model that keeps its training shapes (`keeps_all_variance()`), N ≥ 3
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `number_of_threads` | threads over the left-out shapes (0: all) | `unsigned` | 0 |
/// | `progress_callback` | called with (shapes done, N) | `std::function<void(std::size_t, std::size_t)>` | none |
/// \throws Invalid_argument when the model keeps fewer than 3 training shapes or is truncated
template <typename NamedParameters = parameters::Default_named_parameters>
Shape_model_curve shape_model_generalization(const Statistical_shape_model& model, const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::require_training_shapes(model, "generalization", 3);
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0u);
  const auto progress = choose_parameter(get_parameter(np, internal_np::progress_callback), std::function<void(std::size_t, std::size_t)>());
  const std::vector<Eigen::Matrix3Xd> shapes = internal::training_shapes(model);
  const std::size_t N = shapes.size(), modes = N - 2;
  const Eigen::Index n3 = 3 * static_cast<Eigen::Index>(model.number_of_vertices());
  std::vector<std::vector<double>> errors(N, std::vector<double>(modes, 0.0));
  std::atomic<std::size_t> done(0);
  std::mutex report;
  parallel_for(N, threads, [&](std::size_t left_out, unsigned) {
    std::vector<Eigen::Matrix3Xd> others;
    for(std::size_t j = 0; j < N; ++j)
      if(j != left_out) others.push_back(shapes[j]);
    const Statistical_shape_model loo = build_statistical_shape_model(others, model.triangles(), model.with_scale());
    // projected once; the reconstruction with m modes grows by one mode at a time, in the model's
    // frame, and the left-out shape is moved there once (the same as reconstruct(x, m), moved back)
    const Eigen::Map<const Eigen::Matrix3Xd> X(shapes[left_out].data(), 3, n3 / 3);
    const Shape_model_projection p = loo.project(Eigen::Map<const Eigen::VectorXd>(shapes[left_out].data(), n3));
    const Eigen::Matrix3Xd aligned = internal::transformed(p.to_model, X);
    const Eigen::Map<const Eigen::VectorXd> x(aligned.data(), n3);
    // distances in the model's frame scale by the alignment's scale: divide it out (1 without scale)
    Eigen::VectorXd y = loo.mean();
    for(std::size_t m = 1; m <= modes; ++m) {
      const Eigen::Index i = static_cast<Eigen::Index>(m - 1);
      if(i < loo.variances().size()) y += (p.coefficients[i] * std::sqrt(loo.variances()[i])) * loo.modes().col(i); // (fewer modes: as many as there are)
      errors[left_out][m - 1] = internal::mean_vertex_distance(y, x) / p.to_model.scale;
    }
    if(progress) {
      std::lock_guard<std::mutex> lock(report);
      progress(++done, N);
    }
  });
  Shape_model_curve curve = internal::mean_and_standard_error(errors);
  curve.per_sample = std::move(errors);
  return curve;
}

/// \ingroup PkgShapeCorrShapeModel
/// Specificity S(M): K random instances of the model with M modes (coefficients drawn from N(0, 1)
/// for the first M modes, 0 for the others) are each compared, by the mean vertex distance, with
/// the nearest training shape (Procrustes-aligned, the model's frame); S(M) is the mean over the K
/// instances and `standard_error` its standard error, for M = 1 … k. A specific model draws only
/// shapes like those it was trained on. In mesh units. The same `random_seed` gives the same curve.
/// \param model a model that keeps its training shapes (`keeps_all_variance()`)
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `number_of_samples` | K | `std::size_t` | 1000 |
/// | `random_seed` | seed of the coefficients | `unsigned` | 0 |
/// | `number_of_threads` | threads over the instances (0: all) | `unsigned` | 0 |
/// \throws Invalid_argument when the model keeps no training shape or is truncated, or K is 0
template <typename NamedParameters = parameters::Default_named_parameters>
Shape_model_curve shape_model_specificity(const Statistical_shape_model& model, const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::require_training_shapes(model, "specificity", 1);
  const std::size_t K = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_samples), std::size_t(1000));
  const unsigned seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0u);
  if(K == 0) throw Invalid_argument("specificity: number_of_samples must be positive");
  const std::size_t k = model.number_of_modes(), N = model.number_of_training_shapes();
  std::vector<Eigen::VectorXd> training(N);
  for(std::size_t i = 0; i < N; ++i) training[i] = model.training_shape(i);
  Eigen::MatrixXd coefficients(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(K));
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for(Eigen::Index s = 0; s < coefficients.cols(); ++s)
    for(Eigen::Index i = 0; i < coefficients.rows(); ++i) coefficients(i, s) = normal(random);
  std::vector<std::vector<double>> distances(K, std::vector<double>(k, 0.0));
  parallel_for(K, threads, [&](std::size_t s, unsigned) {
    Eigen::VectorXd x = model.mean(); // the instance with m modes, one mode added at a time
    for(std::size_t m = 1; m <= k; ++m) {
      const Eigen::Index i = static_cast<Eigen::Index>(m - 1);
      x += (coefficients(i, static_cast<Eigen::Index>(s)) * std::sqrt(model.variances()[i])) * model.modes().col(i);
      double nearest = std::numeric_limits<double>::infinity();
      for(const auto& t : training) nearest = std::min(nearest, internal::mean_vertex_distance(x, t));
      distances[s][m - 1] = nearest;
    }
  });
  return internal::mean_and_standard_error(distances);
}

} // namespace shapecorr

#endif
