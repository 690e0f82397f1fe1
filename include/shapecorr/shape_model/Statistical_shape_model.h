// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Statistical_shape_model.h
/// Statistical shape models (point distribution models) of meshes in correspondence: generalized
/// Procrustes alignment, principal component analysis through the Gram matrix, instances,
/// projection and reconstruction (thesis chapter 6, the statistical shape models of template-fitted
/// bones; Cootes et al. 1995, Heimann & Meinzer 2009).
#ifndef SHAPECORR_SHAPE_MODEL_STATISTICAL_SHAPE_MODEL_H
#define SHAPECORR_SHAPE_MODEL_STATISTICAL_SHAPE_MODEL_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parameters.h>
#include <shapecorr/internal/binary_file.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration/rigid_alignment.h>


#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrShapeModel
/// How `principal_components()` computes the modes of a data matrix D (3n × N, one centred shape
/// per column).
enum class Pca_method {
  GRAM_MATRIX, ///< eigenvectors of the N × N Gram matrix DᵀD/(N − 1), mapped back by D (N ≪ 3n: the usual case)
  DENSE_SVD    ///< thin singular value decomposition of D/√(N − 1) (Eigen's BDCSVD): the reference
};

/// \ingroup PkgShapeCorrShapeModel
/// The principal components of a data matrix: `modes` (3n × k, orthonormal columns), `variances`
/// (k, descending, positive) and the `total_variance` (the trace of the covariance, kept modes or not).
struct Principal_components {
  Eigen::MatrixXd modes;      ///< 3n × k, orthonormal columns
  Eigen::VectorXd variances;  ///< k, descending, positive
  double total_variance = 0;  ///< the trace of the covariance (every mode, kept or not)
};

/// \ingroup PkgShapeCorrShapeModel
/// The principal components of the columns of `centered` (3n × N, each column a shape minus the
/// mean shape): the eigenvectors of the covariance C = D Dᵀ/(N − 1) with a non-zero eigenvalue
/// (above 1e-12 of the largest and above `negligible`: at most N − 1 of them), largest first. Each mode's sign is fixed so
/// that its entry of largest magnitude is positive, so both methods return the same modes.
/// \param method `Pca_method::GRAM_MATRIX` (default; O(N² n) time, O(N n) memory) or `DENSE_SVD`
/// \param negligible variances at most this are round-off (e.g. of shapes equal up to a Procrustes tolerance)
/// \throws Invalid_argument for fewer than two columns or a non-finite entry
inline Principal_components principal_components(const Eigen::MatrixXd& centered, Pca_method method = Pca_method::GRAM_MATRIX,
                                                 double negligible = 0) {
  const Eigen::Index N = centered.cols();
  if(N < 2) throw Invalid_argument("principal components: at least two shapes are needed, got " + std::to_string(N));
  if(!centered.allFinite()) throw Invalid_argument("principal components: the data matrix has a non-finite entry");
  const double norm = 1.0 / std::sqrt(static_cast<double>(N - 1));
  // the covariance's non-zero eigenvalues, descending, and how many count (see above)
  auto kept = [&](const Eigen::VectorXd& all) {
    const double largest = all.size() ? all.maxCoeff() : 0.0;
    Eigen::Index k = 0;
    while(k < all.size() && k < N - 1 && all[k] > 1e-12 * largest && all[k] > negligible) ++k;
    return k;
  };
  Principal_components pc;
  Eigen::Index k = 0;
  if(method == Pca_method::GRAM_MATRIX) {
    // G = DᵀD/(N − 1) (one matrix product), its eigenpairs (λ, u); the mode of u is D u/√((N − 1) λ)
    // the lower triangle only (a symmetric rank update: half the products); the solver reads no more
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(N, N);
    G.selfadjointView<Eigen::Lower>().rankUpdate(centered.transpose(), norm * norm);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(G);
    if(es.info() != Eigen::Success) throw Solver_failure("principal components: the eigensolver of the Gram matrix failed");
    const Eigen::VectorXd all = es.eigenvalues().reverse();
    k = kept(all);
    pc.variances = all.head(k);
    const Eigen::MatrixXd U = es.eigenvectors().rowwise().reverse().leftCols(k) * (norm * pc.variances.cwiseSqrt().cwiseInverse()).asDiagonal();
    pc.modes.noalias() = centered * U;
    pc.total_variance = G.trace();
  } else {
    Eigen::BDCSVD<Eigen::MatrixXd> svd(centered * norm, Eigen::ComputeThinU);
    if(svd.info() != Eigen::Success) throw Solver_failure("principal components: the singular value decomposition failed");
    const Eigen::VectorXd all = svd.singularValues().array().square();
    k = kept(all);
    pc.variances = all.head(k);
    pc.modes = svd.matrixU().leftCols(k);
    pc.total_variance = centered.squaredNorm() * norm * norm;
  }
  for(Eigen::Index j = 0; j < k; ++j) {
    Eigen::Index at = 0;
    pc.modes.col(j).cwiseAbs().maxCoeff(&at);
    if(pc.modes(at, j) < 0) pc.modes.col(j) = -pc.modes.col(j);
  }
  return pc;
}

namespace internal {

/// The similarity (or rigid motion) that best maps the points of `from` onto those of `to`
/// (both 3 × n, corresponding columns), in least squares (Umeyama 1991).
inline Similarity_transform procrustes_fit(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to, bool with_scale) {
  const Eigen::Matrix4d T = Eigen::umeyama(from, to, with_scale);
  Similarity_transform s;
  const Eigen::Matrix3d A = T.topLeftCorner<3, 3>();
  s.scale = std::cbrt(A.determinant());
  s.rotation = A / s.scale;
  s.translation = T.topRightCorner<3, 1>();
  return s;
}

inline Eigen::Matrix3Xd transformed(const Similarity_transform& t, const Eigen::Matrix3Xd& x) {
  return ((t.scale * t.rotation) * x).colwise() + t.translation;
}

/// Mean Euclidean distance between corresponding vertices of two shapes (3n vectors, interleaved).
inline double mean_vertex_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index n = a.size() / 3;
  return (Eigen::Map<const Eigen::Matrix3Xd>(a.data(), 3, n) - Eigen::Map<const Eigen::Matrix3Xd>(b.data(), 3, n)).colwise().norm().mean();
}

} // namespace internal

/// \ingroup PkgShapeCorrShapeModel
/// The result of `generalized_procrustes_alignment()`.
struct Procrustes_alignment {
  std::vector<Eigen::Matrix3Xd> aligned;        ///< each shape moved onto the mean (3 × n)
  std::vector<Similarity_transform> transforms; ///< shape i ↦ aligned[i]
  Eigen::Matrix3Xd mean;                        ///< the mean of the aligned shapes
  std::size_t iterations = 0;                   ///< alignment rounds done
  bool converged = false;                       ///< the mean moved by less than the tolerance
};

/// \ingroup PkgShapeCorrShapeModel
/// Generalized Procrustes alignment (Gower 1975): moves every shape (3 × n, the same n points in
/// correspondence) by a rigid motion, or a similarity with `with_scale`, to minimize the sum of
/// squared distances to their mean. Rounds: align every shape to the current mean (Umeyama), average,
/// rotate the new mean onto the old one (no drift) and, with scale, give it the mean centroid size of
/// the input shapes; stop when the mean moves by less than `tolerance` times its size, or after
/// `max_rounds`. The result lies in the frame of the first shape: the mean's centroid is that shape's
/// centroid and its orientation that shape's, so a model built from template fits sits where the
/// template was.
/// \throws Invalid_argument for fewer than two shapes, shapes of different sizes, fewer than three
///         points, or non-finite coordinates
inline Procrustes_alignment generalized_procrustes_alignment(const std::vector<Eigen::Matrix3Xd>& shapes, bool with_scale,
                                                             std::size_t max_rounds = 100, double tolerance = 1e-10) {
  const std::size_t N = shapes.size();
  if(N < 2) throw Invalid_argument("Procrustes alignment: at least two shapes are needed, got " + std::to_string(N));
  const Eigen::Index n = shapes[0].cols();
  if(n < 3) throw Invalid_argument("Procrustes alignment: shapes of at least three points are needed");
  for(std::size_t i = 0; i < N; ++i) {
    if(shapes[i].cols() != n)
      throw Invalid_argument("Procrustes alignment: shape " + std::to_string(i) + " has " + std::to_string(shapes[i].cols()) + " points, shape 0 has " +
                             std::to_string(n) + ": the shapes must be in correspondence (the same vertices)");
    if(!shapes[i].allFinite()) throw Invalid_argument("Procrustes alignment: shape " + std::to_string(i) + " has a non-finite coordinate");
  }
  const Eigen::Vector3d origin = shapes[0].rowwise().mean();
  double size = 0; // the mean centroid size: the scale of the mean with `with_scale`
  for(const auto& s : shapes) size += (s.colwise() - s.rowwise().mean()).norm() / static_cast<double>(N);
  Eigen::Matrix3Xd mean = shapes[0].colwise() - origin;
  if(with_scale) mean *= size / mean.norm();
  Procrustes_alignment r;
  r.aligned.resize(N);
  r.transforms.resize(N);
  for(std::size_t round = 0; round <= max_rounds; ++round) {
    for(std::size_t i = 0; i < N; ++i) {
      r.transforms[i] = internal::procrustes_fit(shapes[i], mean, with_scale);
      r.aligned[i] = internal::transformed(r.transforms[i], shapes[i]);
    }
    if(round == max_rounds) break; // the last alignment is to the final mean
    Eigen::Matrix3Xd next = Eigen::Matrix3Xd::Zero(3, n);
    for(const auto& a : r.aligned) next += a / static_cast<double>(N);
    next = internal::transformed(internal::procrustes_fit(next, mean, false), next);
    if(with_scale) next *= size / next.norm();
    const double moved = (next - mean).norm() / std::max(mean.norm(), 1e-300);
    mean = next;
    r.iterations = round + 1;
    if(moved < tolerance) {
      r.converged = true;
      max_rounds = round + 1; // one more round aligns every shape to this mean, then stops
    }
  }
  // into the frame of the first shape: its centroid (the mean's orientation is already its own)
  Similarity_transform to_first;
  to_first.translation = origin;
  for(std::size_t i = 0; i < N; ++i) {
    r.aligned[i].colwise() += origin;
    r.transforms[i] = to_first.after(r.transforms[i]);
  }
  r.mean = mean.colwise() + origin;
  return r;
}

/// \ingroup PkgShapeCorrShapeModel
/// A coefficient vector of a shape and the similarity that moved it into the model's frame: the
/// result of `Statistical_shape_model::project()`.
struct Shape_model_projection {
  Eigen::VectorXd coefficients; ///< one per mode, in standard deviations of the mode
  Similarity_transform to_model; ///< the shape's frame ↦ the model's (rigid unless the model has scale)
};

/// \ingroup PkgShapeCorrShapeModel
/// A statistical shape model (a point distribution model): shapes of n points in correspondence
/// (meshes of one connectivity, e.g. one template fitted to every specimen) written as
///
///   x = μ + Σ_i c_i √λ_i v_i,
///
/// μ the mean shape, v_i the orthonormal modes (principal components of the Procrustes-aligned
/// training shapes) and λ_i their variances, largest first; the coefficients c_i are in standard
/// deviations, so c ~ N(0, I) draws plausible shapes. Shapes are vectors of 3n numbers, interleaved
/// (x₀, y₀, z₀, x₁, …) — `Eigen::Map<Eigen::Matrix3Xd>` views one as 3 × n — in the frame of the
/// first training shape (`generalized_procrustes_alignment()`), in its units.
///
/// Built by `build_statistical_shape_model()`; kept in a file by `save()` / `load()`, or in the
/// Statismo HDF5 layout (`shape_model/statismo_io.h`). The model keeps the training shapes' scores,
/// so the leave-one-out and specificity measures (`shape_model_generalization()`,
/// `shape_model_specificity()`) can run from a loaded model.
class Statistical_shape_model {
public:
  Statistical_shape_model() = default;

  /// A model from its parts: `mean` (3n), `modes` (3n × k, orthonormal columns), `variances` (k,
  /// positive, descending), `total_variance` (of the training data: at least the sum of the
  /// variances), `triangles` (the connectivity, 0-based vertex indices), `scores` (k × N, the
  /// training shapes' coefficients in standard deviations; may be empty), `with_scale` (the
  /// Procrustes alignment included scale).
  /// \throws Invalid_argument when the sizes disagree or a value is out of range
  Statistical_shape_model(Eigen::VectorXd mean, Eigen::MatrixXd modes, Eigen::VectorXd variances, double total_variance,
                          std::vector<std::array<std::size_t, 3>> triangles, Eigen::MatrixXd scores = Eigen::MatrixXd(), bool with_scale = false)
    : m_mean(std::move(mean)), m_modes(std::move(modes)), m_variances(std::move(variances)), m_total(total_variance),
      m_triangles(std::move(triangles)), m_scores(std::move(scores)), m_scale(with_scale) {
    check();
  }

  /// Number of points (mesh vertices) n.
  std::size_t number_of_vertices() const { return static_cast<std::size_t>(m_mean.size() / 3); }
  /// Number of modes k.
  std::size_t number_of_modes() const { return static_cast<std::size_t>(m_variances.size()); }
  /// Number of training shapes N whose scores the model keeps (0: none).
  std::size_t number_of_training_shapes() const { return static_cast<std::size_t>(m_scores.cols()); }
  /// The mean shape μ (3n, interleaved).
  const Eigen::VectorXd& mean() const { return m_mean; }
  /// The modes v_i as columns (3n × k), orthonormal.
  const Eigen::MatrixXd& modes() const { return m_modes; }
  /// The variances λ_i of the modes (k, descending), in squared mesh units.
  const Eigen::VectorXd& variances() const { return m_variances; }
  /// The total variance of the training shapes (the trace of their covariance).
  double total_variance() const { return m_total; }
  /// λ_i / total variance: the share of the variation each mode explains.
  Eigen::VectorXd explained_variance_ratios() const { return m_variances / std::max(m_total, 1e-300); }
  /// The mesh connectivity shared by every shape (0-based vertex indices, as the template's faces).
  const std::vector<std::array<std::size_t, 3>>& triangles() const { return m_triangles; }
  /// The training shapes' coefficients (k × N, standard deviations).
  const Eigen::MatrixXd& training_scores() const { return m_scores; }
  /// Whether the Procrustes alignment included a uniform scale (then `project()` scales too).
  bool with_scale() const { return m_scale; }
  /// Names of the training shapes (e.g. their files), when given; empty otherwise.
  const std::vector<std::string>& training_names() const { return m_names; }
  /// Sets the names of the training shapes (N of them, or none).
  void set_training_names(std::vector<std::string> names) {
    if(!names.empty() && names.size() != number_of_training_shapes())
      throw Invalid_argument("shape model: " + std::to_string(names.size()) + " names for " + std::to_string(number_of_training_shapes()) + " training shapes");
    m_names = std::move(names);
  }

  /// The shape μ + Σ_i c_i √λ_i v_i for the coefficients c (standard deviations; fewer than k: the
  /// others are 0).
  /// \throws Invalid_argument for more than k coefficients or a non-finite one
  Eigen::VectorXd instance(const Eigen::VectorXd& coefficients) const {
    const Eigen::Index m = coefficients.size();
    if(m > m_variances.size())
      throw Invalid_argument("shape model: " + std::to_string(m) + " coefficients for a model of " + std::to_string(number_of_modes()) + " modes");
    if(!coefficients.allFinite()) throw Invalid_argument("shape model: a coefficient is not finite");
    return m_mean + m_modes.leftCols(m) * (m_variances.head(m).cwiseSqrt().cwiseProduct(coefficients));
  }

  /// Training shape i, Procrustes-aligned (the model's frame), from its scores: exact when the model
  /// keeps every mode of its training data.
  /// \pre i < number_of_training_shapes()
  Eigen::VectorXd training_shape(std::size_t i) const {
    if(i >= number_of_training_shapes())
      throw Invalid_argument("shape model: training shape " + std::to_string(i) + " of " + std::to_string(number_of_training_shapes()));
    return instance(m_scores.col(static_cast<Eigen::Index>(i)));
  }

  /// Whether the kept modes hold all the training variance (to 1e-9): then `training_shape()` gives
  /// the training shapes themselves, and the leave-one-out measures can run.
  bool keeps_all_variance() const { return m_variances.sum() >= (1 - 1e-9) * m_total; }

  /// The coefficients of `shape` (3n, in any pose): the shape is first moved onto the mean by the
  /// best rigid motion (a similarity if the model has scale), then c_i = v_iᵀ(x − μ)/√λ_i.
  /// \throws Invalid_argument when the shape has another number of points or a non-finite coordinate
  Shape_model_projection project(const Eigen::VectorXd& shape) const {
    check_shape(shape, "project");
    const Eigen::Index n = static_cast<Eigen::Index>(number_of_vertices());
    const Eigen::Map<const Eigen::Matrix3Xd> x(shape.data(), 3, n), mu(m_mean.data(), 3, n);
    Shape_model_projection p;
    p.to_model = internal::procrustes_fit(x, mu, m_scale);
    const Eigen::Matrix3Xd aligned = internal::transformed(p.to_model, x);
    p.coefficients = (m_modes.transpose() * (Eigen::Map<const Eigen::VectorXd>(aligned.data(), 3 * n) - m_mean)).cwiseQuotient(m_variances.cwiseSqrt());
    return p;
  }

  /// `shape` as the model sees it with the first `k` modes (all: k ≥ number_of_modes()): projected,
  /// rebuilt from k coefficients, and moved back into the shape's own frame.
  Eigen::VectorXd reconstruct(const Eigen::VectorXd& shape, std::size_t k) const {
    const Shape_model_projection p = project(shape);
    const Eigen::Index m = static_cast<Eigen::Index>(std::min(k, number_of_modes()));
    const Eigen::VectorXd y = instance(p.coefficients.head(m));
    const Eigen::Index n = static_cast<Eigen::Index>(number_of_vertices());
    const Eigen::Matrix3Xd back = internal::transformed(p.to_model.inverse(), Eigen::Map<const Eigen::Matrix3Xd>(y.data(), 3, n));
    return Eigen::Map<const Eigen::VectorXd>(back.data(), 3 * n);
  }

  /// Writes the model to a binary file, format version 1 (native byte order, marked): "SCSSM001",
  /// the byte-order mark 0x01020304, n, the number of triangles, k, N, flags (1: scale), the total
  /// variance, μ, λ, the modes (column-major), the scores (column-major), the triangles (64-bit
  /// indices), N names (64-bit length, bytes), and the 64-bit FNV-1a checksum of everything before.
  /// Doubles throughout: a loaded model equals the saved one exactly.
  /// \throws Output_error when the file cannot be written
  void save(const std::string& path) const {
    internal::Checked_binary_writer out(path, "SCSSM001", "shape model");
    const std::uint64_t n = number_of_vertices(), k = number_of_modes(), N = number_of_training_shapes();
    out.put_u64(n);
    out.put_u64(m_triangles.size());
    out.put_u64(k);
    out.put_u64(N);
    out.put_u64(m_scale ? 1 : 0);
    out.put_double(m_total);
    out.put(m_mean.data(), sizeof(double) * 3 * n);
    out.put(m_variances.data(), sizeof(double) * k);
    out.put(m_modes.data(), sizeof(double) * 3 * n * k);
    out.put(m_scores.data(), sizeof(double) * k * N);
    for(const auto& t : m_triangles)
      for(std::size_t c : t) out.put_u64(c);
    for(std::size_t i = 0; i < N; ++i) {
      const std::string name = i < m_names.size() ? m_names[i] : std::string();
      out.put_u64(name.size());
      out.put(name.data(), name.size());
    }
    out.finish();
  }

  /// Reads a model written by `save()` and checks it: kind and version, byte order, every size
  /// against the bytes left in the file (before allocating), the checksum, and the values (see the
  /// constructor).
  /// \throws Invalid_input (`unreadable_file`) naming the file and the first problem found
  static Statistical_shape_model load(const std::string& path) {
    internal::Checked_binary_reader in(path, "SCSSM001", 5, "shape model");
    if(in.version(5) != "001") in.fail("format version '" + in.version(5) + "' (this build reads version 001)");
    const std::uint64_t n = in.get_u64(), m = in.get_u64(), k = in.get_u64(), N = in.get_u64(), flags = in.get_u64();
    const double total = in.get_double();
    if(n == 0 || m == 0) in.fail("no vertices or no triangles");
    if(flags > 1) in.fail("unknown flags " + std::to_string(flags));
    in.require(n, 3 * sizeof(double), "vertices");
    in.require(m, 3 * sizeof(std::uint64_t), "triangles");
    in.require(k, sizeof(double), "variances");
    if(k > 0) in.require(3 * n, k * sizeof(double), "mode entries");
    if(k > 0) in.require(N, k * sizeof(double), "score columns");
    in.require(N, sizeof(std::uint64_t), "names");
    const Eigen::Index ni = static_cast<Eigen::Index>(n), ki = static_cast<Eigen::Index>(k), Ni = static_cast<Eigen::Index>(N);
    Eigen::VectorXd mean(3 * ni), variances(ki);
    in.get(mean.data(), sizeof(double) * 3 * n);
    in.get(variances.data(), sizeof(double) * k);
    Eigen::MatrixXd modes(3 * ni, ki), scores(ki, Ni);
    in.get(modes.data(), sizeof(double) * 3 * n * k);
    in.get(scores.data(), sizeof(double) * k * N);
    std::vector<std::array<std::size_t, 3>> triangles(m);
    for(auto& t : triangles)
      for(std::size_t& c : t) c = static_cast<std::size_t>(in.get_u64());
    std::vector<std::string> names(N);
    for(auto& name : names) {
      const std::uint64_t length = in.get_u64();
      in.require(length, 1, "name bytes");
      name.resize(length);
      in.get(&name[0], length);
    }
    in.finish();
    try {
      Statistical_shape_model model(std::move(mean), std::move(modes), std::move(variances), total, std::move(triangles), std::move(scores), flags == 1);
      if(std::any_of(names.begin(), names.end(), [](const std::string& s) { return !s.empty(); })) model.set_training_names(std::move(names));
      return model;
    } catch(const Invalid_argument& e) {
      in.fail(e.what());
    }
  }

private:
  void check() const {
    const Eigen::Index k = m_variances.size();
    if(m_mean.size() == 0 || m_mean.size() % 3 != 0) throw Invalid_argument("shape model: the mean must have 3n > 0 entries, it has " + std::to_string(m_mean.size()));
    if(m_modes.rows() != m_mean.size() || m_modes.cols() != k)
      throw Invalid_argument("shape model: the modes are " + std::to_string(m_modes.rows()) + " x " + std::to_string(m_modes.cols()) + ", expected " +
                             std::to_string(m_mean.size()) + " x " + std::to_string(k));
    if(m_scores.size() != 0 && m_scores.rows() != k) throw Invalid_argument("shape model: the scores must have one row per mode");
    if(!m_mean.allFinite() || !m_modes.allFinite() || !m_scores.allFinite()) throw Invalid_argument("shape model: a non-finite value");
    for(Eigen::Index i = 0; i < k; ++i) {
      if(!(std::isfinite(m_variances[i]) && m_variances[i] > 0)) throw Invalid_argument("shape model: variance " + std::to_string(i) + " is not a positive number");
      if(i > 0 && m_variances[i] > m_variances[i - 1] * (1 + 1e-12)) throw Invalid_argument("shape model: variances not descending at " + std::to_string(i));
    }
    if(!(std::isfinite(m_total) && m_total >= m_variances.sum() * (1 - 1e-9)))
      throw Invalid_argument("shape model: the total variance is smaller than the sum of the modes' variances");
    if(k > 0 && !(m_modes.transpose() * m_modes).isIdentity(1e-6)) throw Invalid_argument("shape model: the modes are not orthonormal");
    const std::size_t n = number_of_vertices();
    for(std::size_t f = 0; f < m_triangles.size(); ++f)
      for(std::size_t c : m_triangles[f])
        if(c >= n) throw Invalid_argument("shape model: triangle " + std::to_string(f) + " refers to vertex " + std::to_string(c) + " of " + std::to_string(n));
  }
  void check_shape(const Eigen::VectorXd& shape, const char* what) const {
    if(shape.size() != m_mean.size())
      throw Invalid_argument(std::string("shape model: ") + what + ": a shape of " + std::to_string(shape.size() / 3) + " points for a model of " +
                             std::to_string(number_of_vertices()));
    if(!shape.allFinite()) throw Invalid_argument(std::string("shape model: ") + what + ": the shape has a non-finite coordinate");
  }

  Eigen::VectorXd m_mean;
  Eigen::MatrixXd m_modes;
  Eigen::VectorXd m_variances;
  double m_total = 0;
  std::vector<std::array<std::size_t, 3>> m_triangles;
  Eigen::MatrixXd m_scores;
  bool m_scale = false;
  std::vector<std::string> m_names;
};

/// \ingroup PkgShapeCorrShapeModel
/// A statistical shape model of shapes in correspondence (3 × n each, the same n points) sharing
/// the connectivity `triangles`: generalized Procrustes alignment (`with_scale`: similarities,
/// else rigid motions), the mean, and the principal components of the aligned shapes
/// (`principal_components()` through the Gram matrix); the scores of every training shape are kept.
/// \throws Invalid_argument for fewer than two shapes, shapes of different sizes or non-finite
///         coordinates (see `generalized_procrustes_alignment()`)
inline Statistical_shape_model build_statistical_shape_model(const std::vector<Eigen::Matrix3Xd>& shapes, std::vector<std::array<std::size_t, 3>> triangles,
                                                             bool with_scale = false, Pca_method method = Pca_method::GRAM_MATRIX) {
  const Procrustes_alignment gpa = generalized_procrustes_alignment(shapes, with_scale);
  const Eigen::Index n3 = 3 * gpa.mean.cols(), N = static_cast<Eigen::Index>(shapes.size());
  Eigen::MatrixXd D(n3, N);
  for(Eigen::Index i = 0; i < N; ++i) D.col(i) = Eigen::Map<const Eigen::VectorXd>(gpa.aligned[static_cast<std::size_t>(i)].data(), n3);
  const Eigen::VectorXd mean = D.rowwise().mean(); // the aligned shapes' own mean: their scores sum to 0
  D.colwise() -= mean;
  // what the Procrustes tolerance (1e-10 of the size) leaves is round-off, not variation
  const double negligible = 1e-18 * (gpa.mean.colwise() - gpa.mean.rowwise().mean()).squaredNorm();
  const Principal_components pc = principal_components(D, method, negligible);
  Eigen::MatrixXd scores = pc.variances.cwiseSqrt().cwiseInverse().asDiagonal() * (pc.modes.transpose() * D);
  return Statistical_shape_model(mean, pc.modes, pc.variances, pc.total_variance, std::move(triangles), std::move(scores), with_scale);
}

/// \ingroup PkgShapeCorrShapeModel
/// A statistical shape model of meshes in correspondence: every mesh has the vertices and faces of
/// the first (one template fitted to every specimen, e.g. by `fit_template()`), its vertex i being
/// the same anatomical point in each. The model's triangles are the first mesh's faces.
/// \tparam MeshRange a range of a model of `FaceListGraph` with triangle faces
/// \param meshes the training meshes, at least two
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `allow_scaling` | Procrustes alignment with a uniform scale (similarities) | `bool` | `false` |
/// | `vertex_point_map` | positions (the same map type for every mesh) | `ReadablePropertyMap<vertex_descriptor, Point_3>` | each mesh's own |
/// | `vertex_index_map` | vertex order (point i of every shape) | `ReadablePropertyMap<vertex_descriptor, size_t>` | each mesh's own, or a fresh one |
/// \throws Invalid_input for a mesh with a non-triangle face or a non-finite coordinate;
///         Invalid_argument for fewer than two meshes, or meshes that do not share the first one's
///         vertices and faces
/// \code
///   std::vector<Mesh> fits = ...;   // one template fitted to each specimen
///   const shapecorr::Statistical_shape_model model = shapecorr::build_statistical_shape_model(fits);
///   std::cout << model.explained_variance_ratios().head(3).transpose() << "\n";
/// \endcode
template <typename MeshRange, typename NamedParameters = parameters::Default_named_parameters>
Statistical_shape_model build_statistical_shape_model(const MeshRange& meshes, const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename std::decay<decltype(*std::begin(meshes))>::type TriangleMesh;
  const bool with_scale = choose_parameter(get_parameter(np, internal_np::allow_scaling), false);
  std::vector<Eigen::Matrix3Xd> shapes;
  std::vector<std::array<std::size_t, 3>> triangles;
  Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> faces;
  std::size_t i = 0;
  for(const TriangleMesh& tm : meshes) {
    const internal::Triangle_arrays a = internal::finite_triangle_arrays(tm, np, "shape model", "mesh " + std::to_string(i));
    if(i == 0) {
      faces = a.F;
      for(Eigen::Index f = 0; f < a.F.rows(); ++f)
        triangles.push_back({static_cast<std::size_t>(a.F(f, 0)), static_cast<std::size_t>(a.F(f, 1)), static_cast<std::size_t>(a.F(f, 2))});
    } else if(a.V.rows() != shapes[0].cols() || a.F != faces) {
      throw Invalid_argument("shape model: mesh " + std::to_string(i) + " (" + std::to_string(a.V.rows()) + " vertices, " + std::to_string(a.F.rows()) +
                             " faces) does not have the vertices and faces of mesh 0 (" + std::to_string(shapes[0].cols()) + ", " +
                             std::to_string(faces.rows()) + "): fit one template to every specimen first");
    }
    shapes.push_back(a.V.transpose());
    ++i;
  }
  return build_statistical_shape_model(shapes, std::move(triangles), with_scale);
}

/// \ingroup PkgShapeCorrShapeModel
/// Builds `tm` (cleared first) as the mesh of `shape` (3n, interleaved, e.g. `model.instance(c)`)
/// with the model's triangles: vertex i of `tm` is point i.
/// \tparam TriangleMesh a model of `MutableFaceGraph`
/// \throws Invalid_argument when `shape` has another number of points than the model
template <typename TriangleMesh>
void make_shape_mesh(const Statistical_shape_model& model, const Eigen::VectorXd& shape, TriangleMesh& tm) {
  if(static_cast<std::size_t>(shape.size()) != 3 * model.number_of_vertices())
    throw Invalid_argument("make_shape_mesh: a shape of " + std::to_string(shape.size() / 3) + " points for a model of " + std::to_string(model.number_of_vertices()));
  std::vector<std::array<double, 3>> points(model.number_of_vertices());
  for(std::size_t i = 0; i < points.size(); ++i) points[i] = {shape[3 * i], shape[3 * i + 1], shape[3 * i + 2]};
  internal::soup_to_mesh(points, model.triangles(), tm);
}

} // namespace shapecorr

#endif
