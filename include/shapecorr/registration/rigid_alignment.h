// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file rigid_alignment.h
/// Rigid (optionally similarity) alignment of a source mesh to a target mesh, the pre-alignment of
/// every non-rigid method (ALGORITHMS.md, chapter 6: "roughly aligned (rigid ICP first)"): an
/// initialization from landmark pairs, from principal axes, or none; then trimmed ICP.
#ifndef SHAPECORR_REGISTRATION_RIGID_ALIGNMENT_H
#define SHAPECORR_REGISTRATION_RIGID_ALIGNMENT_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/closest_point_tree.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/parallel.h>
#include <shapecorr/parameters.h>
#include <shapecorr/registration/registration_report.h>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrRegistration
/// x ↦ scale · rotation · x + translation (scale 1: a rigid motion).
struct Similarity_transform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); ///< proper rotation (determinant +1)
  double scale = 1.0;                                     ///< uniform scale, positive
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  ///< applied last
  /// The image of a point.
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return scale * (rotation * x) + translation; }
  /// This transform after `first`: x ↦ (*this)(first(x)).
  Similarity_transform after(const Similarity_transform& first) const {
    Similarity_transform c;
    c.rotation = rotation * first.rotation;
    c.scale = scale * first.scale;
    c.translation = scale * (rotation * first.translation) + translation;
    return c;
  }
  /// The inverse transform.
  Similarity_transform inverse() const {
    Similarity_transform i;
    i.rotation = rotation.transpose();
    i.scale = 1.0 / scale;
    i.translation = -(i.scale * (i.rotation * translation));
    return i;
  }
  /// The 4 × 4 homogeneous matrix.
  Eigen::Matrix4d matrix() const {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = scale * rotation;
    m.topRightCorner<3, 1>() = translation;
    return m;
  }
};

/// \ingroup PkgShapeCorrRegistration
/// Where rigid alignment starts (named parameter `rigid_initialization`).
enum class Rigid_initialization {
  NONE,           ///< the identity: the meshes are roughly aligned already
  LANDMARKS,      ///< least squares over landmark pairs (`landmark_points` in both packs)
  PRINCIPAL_AXES  ///< centroids and principal axes matched, every proper sign choice (and axis swap) tried
};

/// \ingroup PkgShapeCorrRegistration
/// The distance ICP minimizes (named parameter `icp_metric`).
enum class Icp_metric {
  POINT_TO_PLANE, ///< distance to the tangent plane of the target at the closest point (fast convergence)
  POINT_TO_POINT  ///< distance to the closest point (closed form per step; robust from far)
};

/// \ingroup PkgShapeCorrRegistration
/// The result of `align_rigidly()`.
struct Rigid_alignment_report {
  Similarity_transform transform;           ///< source ↦ target
  Rigid_initialization initialization = Rigid_initialization::NONE; ///< how it started
  std::size_t starts_tried = 1;             ///< ICP runs (principal axes: one per sign choice and swap)
  std::size_t winning_start = 0;            ///< the start whose ICP ended with the smallest residual
  double initial_rms = 0;                   ///< trimmed RMS distance after the initialization (winning start)
  double final_rms = 0;                     ///< trimmed RMS distance at the end
  std::vector<Iteration_record> iterations; ///< ICP of the winning start (energy: trimmed RMS distance of the metric)
  Stop_reason stop = Stop_reason::CONVERGED; ///< why the winning ICP stopped
  double seconds = 0;                       ///< wall time
};

namespace internal {

/// Source samples of ICP: vertex positions and area-weighted vertex normals, at most `count`
/// (every k-th vertex).
struct Icp_samples {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<double> areas; // vertex areas (a third of the incident triangles'): PCA weights
};

inline Eigen::Vector3d triangle_normal(const Triangle_arrays& a, std::size_t f) {
  const Eigen::Index fi = static_cast<Eigen::Index>(f);
  const Eigen::Vector3d p = a.point(static_cast<std::size_t>(a.F(fi, 0))), q = a.point(static_cast<std::size_t>(a.F(fi, 1))),
                        r = a.point(static_cast<std::size_t>(a.F(fi, 2)));
  const Eigen::Vector3d n = (q - p).cross(r - p);
  const double l = n.norm();
  return l > 0 ? Eigen::Vector3d(n / l) : Eigen::Vector3d::Zero();
}

inline Icp_samples icp_samples(const Triangle_arrays& a, std::size_t count) {
  const std::size_t n = a.number_of_vertices();
  std::vector<Eigen::Vector3d> normal(n, Eigen::Vector3d::Zero());
  std::vector<double> area(n, 0.0);
  for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
    const Eigen::Vector3d p = a.point(static_cast<std::size_t>(a.F(f, 0))), q = a.point(static_cast<std::size_t>(a.F(f, 1))),
                          r = a.point(static_cast<std::size_t>(a.F(f, 2)));
    const Eigen::Vector3d w = (q - p).cross(r - p); // twice the area times the unit normal
    for(int k = 0; k < 3; ++k) {
      normal[static_cast<std::size_t>(a.F(f, k))] += w;
      area[static_cast<std::size_t>(a.F(f, k))] += w.norm() / 6.0;
    }
  }
  Icp_samples s;
  const std::size_t stride = count == 0 || n <= count ? 1 : (n + count - 1) / count;
  for(std::size_t i = 0; i < n; i += stride) {
    if(!(area[i] > 0)) continue; // isolated vertex
    s.points.push_back(a.point(i));
    s.normals.push_back(normal[i].normalized());
    s.areas.push_back(area[i]);
  }
  return s;
}

/// argmin over s, R, t of Σ w_i |s R x_i + t − y_i|² (Umeyama 1991; s = 1 unless `with_scale`).
inline Similarity_transform fit_similarity(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& y,
                                           const std::vector<double>& w, bool with_scale) {
  double W = 0;
  Eigen::Vector3d mx = Eigen::Vector3d::Zero(), my = Eigen::Vector3d::Zero();
  for(std::size_t i = 0; i < x.size(); ++i) {
    W += w[i];
    mx += w[i] * x[i];
    my += w[i] * y[i];
  }
  mx /= W;
  my /= W;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  double vx = 0;
  for(std::size_t i = 0; i < x.size(); ++i) {
    C += w[i] * (y[i] - my) * (x[i] - mx).transpose();
    vx += w[i] * (x[i] - mx).squaredNorm();
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(C, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if(svd.matrixU().determinant() * svd.matrixV().determinant() < 0) S(2, 2) = -1;
  Similarity_transform T;
  T.rotation = svd.matrixU() * S * svd.matrixV().transpose();
  T.scale = with_scale && vx > 0 ? (svd.singularValues().asDiagonal() * S).trace() / vx : 1.0;
  if(!(T.scale > 0)) T.scale = 1.0;
  T.translation = my - T.scale * (T.rotation * mx);
  return T;
}

/// The rotation of a rotation vector (Rodrigues).
inline Eigen::Matrix3d rotation_of(const Eigen::Vector3d& w) {
  const double a = w.norm();
  return a > 0 ? Eigen::AngleAxisd(a, w / a).toRotationMatrix() : Eigen::Matrix3d::Identity();
}

struct Icp_options {
  Icp_metric metric = Icp_metric::POINT_TO_PLANE;
  bool with_scale = false;
  double trimming = 0.9;         // fraction of the compatible pairs kept (the closest)
  double cos_normal_angle = 0.5; // pairs whose normals differ by more than the angle are rejected
  std::size_t iterations = 50;
  unsigned threads = 0;
};

struct Icp_run {
  Similarity_transform transform;
  std::vector<Iteration_record> iterations;
  Stop_reason stop = Stop_reason::ITERATION_LIMIT;
  double initial_rms = 0, final_rms = 0;
};

/// Trimmed ICP of the samples onto the tree's triangles from `start`. Each iteration: closest
/// points, pairs with incompatible normals rejected, the closest `trimming` fraction kept, one
/// least-squares update (closed form for point-to-point; linearized rotation for point-to-plane).
/// Stops when the trimmed RMS changes by less than 1e-7 relative (converged), when the update moves
/// no sample by more than 1e-9 of the source's size (no motion), with fewer than 7 pairs, or at the
/// iteration limit.
inline Icp_run run_icp(const Icp_samples& src, const Triangle_arrays& target, const Closest_point_tree& tree, const Similarity_transform& start,
                       const Icp_options& o) {
  Icp_run run;
  run.transform = start;
  const std::size_t n = src.points.size();
  double extent = 0;
  for(const auto& p : src.points) extent = std::max(extent, (p - src.points.front()).norm());
  if(!(extent > 0)) extent = 1.0;
  struct Pair {
    Eigen::Vector3d q, c, normal;
    double distance = 0;
    bool ok = false;
  };
  std::vector<Pair> pairs(n);
  double previous_rms = -1;
  for(std::size_t it = 0; it < o.iterations; ++it) {
    const Similarity_transform& T = run.transform;
    parallel_for(n, o.threads, [&](std::size_t i, unsigned) {
      Pair& p = pairs[i];
      p.q = T(src.points[i]);
      const Closest_point c = tree.closest(p.q);
      p.c = c.point;
      p.normal = triangle_normal(target, c.triangle);
      p.distance = c.distance;
      p.ok = (T.rotation * src.normals[i]).dot(p.normal) >= o.cos_normal_angle;
    });
    std::vector<const Pair*> kept;
    for(const Pair& p : pairs)
      if(p.ok) kept.push_back(&p);
    std::sort(kept.begin(), kept.end(), [](const Pair* a, const Pair* b) { return a->distance < b->distance; });
    kept.resize(static_cast<std::size_t>(std::ceil(o.trimming * static_cast<double>(kept.size()))));
    Iteration_record rec;
    rec.iteration = it;
    rec.pairs = kept.size();
    if(kept.size() < 7) {
      run.stop = Stop_reason::TOO_FEW_PAIRS;
      run.iterations.push_back(rec);
      break;
    }
    double sum2 = 0, energy = 0;
    for(const Pair* p : kept) {
      sum2 += p->distance * p->distance;
      const double e = o.metric == Icp_metric::POINT_TO_PLANE ? p->normal.dot(p->q - p->c) : p->distance;
      energy += e * e;
    }
    rec.rms_distance = std::sqrt(sum2 / static_cast<double>(kept.size()));
    rec.energy = std::sqrt(energy / static_cast<double>(kept.size()));
    if(it == 0) run.initial_rms = rec.rms_distance;
    run.final_rms = rec.rms_distance;

    // the update, a similarity U applied after T
    Similarity_transform U;
    if(o.metric == Icp_metric::POINT_TO_POINT) {
      std::vector<Eigen::Vector3d> x, y;
      for(const Pair* p : kept) {
        x.push_back(p->q);
        y.push_back(p->c);
      }
      U = fit_similarity(x, y, std::vector<double>(x.size(), 1.0), o.with_scale);
    } else {
      // minimize Σ (n · ((1 + δ)(I + [ω]×)(q − m) + m + τ − c))²: unknowns ω, τ (and δ), about the centroid m
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for(const Pair* p : kept) m += p->q;
      m /= static_cast<double>(kept.size());
      const int k = o.with_scale ? 7 : 6;
      Eigen::MatrixXd A = Eigen::MatrixXd::Zero(k, k);
      Eigen::VectorXd b = Eigen::VectorXd::Zero(k);
      Eigen::VectorXd J(k);
      for(const Pair* p : kept) {
        const Eigen::Vector3d r = p->q - m;
        J.head<3>() = r.cross(p->normal);
        J.segment<3>(3) = p->normal;
        if(o.with_scale) J(6) = p->normal.dot(r);
        const double e = p->normal.dot(p->q - p->c);
        A.noalias() += J * J.transpose();
        b.noalias() -= J * e;
      }
      const Eigen::VectorXd x = A.ldlt().solve(b);
      if(!x.allFinite()) {
        run.stop = Stop_reason::TOO_FEW_PAIRS; // degenerate: e.g. all pairs on one plane
        run.iterations.push_back(rec);
        break;
      }
      const Eigen::Matrix3d R = rotation_of(x.head<3>());
      const double s = o.with_scale ? std::max(0.5, std::min(2.0, 1.0 + x(6))) : 1.0;
      U.rotation = R;
      U.scale = s;
      U.translation = m + x.segment<3>(3) - s * (R * m);
    }
    // the update's largest displacement of a sample (an upper bound over the kept pairs' hull)
    double step = 0;
    for(const Pair* p : kept) step = std::max(step, (U(p->q) - p->q).norm());
    rec.step = step;
    run.iterations.push_back(rec);
    run.transform = U.after(run.transform);
    if(step <= 1e-9 * extent) {
      run.stop = Stop_reason::NO_MOTION;
      break;
    }
    if(previous_rms >= 0 && std::abs(previous_rms - rec.rms_distance) <= 1e-7 * std::max(rec.rms_distance, 1e-12 * extent)) {
      run.stop = Stop_reason::CONVERGED;
      break;
    }
    previous_rms = rec.rms_distance;
    run.stop = Stop_reason::ITERATION_LIMIT;
  }
  return run;
}

/// Centroid and principal axes (columns, ascending variance) of area-weighted samples.
inline void principal_axes(const Icp_samples& s, Eigen::Vector3d& centroid, Eigen::Matrix3d& axes, Eigen::Vector3d& variances) {
  double W = 0;
  centroid.setZero();
  for(std::size_t i = 0; i < s.points.size(); ++i) {
    W += s.areas[i];
    centroid += s.areas[i] * s.points[i];
  }
  centroid /= W;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < s.points.size(); ++i) C += s.areas[i] * (s.points[i] - centroid) * (s.points[i] - centroid).transpose();
  C /= W;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  axes = es.eigenvectors();
  variances = es.eigenvalues();
  if(axes.determinant() < 0) axes.col(0) *= -1.0;
}

/// The starts of a principal-axes initialization: for every ordering of the source's axes that
/// pairs axes of similar variance (ratio above 0.8), the four proper sign choices.
inline std::vector<Similarity_transform> principal_axes_starts(const Icp_samples& source, const Icp_samples& target, bool with_scale) {
  Eigen::Vector3d ms, mt, vs, vt;
  Eigen::Matrix3d Es, Et;
  principal_axes(source, ms, Es, vs);
  principal_axes(target, mt, Et, vt);
  const double scale = with_scale && vs.sum() > 0 ? std::sqrt(vt.sum() / vs.sum()) : 1.0;
  std::vector<std::array<int, 3>> orders = {{0, 1, 2}};
  auto close = [&](int i, int j) { return std::min(vt(i), vt(j)) > 0.8 * std::max(vt(i), vt(j)); };
  if(close(0, 1)) orders.push_back({1, 0, 2});
  if(close(1, 2)) orders.push_back({0, 2, 1});
  if(close(0, 1) && close(1, 2)) {
    orders.push_back({2, 1, 0});
    orders.push_back({1, 2, 0});
    orders.push_back({2, 0, 1});
  }
  std::vector<Similarity_transform> starts;
  for(const auto& o : orders) {
    Eigen::Matrix3d P;
    for(int k = 0; k < 3; ++k) P.col(k) = Es.col(o[static_cast<std::size_t>(k)]);
    if(P.determinant() < 0) P.col(0) *= -1.0;
    for(const Eigen::Vector3d& sign : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, -1, 1), Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(1, -1, -1)}) {
      Similarity_transform T;
      T.rotation = Et * sign.asDiagonal() * P.transpose();
      T.scale = scale;
      T.translation = mt - scale * (T.rotation * ms);
      starts.push_back(T);
    }
  }
  return starts;
}

template <typename PointRange>
std::vector<Eigen::Vector3d> to_eigen_points(const PointRange& r) {
  std::vector<Eigen::Vector3d> out;
  for(const auto& p : r) out.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  return out;
}

template <typename NamedParameters>
std::vector<Eigen::Vector3d> landmarks_of(const NamedParameters& np, const char* which) {
  using parameters::get_parameter;
  auto given = get_parameter(np, internal_np::landmark_points);
  if constexpr(std::is_same<decltype(given), CGAL::internal_np::Param_not_found>::value) {
    throw Invalid_argument(std::string("align_rigidly: LANDMARKS needs landmark_points in the ") + which + " named parameters");
  } else {
    return to_eigen_points(given);
  }
}

} // namespace internal

/// \ingroup PkgShapeCorrRegistration
/// Aligns `source` to `target` by a rigid motion (or a similarity with `allow_scaling(true)`) and
/// returns it with a report; the meshes are not modified (`apply_transform()` moves one).
///
/// 1. **Initialization** (`rigid_initialization`): `NONE` starts from the identity; `LANDMARKS`
///    from the least-squares similarity of landmark pairs (`landmark_points` in np1 and np2, at
///    least 3, in the same order); `PRINCIPAL_AXES` matches the area-weighted centroids and
///    principal axes, trying the four proper sign choices, and the axis orders that swap axes of
///    similar variance (ratio above 0.8), each followed by ICP: the start with the smallest final
///    residual wins.
/// 2. **Trimmed ICP**: source vertices (at most `number_of_samples`, every k-th) are paired with
///    their closest points on the target; pairs whose normals differ by more than
///    `maximum_normal_angle` are rejected, the closest `trimming_fraction` of the rest are kept;
///    each iteration solves the least-squares update of `icp_metric`. It stops when the trimmed
///    RMS distance changes by less than 1e-7 relative, when an update moves nothing, with fewer
///    than 7 pairs, or after `number_of_iterations` (a report value, not an error).
///
/// `source` and `target` may be of different mesh types; normals follow the faces' orientation
/// (both meshes consistently oriented).
///
/// | named parameter | pack | meaning | type | default |
/// |---|---|---|---|---|
/// | `rigid_initialization` | np1 | where to start | `Rigid_initialization` | `PRINCIPAL_AXES` |
/// | `landmark_points` | np1, np2 | landmark positions (source's, target's) | range of points with `x()`, `y()`, `z()` | none |
/// | `allow_scaling` | np1 | also a uniform scale | `bool` | `false` |
/// | `icp_metric` | np1 | the distance minimized | `Icp_metric` | `POINT_TO_PLANE` |
/// | `trimming_fraction` | np1 | fraction of compatible pairs kept | `double` in (0, 1] | 0.9 |
/// | `maximum_normal_angle` | np1 | largest angle between paired normals (radians) | `double` | π/3 |
/// | `number_of_iterations` | np1 | ICP iterations per start, at most | `std::size_t` | 50 |
/// | `number_of_samples` | np1 | source vertices used, at most | `std::size_t` | 10000 |
/// | `number_of_threads` | np1 | threads of the closest-point queries (0: all) | `unsigned` | 0 |
/// | `vertex_point_map`, `vertex_index_map` | np1, np2 | positions, indices | property maps | the mesh's |
///
/// \throws Invalid_input for a mesh without triangles or with a non-finite coordinate;
///         Invalid_argument for landmarks missing, of different counts, fewer than 3 or
///         degenerate (collinear), or a parameter out of its range
/// \code
///   const shapecorr::Rigid_alignment_report r = shapecorr::align_rigidly(source, target,
///       SP::rigid_initialization(shapecorr::Rigid_initialization::PRINCIPAL_AXES).allow_scaling(true));
///   shapecorr::apply_transform(source, r.transform);   // move the source onto the target
/// \endcode
template <typename SourceMesh, typename TargetMesh, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Rigid_alignment_report align_rigidly(const SourceMesh& source, const TargetMesh& target,
                                     const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                     const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto t0 = std::chrono::steady_clock::now();
  const internal::Triangle_arrays S = internal::finite_triangle_arrays(source, np1, "align_rigidly", "the source"),
                                 T = internal::finite_triangle_arrays(target, np2, "align_rigidly", "the target");
  internal::Icp_options o;
  o.metric = choose_parameter(get_parameter(np1, internal_np::icp_metric), Icp_metric::POINT_TO_PLANE);
  o.with_scale = choose_parameter(get_parameter(np1, internal_np::allow_scaling), false);
  o.trimming = choose_parameter(get_parameter(np1, internal_np::trimming_fraction), 0.9);
  const double angle = choose_parameter(get_parameter(np1, internal_np::maximum_normal_angle), CGAL_PI / 3);
  o.iterations = choose_parameter(get_parameter(np1, CGAL::internal_np::number_of_iterations), std::size_t(50));
  o.threads = choose_parameter(get_parameter(np1, internal_np::number_of_threads), 0u);
  const std::size_t samples = choose_parameter(get_parameter(np1, CGAL::internal_np::number_of_samples), std::size_t(10000));
  if(!(o.trimming > 0 && o.trimming <= 1)) throw Invalid_argument("align_rigidly: trimming_fraction must be in (0, 1]");
  if(!(angle > 0 && angle <= CGAL_PI)) throw Invalid_argument("align_rigidly: maximum_normal_angle must be in (0, pi]");
  if(o.iterations > 100000) throw Invalid_argument("align_rigidly: number_of_iterations above 100000");
  o.cos_normal_angle = std::cos(angle);

  Rigid_alignment_report report;
  report.initialization = choose_parameter(get_parameter(np1, internal_np::rigid_initialization), Rigid_initialization::PRINCIPAL_AXES);
  const internal::Icp_samples src = internal::icp_samples(S, samples);
  std::vector<Similarity_transform> starts;
  if(report.initialization == Rigid_initialization::NONE) {
    starts.emplace_back();
  } else if(report.initialization == Rigid_initialization::LANDMARKS) {
    const std::vector<Eigen::Vector3d> a = internal::landmarks_of(np1, "source (np1)"), b = internal::landmarks_of(np2, "target (np2)");
    if(a.size() != b.size())
      throw Invalid_argument("align_rigidly: " + std::to_string(a.size()) + " source landmarks against " + std::to_string(b.size()) + " target landmarks");
    if(a.size() < 3) throw Invalid_argument("align_rigidly: at least 3 landmark pairs are needed, got " + std::to_string(a.size()));
    for(std::size_t i = 0; i < a.size(); ++i)
      if(!a[i].allFinite() || !b[i].allFinite()) throw Invalid_argument("align_rigidly: landmark " + std::to_string(i) + " has a non-finite coordinate");
    // collinear landmarks leave a rotation about their line free
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for(const auto& p : a) m += p;
    m /= static_cast<double>(a.size());
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for(const auto& p : a) C += (p - m) * (p - m).transpose();
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(C).eigenvalues();
    if(!(ev(1) > 1e-12 * ev(2))) throw Invalid_argument("align_rigidly: the source landmarks are collinear (or coincide)");
    starts.push_back(internal::fit_similarity(a, b, std::vector<double>(a.size(), 1.0), o.with_scale));
  } else {
    starts = internal::principal_axes_starts(src, internal::icp_samples(T, samples), o.with_scale);
  }

  const internal::Closest_point_tree tree(T);
  report.starts_tried = starts.size();
  // the start whose ICP ends with the smallest trimmed residual (runs without enough pairs lose)
  bool have = false, have_usable = false;
  for(std::size_t k = 0; k < starts.size(); ++k) {
    internal::Icp_run run = internal::run_icp(src, T, tree, starts[k], o);
    const bool usable = run.stop != Stop_reason::TOO_FEW_PAIRS;
    if(!have || (usable && (!have_usable || run.final_rms < report.final_rms))) {
      report.transform = run.transform;
      report.winning_start = k;
      report.initial_rms = run.initial_rms;
      report.final_rms = run.final_rms;
      report.iterations = std::move(run.iterations);
      report.stop = run.stop;
      have = true;
      have_usable = have_usable || usable;
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

/// \ingroup PkgShapeCorrRegistration
/// Moves every vertex of `tm` by `transform` (through its vertex point map, `vertex_point_map` in
/// `np`).
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void apply_transform(TriangleMesh& tm, const Similarity_transform& transform, const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), CGAL::get_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    const Eigen::Vector3d q = transform(Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    put(vpm, v, Point(q.x(), q.y(), q.z()));
  }
}

} // namespace shapecorr

#endif
