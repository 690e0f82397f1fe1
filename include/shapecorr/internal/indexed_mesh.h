// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: a flat, indexed copy of a triangle mesh (positions + corner array) on which the numerical
// kernels run, with the correspondence between indices and the mesh's own vertex descriptors.
#ifndef SHAPECORR_INTERNAL_INDEXED_MESH_H
#define SHAPECORR_INTERNAL_INDEXED_MESH_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace shapecorr {
namespace internal {

/// Positions (n x 3, row i = vertex i) and triangles (m x 3 vertex indices, counter-clockwise as in
/// the mesh). Indices are 0-based and follow the mesh's vertex index map.
struct Triangle_arrays {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> V;
  Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> F;
  std::size_t number_of_vertices() const { return static_cast<std::size_t>(V.rows()); }
  std::size_t number_of_faces() const { return static_cast<std::size_t>(F.rows()); }
  Eigen::Vector3d point(std::size_t i) const { return V.row(static_cast<Eigen::Index>(i)).transpose(); }
};

/// The flat copy together with the index <-> descriptor correspondence.
/// The vertex index map of the named parameters (or the mesh's own, or a fresh one) is used once,
/// at construction, and kept type-erased so that the class depends on the mesh type only.
template <typename TriangleMesh>
class Indexed_mesh {
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  Indexed_mesh() = default;

  template <typename NamedParameters>
  Indexed_mesh(const TriangleMesh& tm, const NamedParameters& np) : m_tm(&tm) {
    using parameters::choose_parameter;
    auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    m_index = [vim](vertex_descriptor v) { return static_cast<std::size_t>(get(vim, v)); };
    using parameters::get_parameter;
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                CGAL::get_const_property_map(CGAL::vertex_point, tm));
    const std::size_t n = num_vertices(tm);
    m_vertices.resize(n);
    m_arrays.V.resize(static_cast<Eigen::Index>(n), 3);
    for(vertex_descriptor v : vertices(tm)) {
      const std::size_t i = m_index(v);
      if(i >= n)
        throw Invalid_argument("vertex index map is not initialized (index " + std::to_string(i) +
                                " for a mesh of " + std::to_string(n) + " vertices)");
      m_vertices[i] = v;
      const auto& p = get(vpm, v);
      m_arrays.V(static_cast<Eigen::Index>(i), 0) = CGAL::to_double(p.x());
      m_arrays.V(static_cast<Eigen::Index>(i), 1) = CGAL::to_double(p.y());
      m_arrays.V(static_cast<Eigen::Index>(i), 2) = CGAL::to_double(p.z());
    }
    m_arrays.F.resize(static_cast<Eigen::Index>(num_faces(tm)), 3);
    Eigen::Index f = 0;
    for(face_descriptor fd : faces(tm)) {
      int k = 0;
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(fd, tm), tm)) {
        if(k == 3)
          throw Invalid_input(Mesh_defect::non_triangle_face,
                              "face " + std::to_string(f) + " has more than three vertices");
        m_arrays.F(f, k++) = static_cast<int>(m_index(v));
      }
      if(k != 3)
        throw Invalid_input(Mesh_defect::non_triangle_face,
                            "face " + std::to_string(f) + " has fewer than three vertices");
      ++f;
    }
  }

  const Triangle_arrays& arrays() const { return m_arrays; }
  std::size_t number_of_vertices() const { return m_vertices.size(); }
  vertex_descriptor vertex(std::size_t i) const { return m_vertices[i]; }
  const std::vector<vertex_descriptor>& vertex_descriptors() const { return m_vertices; }
  std::size_t index(vertex_descriptor v) const { return m_index(v); }
  const TriangleMesh& mesh() const { return *m_tm; }

private:
  const TriangleMesh* m_tm = nullptr;
  std::function<std::size_t(vertex_descriptor)> m_index;
  std::vector<vertex_descriptor> m_vertices;
  Triangle_arrays m_arrays;
};

/// Throws `Invalid_input` (message starting with `context`, naming `which`: "the source", "T")
/// unless the flat copy has triangles and finite coordinates only.
inline void require_finite_triangles(const Triangle_arrays& a, const std::string& context, const std::string& which) {
  if(a.number_of_faces() == 0) throw Invalid_input(Mesh_defect::empty_mesh, context + ": " + which + " has no triangle");
  for(Eigen::Index i = 0; i < a.V.rows(); ++i)
    if(!a.V.row(i).allFinite())
      throw Invalid_input(Mesh_defect::non_finite_coordinate,
                          context + ": vertex " + std::to_string(i) + " of " + which + " has a non-finite coordinate");
}

/// The flat copy of a mesh, checked by `require_finite_triangles`.
template <typename TriangleMesh, typename NamedParameters>
Triangle_arrays finite_triangle_arrays(const TriangleMesh& tm, const NamedParameters& np, const std::string& context, const std::string& which) {
  Triangle_arrays a = Indexed_mesh<TriangleMesh>(tm, np).arrays();
  require_finite_triangles(a, context, which);
  return a;
}

} // namespace internal
} // namespace shapecorr

#endif
