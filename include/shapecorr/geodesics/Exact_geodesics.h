// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Exact_geodesics.h
#ifndef SHAPECORR_GEODESICS_EXACT_GEODESICS_H
#define SHAPECORR_GEODESICS_EXACT_GEODESICS_H

#include <shapecorr/parallel.h>
#include <shapecorr/internal/components.h>
#include <shapecorr/geodesics/internal/engine_helpers.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>

#include <functional>
#include <limits>
#include <mutex>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrGeodesics
/// Exact geodesic distances (the reference): CGAL's `Surface_mesh_shortest_path` (Xin & Wang's
/// improvement of Chen & Han), one sequence tree per query. Same interface as
/// `Heat_method_geodesics` (a model of `GeodesicDistanceEngine`); batched queries run the sources
/// in parallel, one CGAL object per thread.
///
/// Distances to vertices of components holding no source are `+infinity`.
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces, supported by CGAL's
///         `Surface_mesh_shortest_path` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`, ...)
/// \tparam VertexPointMap the type of the `vertex_point_map` named parameter (default: the
///         mesh's internal point map)
template <typename TriangleMesh,
          typename VertexPointMap = typename CGAL::GetVertexPointMap<TriangleMesh>::const_type>
class Exact_geodesics {
public:
  /// The mesh's vertex type.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// The vertex point map type.
  typedef VertexPointMap Vpm;
  /// The point type.
  typedef typename boost::property_traits<Vpm>::value_type Point;
  /// The kernel of the points.
  typedef typename CGAL::Kernel_traits<Point>::Kernel Kernel;
  /// CGAL's shortest path traits.
  typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, TriangleMesh> Traits;
  /// Index maps of CGAL's shortest path object.
  typedef decltype(CGAL::get_initialized_vertex_index_map(std::declval<const TriangleMesh&>())) VIM;
  /// (halfedges)
  typedef decltype(CGAL::get_initialized_halfedge_index_map(std::declval<const TriangleMesh&>())) HIM;
  /// (faces)
  typedef decltype(CGAL::get_initialized_face_index_map(std::declval<const TriangleMesh&>())) FIM;
  /// CGAL's shortest path object, one per query.
  typedef CGAL::Surface_mesh_shortest_path<Traits, VIM, HIM, FIM, Vpm> Shortest_path;
  /// Progress callback `f(done, total)` of batch queries.
  typedef std::function<void(std::size_t, std::size_t)> Progress;

  /// \param tm the triangle mesh; it must outlive this object and stay unchanged
  /// \param np `vertex_point_map` (of type `VertexPointMap`), `vertex_index_map` (0-based vertex
  /// indices), `number_of_threads` (0 = all cores).
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Exact_geodesics(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_tm(tm), m_mesh(tm, np), m_vim(CGAL::get_initialized_vertex_index_map(tm)),
      m_him(CGAL::get_initialized_halfedge_index_map(tm)), m_fim(CGAL::get_initialized_face_index_map(tm)),
      m_vpm(parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                         CGAL::get_const_property_map(CGAL::vertex_point, tm))) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    m_threads = resolve_thread_count(choose_parameter(get_parameter(np, internal_np::number_of_threads), 0u));
    m_components = internal::vertex_components(m_mesh.number_of_vertices(), m_mesh.arrays().F, m_component);
  }

  /// n: vertex indices run over [0, n).
  std::size_t number_of_vertices() const { return m_mesh.number_of_vertices(); }
  /// The 0-based index of `v` (the vertex index map fixed at construction).
  std::size_t index(vertex_descriptor v) const { return m_mesh.index(v); }
  /// The vertex of index `i`.
  vertex_descriptor vertex(std::size_t i) const { return m_mesh.vertex(i); }
  /// The mesh the engine was built on.
  const TriangleMesh& mesh() const { return m_tm; }
  /// Positions and triangles in index order (the flat copy the engine works on).
  const internal::Triangle_arrays& arrays() const { return m_mesh.arrays(); }
  /// Threads of batch queries.
  unsigned number_of_threads() const { return m_threads; }

  /// Distance of every vertex (by index) to the nearest of `sources` (indices); `+infinity` in components without a source. \throws Invalid_argument for no source or an index out of range
  Eigen::VectorXd distances_to_set(const std::vector<std::size_t>& sources) const {
    if(sources.empty()) throw Invalid_argument("exact geodesics: no source vertex given");
    Shortest_path sp(m_tm, m_vim, m_him, m_fim, m_vpm);
    std::vector<char> has_source(m_components, 0);
    for(std::size_t s : sources) {
      check_source(s);
      sp.add_source_point(vertex(s));
      has_source[static_cast<std::size_t>(m_component[s])] = 1;
    }
    sp.build_sequence_tree();
    const std::size_t n = number_of_vertices();
    Eigen::VectorXd d(static_cast<Eigen::Index>(n));
    for(std::size_t i = 0; i < n; ++i) {
      d[static_cast<Eigen::Index>(i)] = has_source[static_cast<std::size_t>(m_component[i])]
                                            ? CGAL::to_double(sp.shortest_distance_to_source_points(vertex(i)).first)
                                            : std::numeric_limits<double>::infinity();
    }
    for(std::size_t s : sources) d[static_cast<Eigen::Index>(s)] = 0.0;
    return d;
  }
  /// Distance of every vertex (by index) to vertex `source`.
  Eigen::VectorXd distances_from(std::size_t source) const { return distances_to_set({source}); }

  /// As `Heat_method_geodesics::for_each_batch` (batches of one source each).
  template <typename BlockFn>
  void for_each_batch(const std::vector<std::size_t>& sources, BlockFn&& fn, const Progress& progress = {}) const {
    internal::for_each_single_source(sources, m_threads, [&](std::size_t s, unsigned) { return distances_from(s); }, fn, progress);
  }

  template <typename VertexRange, typename VertexDistanceMap>
  /// Distance of every vertex to the nearest vertex of `sources` (`vertex_descriptor`s), written into `distance_map` (a `WritablePropertyMap<vertex_descriptor, double>`).
  void compute_geodesic_distances(const VertexRange& sources, VertexDistanceMap distance_map) const {
    internal::write_distances_to_set(*this, sources, distance_map);
  }

private:
  void check_source(std::size_t s) const {
    if(s >= number_of_vertices())
      throw Invalid_argument("source vertex " + std::to_string(s) + " out of range (mesh has " +
                                                             std::to_string(number_of_vertices()) + " vertices)");
  }
  const TriangleMesh& m_tm;
  internal::Indexed_mesh<TriangleMesh> m_mesh;
  VIM m_vim;
  HIM m_him;
  FIM m_fim;
  Vpm m_vpm;
  unsigned m_threads = 1;
  std::size_t m_components = 0;
  std::vector<int> m_component;
};

} // namespace shapecorr

#endif
