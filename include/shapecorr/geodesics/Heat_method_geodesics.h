// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Heat_method_geodesics.h
#ifndef SHAPECORR_GEODESICS_HEAT_METHOD_GEODESICS_H
#define SHAPECORR_GEODESICS_HEAT_METHOD_GEODESICS_H

#include <shapecorr/geodesics/internal/heat_method_engine.h>
#include <shapecorr/geodesics/internal/engine_helpers.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/parameters.h>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrGeodesics
/// Fast approximate geodesic distances by the heat method (Crane, Weischedel & Wardetzky 2013):
/// two sparse Cholesky factorizations (heat operator `M + tL`, cotangent Laplacian `L`) computed
/// once at construction, then any number of queries. Batches of sources share one triangular solve
/// with several right-hand sides; batches run in parallel.
///
/// This class is a model of the `GeodesicDistanceEngine` concept (doc/concepts.md): vertices are
/// addressed by their 0-based index in the vertex index map given at construction.
///
/// Boundaries: Neumann conditions for both solves. Several connected components: distances to
/// vertices of a component that holds no source are `+infinity`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam SparseSolver a model of `SparseSPDSolver` (see `shapecorr/internal/sparse_solver.h`)
template <typename TriangleMesh, typename SparseSolver = Default_sparse_spd_solver>
class Heat_method_geodesics {
public:
  /// The mesh's vertex type.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// Progress callback `f(done, total)` of batch queries.
  typedef std::function<void(std::size_t, std::size_t)> Progress;

  /// Precomputes the operators and (lazily, per thread) their factorizations.
  /// \param tm the triangle mesh; it must outlive this object and stay unchanged
  /// \param np optional named parameters:
  /// | name | meaning | type | default |
  /// |---|---|---|---|
  /// | `vertex_point_map` | positions | `ReadablePropertyMap<vertex_descriptor, Point_3>` | `get(CGAL::vertex_point, tm)` |
  /// | `vertex_index_map` | 0-based vertex indices | `ReadablePropertyMap<vertex_descriptor, size_t>` | the mesh's own, or a fresh one |
  /// | `time_step_factor` | m in t = m h^2, h the mean edge length | `double` | 1 |
  /// | `use_intrinsic_delaunay` | run on the intrinsic Delaunay triangulation (robust to obtuse / poor triangles) | `bool` | `false` |
  /// | `number_of_threads` | worker threads, 0 = all cores | `unsigned` | 0 |
  /// | `batch_size` | sources per multi right-hand-side solve | `std::size_t` | 8 |
  /// \throws Invalid_input for an empty mesh, non-triangle faces or non-finite coordinates
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Heat_method_geodesics(const TriangleMesh& tm,
                                 const NamedParameters& np = CGAL::parameters::default_values())
    : m_mesh(tm, np) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    internal::Heat_method_options opt;
    opt.time_step_factor = choose_parameter(get_parameter(np, internal_np::time_step_factor), 1.0);
    opt.intrinsic_delaunay = choose_parameter(get_parameter(np, internal_np::use_intrinsic_delaunay), false);
    opt.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0u);
    opt.batch_size = choose_parameter(get_parameter(np, internal_np::batch_size), std::size_t(8));
    if(!(opt.time_step_factor > 0))
      throw Invalid_argument("heat method: time_step_factor must be positive");
    m_engine = std::make_unique<internal::Heat_method_engine<SparseSolver>>(m_mesh.arrays(), opt);
  }

  /// Number of vertices; indices run over [0, n).
  std::size_t number_of_vertices() const { return m_mesh.number_of_vertices(); }
  /// Index of a vertex descriptor.
  std::size_t index(vertex_descriptor v) const { return m_mesh.index(v); }
  /// Vertex descriptor of an index.
  vertex_descriptor vertex(std::size_t i) const { return m_mesh.vertex(i); }
  /// The mesh.
  const TriangleMesh& mesh() const { return m_mesh.mesh(); }
  /// Flat copy of the mesh (positions, triangles) in index order.
  const internal::Triangle_arrays& arrays() const { return m_mesh.arrays(); }
  /// The diffusion time t actually used.
  double time_step() const { return m_engine->time_step(); }
  /// Number of intrinsic edge flips done (0 unless `use_intrinsic_delaunay`).
  std::size_t number_of_flips() const { return m_engine->number_of_flips(); }
  /// Threads used by batched queries.
  unsigned number_of_threads() const { return m_engine->number_of_threads(); }

  /// Distance of every vertex (index order) to the nearest of the sources (indices).
  Eigen::VectorXd distances_to_set(const std::vector<std::size_t>& sources) const {
    return m_engine->distances_to_set(sources);
  }
  /// Distance of every vertex (index order) to one source (index).
  Eigen::VectorXd distances_from(std::size_t source) const { return m_engine->distances_from(source); }

  /// Single-source distances for many sources: `fn(first, count, block)` receives an n x count
  /// block whose column j holds the distances from `sources[first + j]`. Called concurrently for
  /// different batches.
  template <typename BlockFn>
  void for_each_batch(const std::vector<std::size_t>& sources, BlockFn&& fn, const Progress& progress = {}) const {
    m_engine->for_each_batch(sources, std::forward<BlockFn>(fn), progress);
  }

  /// Writes into `distance_map` the distance of every vertex to the nearest of `sources`.
  /// \tparam VertexRange a range of `vertex_descriptor`
  /// \tparam VertexDistanceMap a `WritablePropertyMap<vertex_descriptor, double>`
  template <typename VertexRange, typename VertexDistanceMap>
  /// Distance of every vertex to the nearest vertex of `sources` (`vertex_descriptor`s), written into `distance_map` (a `WritablePropertyMap<vertex_descriptor, double>`).
  void compute_geodesic_distances(const VertexRange& sources, VertexDistanceMap distance_map) const {
    internal::write_distances_to_set(*this, sources, distance_map);
  }

private:
  internal::Indexed_mesh<TriangleMesh> m_mesh;
  std::unique_ptr<internal::Heat_method_engine<SparseSolver>> m_engine;
};

} // namespace shapecorr

#endif
