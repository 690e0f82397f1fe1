// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file average_geodesic_distance.h
/// Average geodesic distance, global and local (thesis, chapter 4).
#ifndef SHAPECORR_GEODESICS_AVERAGE_GEODESIC_DISTANCE_H
#define SHAPECORR_GEODESICS_AVERAGE_GEODESIC_DISTANCE_H

#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/geodesics/with_geodesic_engine.h>
#include <shapecorr/internal/furthest_point_order.h>
#include <shapecorr/parallel.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <numeric>
#include <vector>

namespace shapecorr {
namespace internal {

/// A(X): total area of the triangles incident to each vertex.
inline Eigen::VectorXd incident_triangle_areas(const Triangle_arrays& a) {
  Eigen::VectorXd A = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(a.number_of_vertices()));
  for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
    const Eigen::Vector3d p = a.V.row(a.F(f, 0)), q = a.V.row(a.F(f, 1)), r = a.V.row(a.F(f, 2));
    const double area = 0.5 * (q - p).cross(r - p).norm();
    for(int k = 0; k < 3; ++k) A[a.F(f, k)] += area;
  }
  return A;
}

/// Global agd of every vertex from the distance fields of its sources (row s of `D`: distances
/// from source s), weighted by the area of each source's geodesic Voronoi cell, or by A(X) itself
/// when every vertex is a source (D square).
inline Eigen::VectorXd global_agd(const Eigen::VectorXd& A,
                                  const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& D,
                                  const std::vector<std::size_t>& sources) {
  const std::size_t n = static_cast<std::size_t>(D.cols()), k = static_cast<std::size_t>(D.rows());
  Eigen::VectorXd w(static_cast<Eigen::Index>(k));
  if(k == n) {
    for(std::size_t s = 0; s < k; ++s) w[static_cast<Eigen::Index>(s)] = A[static_cast<Eigen::Index>(sources[s])];
  } else {
    w.setZero();
    for(std::size_t v = 0; v < n; ++v) {
      Eigen::Index arg;
      D.col(static_cast<Eigen::Index>(v)).minCoeff(&arg);
      w[arg] += A[static_cast<Eigen::Index>(v)];
    }
  }
  // per vertex, average over the sources it can reach (several components: its own component's)
  Eigen::VectorXd num = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n)), den = num;
  for(std::size_t s = 0; s < k; ++s) {
    const double ws = w[static_cast<Eigen::Index>(s)];
    if(ws <= 0) continue;
    for(std::size_t v = 0; v < n; ++v) {
      const float d = D(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(v));
      if(std::isfinite(d)) { num[static_cast<Eigen::Index>(v)] += ws * d; den[static_cast<Eigen::Index>(v)] += ws; }
    }
  }
  Eigen::VectorXd agd(static_cast<Eigen::Index>(n));
  for(Eigen::Index v = 0; v < agd.size(); ++v)
    agd[v] = den[v] > 0 ? num[v] / den[v] : std::numeric_limits<double>::quiet_NaN();
  return agd;
}

/// Local agd of every vertex (radius-limited fast marching from each, in parallel).
template <typename TriangleMesh>
std::vector<double> local_average_geodesic_distances(const Fast_marching_geodesics<TriangleMesh>& engine, double radius,
                                                     const std::function<void(std::size_t, std::size_t)>& progress) {
  const std::size_t n = engine.number_of_vertices();
  const Eigen::VectorXd A = incident_triangle_areas(engine.arrays());
  std::vector<double> agd(n, 0.0);
  const unsigned threads = engine.number_of_threads();
  std::vector<typename Fast_marching_geodesics<TriangleMesh>::Workspace> ws(threads);
  std::vector<typename Fast_marching_geodesics<TriangleMesh>::Ball> balls(threads);
  const std::size_t chunk = 64;
  std::mutex mtx;
  std::size_t done = 0;
  parallel_for((n + chunk - 1) / chunk, threads, [&](std::size_t c, unsigned tid) {
    for(std::size_t q = c * chunk; q < std::min(n, (c + 1) * chunk); ++q) {
      engine.distances_within(q, radius, balls[tid], ws[tid]);
      double num = 0, den = 0;
      for(const auto& p : balls[tid]) {
        if(p.second >= radius) continue;
        num += A[static_cast<Eigen::Index>(p.first)] * p.second;
        den += A[static_cast<Eigen::Index>(p.first)];
      }
      agd[q] = den > 0 ? num / den : 0.0;
    }
    if(progress) {
      std::lock_guard<std::mutex> lock(mtx);
      done = std::min(n, done + chunk);
      progress(done, n);
    }
  });
  return agd;
}

} // namespace internal

/// \ingroup PkgShapeCorrGeodesics
/// Global average geodesic distance `agd(Q) = sum_X A(X) gd(Q,X) / sum_X A(X)` for every vertex Q
/// (thesis, chapter 4), A(X) the area of the triangles incident to X. With `number_of_sources(k)`
/// the sum runs over k furthest-point samples X, each weighted by the area of its geodesic Voronoi
/// cell; `number_of_sources(0)` (or k >= n) uses every vertex (n single-source queries, batched).
/// \tparam VertexAgdMap a `WritablePropertyMap<vertex_descriptor, double>`
/// \param np `number_of_sources` (default 100), `random_seed`, `geodesic_method`,
///        `geodesic_engine`, `progress_callback`, and the engine's parameters.
/// Several components: each vertex averages over the sources of its own component (furthest
/// point sampling reaches every component once k is at least their number; a vertex whose
/// component holds no source gets NaN). \sa `compute_local_average_geodesic_distance()`
template <typename TriangleMesh, typename VertexAgdMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_average_geodesic_distance(const TriangleMesh& tm, VertexAgdMap agd_map,
                                       const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  std::size_t k = choose_parameter(get_parameter(np, internal_np::number_of_sources), std::size_t(100));
  const unsigned seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const auto progress = internal::progress_of(np);
  with_geodesic_engine(tm, np, [&](const auto& engine) {
    const std::size_t n = engine.number_of_vertices();
    // distances from each source to every vertex, row s = from sources[s] (float: k x n x 4 bytes)
    Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> D;
    std::vector<std::size_t> sources;
    if(k == 0 || k >= n) {
      sources.resize(n);
      std::iota(sources.begin(), sources.end(), std::size_t(0));
      D.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
      engine.for_each_batch(sources, [&](std::size_t first, std::size_t count, const Eigen::MatrixXd& block) {
        D.block(static_cast<Eigen::Index>(first), 0, static_cast<Eigen::Index>(count), static_cast<Eigen::Index>(n)) =
            block.transpose().cast<float>();
      }, progress);
    } else {
      // the sampling computes each sample's distance field: keep them instead of computing them again
      std::vector<Eigen::VectorXf> fields;
      sources = internal::furthest_point_sampling_indices(n, k, internal::seeded_start_vertex(seed, n), false, [&](std::size_t s) {
        Eigen::VectorXd d = engine.distances_from(s);
        fields.push_back(d.cast<float>());
        if(progress) progress(fields.size(), k + 1);
        return d;
      });
      const std::size_t dropped = fields.size() - sources.size(); // the thesis drops the arbitrary start
      D.resize(static_cast<Eigen::Index>(sources.size()), static_cast<Eigen::Index>(n));
      for(std::size_t s = 0; s < sources.size(); ++s) D.row(static_cast<Eigen::Index>(s)) = fields[s + dropped].transpose();
    }
    const Eigen::VectorXd agd = internal::global_agd(internal::incident_triangle_areas(engine.arrays()), D, sources);
    for(std::size_t i = 0; i < n; ++i) put(agd_map, engine.vertex(i), agd[static_cast<Eigen::Index>(i)]);
    return 0;
  });
}

/// \ingroup PkgShapeCorrGeodesics
/// Local average geodesic distance with radius r (thesis, chapter 4):
/// `agd_r(Q) = sum_{X: gd(Q,X) < r} A(X) gd(Q,X) / sum_{X: gd(Q,X) < r} A(X)` for every vertex Q,
/// with radius-limited fast marching (cost per vertex proportional to its geodesic ball), in
/// parallel. Depends only on the r-neighbourhood of Q, hence usable on partial shapes.
/// \param radius r in mesh units (the thesis gives it as a fraction of the diameter D:
///        pass `fraction * geodesic_diameter(tm)`)
/// \param np `vertex_point_map`, `vertex_index_map`, `number_of_threads`, `progress_callback`
template <typename TriangleMesh, typename VertexAgdMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_local_average_geodesic_distance(const TriangleMesh& tm, double radius, VertexAgdMap agd_map,
                                             const NamedParameters& np = CGAL::parameters::default_values()) {
  if(!(radius > 0))
    throw Invalid_argument("local average geodesic distance: the radius must be positive");
  Fast_marching_geodesics<TriangleMesh> engine(tm, np);
  const std::vector<double> agd = internal::local_average_geodesic_distances(engine, radius, internal::progress_of(np));
  const std::size_t n = engine.number_of_vertices();
  for(std::size_t i = 0; i < n; ++i) put(agd_map, engine.vertex(i), agd[i]);
}

} // namespace shapecorr

#endif
