// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file all_pairs_geodesic_distances.h
#ifndef SHAPECORR_GEODESICS_ALL_PAIRS_GEODESIC_DISTANCES_H
#define SHAPECORR_GEODESICS_ALL_PAIRS_GEODESIC_DISTANCES_H

#include <shapecorr/exceptions.h>
#include <shapecorr/geodesics/with_geodesic_engine.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <type_traits>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrGeodesics
/// A dense, symmetric matrix of geodesic distances between all vertices, stored as `float`
/// (row-major n x n, 4 n^2 bytes: 75 MB for 4.3k vertices, 1.6 GB for 20k). The matrix is exactly
/// symmetric: with the heat method or exact distances entry (i, j) is the average of the distances
/// computed from i and from j; with fast marching it is the one computed from whichever of i, j the
/// sweep reaches first. The diagonal is 0. Unreachable pairs (different components) hold `+infinity`.
class Geodesic_distance_matrix {
public:
  /// Row-major n x n float matrix.
  typedef Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Matrix;
  Geodesic_distance_matrix() = default;
  /// Takes ownership of `m`.
  explicit Geodesic_distance_matrix(Matrix m) : m_d(std::move(m)) {}
  /// n, the number of vertices.
  std::size_t size() const { return static_cast<std::size_t>(m_d.rows()); }
  /// Distance between vertices i and j (0-based indices of the engine's vertex index map).
  float operator()(std::size_t i, std::size_t j) const { return m_d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)); }
  /// Row i: the distances from vertex i to every vertex.
  auto row(std::size_t i) const { return m_d.row(static_cast<Eigen::Index>(i)); }
  /// The matrix itself: entry (i, j) is the distance between vertices i and j.
  const Matrix& matrix() const { return m_d; }
  /// Largest finite entry: the geodesic diameter D of the mesh.
  double diameter() const {
    float best = 0;
    for(Eigen::Index i = 0; i < m_d.size(); ++i) {
      const float v = m_d.data()[i];
      if(std::isfinite(v) && v > best) best = v;
    }
    return best;
  }
  /// Memory held, in bytes.
  std::size_t memory_bytes() const { return sizeof(float) * static_cast<std::size_t>(m_d.size()); }

private:
  Matrix m_d;
};

namespace internal {

/// Visits every pair i < j of a square matrix blockwise (cache-friendly transposed access) as
/// `op(D(i,j), D(j,i))` or `op(D(i,j), D(j,i), i, j)`, then zeroes the diagonal.
template <typename Op>
void symmetrize(Geodesic_distance_matrix::Matrix& D, Op&& op) {
  const Eigen::Index N = D.rows(), B = 64;
  for(Eigen::Index bi = 0; bi < N; bi += B)
    for(Eigen::Index bj = bi; bj < N; bj += B)
      for(Eigen::Index i = bi; i < std::min(bi + B, N); ++i)
        for(Eigen::Index j = std::max(bj, i + 1); j < std::min(bj + B, N); ++j) {
          if constexpr(std::is_invocable<Op, float&, float&, Eigen::Index, Eigen::Index>::value) op(D(i, j), D(j, i), i, j);
          else op(D(i, j), D(j, i));
        }
  for(Eigen::Index i = 0; i < N; ++i) D(i, i) = 0.f;
}

template <typename GeodesicDistanceEngine>
Geodesic_distance_matrix all_pairs_from_engine(const GeodesicDistanceEngine& engine,
                                               const std::function<void(std::size_t, std::size_t)>& progress) {
  const std::size_t n = engine.number_of_vertices();
  Geodesic_distance_matrix::Matrix D(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  std::vector<std::size_t> sources(n);
  std::iota(sources.begin(), sources.end(), std::size_t(0));
  // the block for sources [first, first+count) goes to rows [first, first+count): row s = from s
  engine.for_each_batch(sources, [&](std::size_t first, std::size_t count, const Eigen::MatrixXd& block) {
    D.block(static_cast<Eigen::Index>(first), 0, static_cast<Eigen::Index>(count), static_cast<Eigen::Index>(n)) =
        block.transpose().cast<float>();
  }, progress);
  symmetrize(D, [&](float& a, float& b) { a = b = 0.5f * (a + b); });
  return Geodesic_distance_matrix(std::move(D));
}

/// Fast marching, one triangle of the matrix: sources are swept in order of distance from an
/// extreme vertex, and the march from the p-th source stops once every vertex later in that order
/// is reached (on the TOSCA wolf 0.83 of the vertex visits of n full marches, 0.81 of their time). Entry (i, j) is the
/// distance from whichever of i, j comes first in the sweep.
template <typename TriangleMesh>
Geodesic_distance_matrix all_pairs_from_engine(const Fast_marching_geodesics<TriangleMesh>& engine,
                                               const std::function<void(std::size_t, std::size_t)>& progress) {
  typedef typename Fast_marching_geodesics<TriangleMesh>::Workspace Workspace;
  const std::size_t n = engine.number_of_vertices();
  const float inf = std::numeric_limits<float>::infinity();
  Geodesic_distance_matrix::Matrix D = Geodesic_distance_matrix::Matrix::Constant(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n), inf);
  // sweep order: by distance from the vertex farthest from vertex 0 (unreachable vertices last)
  std::vector<double> key(n, std::numeric_limits<double>::infinity());
  Workspace w0;
  std::size_t extreme = 0;
  double far = -1;
  engine.march({0}, std::numeric_limits<double>::infinity(), w0, [&](std::size_t v, double d) {
    if(d > far) { far = d; extreme = v; }
  });
  engine.march({extreme}, std::numeric_limits<double>::infinity(), w0, [&](std::size_t v, double d) { key[v] = d; });
  std::vector<std::size_t> order(n), pos(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  for(std::size_t p = 0; p < n; ++p) pos[order[p]] = p;

  std::vector<Workspace> ws(engine.number_of_threads());
  std::mutex mtx;
  std::size_t done = 0;
  parallel_for(n, engine.number_of_threads(), [&](std::size_t p, unsigned tid) {
    const std::size_t s = order[p];
    float* row = D.data() + static_cast<std::ptrdiff_t>(s * n);
    std::size_t remaining = n - 1 - p;
    if(remaining > 0)
      engine.march({s}, std::numeric_limits<double>::infinity(), ws[tid], [&](std::size_t v, double d) {
        if(pos[v] > p) {
          row[v] = static_cast<float>(d);
          --remaining;
        }
        return remaining > 0;
      });
    if(progress) {
      std::lock_guard<std::mutex> lock(mtx);
      progress(++done, n);
    }
  });
  // mirror: (i, j) was computed by whichever of i, j comes first in the sweep
  symmetrize(D, [&](float& ij, float& ji, Eigen::Index i, Eigen::Index j) {
    if(pos[static_cast<std::size_t>(i)] < pos[static_cast<std::size_t>(j)]) ji = ij;
    else ij = ji;
  });
  return Geodesic_distance_matrix(std::move(D));
}

} // namespace internal

/// \ingroup PkgShapeCorrGeodesics
/// All-pairs geodesic distances between the vertices of `tm`, in the order of the engine's vertex
/// index map. Cost: n single-source queries in parallel; memory 4 n^2 bytes. The default backend
/// is fast marching (first order, the more accurate); the heat method
/// (`geodesic_method(Geodesic_method::HEAT)`, batched multi right-hand-side solves) is faster and
/// less accurate. benchmark/README.md has the times and errors against CGAL's `Heat_method_3`.
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `geodesic_engine` | a precomputed engine to reuse | pointer to a `GeodesicDistanceEngine` | none: one is built |
/// | `geodesic_method` | backend to build when no engine is given | `Geodesic_method` | `FAST_MARCHING` |
/// | `progress_callback` | called as `f(sources_done, sources_total)` | `std::function<void(size_t, size_t)>` | none |
/// | (engine parameters) | `vertex_point_map`, `vertex_index_map`, `time_step_factor`, `use_intrinsic_delaunay`, `number_of_threads`, `batch_size` | see `Heat_method_geodesics` | |
/// \returns a `Geodesic_distance_matrix` (float, symmetrized)
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Geodesic_distance_matrix compute_all_pairs_geodesic_distances(const TriangleMesh& tm,
                                                              const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto progress = internal::progress_of(np);
  return with_geodesic_engine(tm, np, [&](const auto& engine) {
    return internal::all_pairs_from_engine(engine, progress);
  }, Geodesic_method::FAST_MARCHING);
}

} // namespace shapecorr

#endif
