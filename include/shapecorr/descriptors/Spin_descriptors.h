// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Spin_descriptors.h
/// Spin images, face-based spin images, improved spin images and Spin Contours of a mesh
/// (ALGORITHMS.md, chapter 3): a precomputed object and the property-map functions.
#ifndef SHAPECORR_DESCRIPTORS_SPIN_DESCRIPTORS_H
#define SHAPECORR_DESCRIPTORS_SPIN_DESCRIPTORS_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/Spin_image.h>
#include <shapecorr/descriptors/internal/spin_construction.h>
#include <shapecorr/descriptors/internal/spin_geometry.h>
#include <shapecorr/parallel.h>
#include <shapecorr/internal/progress.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/parameters.h>

#include <Eigen/Core>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/property_map.hpp>

#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// The rigid spin descriptors of one mesh, computed for any number of oriented points: the mesh
/// data (face areas, normals, centroid, kd-trees) is prepared once at construction.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
///
/// Named parameters of the constructor:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `vertex_point_map` | positions | `ReadablePropertyMap<vertex_descriptor, Point_3>` | `get(CGAL::vertex_point, tm)` |
/// | `vertex_index_map` | 0-based vertex indices | `ReadablePropertyMap<vertex_descriptor, size_t>` | the mesh's own, or a fresh one |
/// | `support_length` | L: alpha in [0, L], beta in [-L, L] | `double` | the extent: twice the largest distance of a vertex from the area centroid (the thesis's "100% of the bounding box", made independent of rotations; `bounding_box_diagonal()` gives the axis-aligned value) |
/// | `image_rows`, `image_columns` | beta samples (rows) and alpha samples (columns) | `std::size_t` | 120, 60 (thesis) |
/// | `spin_axis` | the direction n of oriented points | `Spin_axis` | `NORMAL` |
/// | `central_radius` | radius of `LOCAL_CENTRAL_DIRECTION` | `double` | 0.1 x the extent (thesis: 5-15% of the bounding box) |
/// | `lrf_radius` | radius of the SHOT frame (`SHOT_LRF`) | `double` | 30 x mean edge length (thesis) |
/// | `support_angle` | spin images: drop vertices/faces whose normal makes a larger angle with n (radians) | `double` | pi (no limit) |
/// | `face_samples_per_bin` | face-based image: sub-triangle edges at most bin width / this | `double` | 2 |
/// | `number_of_threads` | threads of the batch functions | `unsigned` | all |
///
/// \throws Invalid_input for an empty mesh, non-triangle faces, non-finite coordinates, a surface
/// of zero area, or parameters out of range
template <typename TriangleMesh>
class Spin_descriptors {
public:
  /// The mesh's graph traits.
  typedef boost::graph_traits<TriangleMesh> GT;
  /// The mesh's vertex type.
  typedef typename GT::vertex_descriptor vertex_descriptor;
  /// The mesh's face type.
  typedef typename GT::face_descriptor face_descriptor;
  /// A point on a face by barycentric coordinates (CGAL's Polygon Mesh Processing location).
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;
  /// Progress callback `f(done, total)` of the batch functions.
  typedef std::function<void(std::size_t, std::size_t)> Progress;

  template <typename NamedParameters = parameters::Default_named_parameters>
  /// Precomputes normals, the centroid and the flat copy of `tm` (named parameters above).
  explicit Spin_descriptors(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_mesh(tm, np), m_geometry(m_mesh.arrays()) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    m_options.support = choose_parameter(get_parameter(np, internal_np::support_length), m_geometry.extent);
    m_options.rows = choose_parameter(get_parameter(np, internal_np::image_rows), std::size_t(120));
    m_options.cols = choose_parameter(get_parameter(np, internal_np::image_columns), std::size_t(60));
    m_axis = choose_parameter(get_parameter(np, internal_np::spin_axis), Spin_axis::NORMAL);
    m_central_radius = choose_parameter(get_parameter(np, internal_np::central_radius), 0.1 * m_geometry.extent);
    m_lrf_radius = choose_parameter(get_parameter(np, internal_np::lrf_radius), 30.0 * m_geometry.mean_edge_length);
    const double angle = choose_parameter(get_parameter(np, internal_np::support_angle), CGAL_PI);
    m_options.cos_support_angle = angle >= CGAL_PI ? -1.0 : std::cos(angle);
    m_options.samples_per_bin = choose_parameter(get_parameter(np, internal_np::face_samples_per_bin), 2.0);
    m_threads = resolve_thread_count(choose_parameter(get_parameter(np, internal_np::number_of_threads), 0u));
    if(!(m_options.support > 0) || !std::isfinite(m_options.support))
      throw Invalid_argument("spin descriptors: support_length must be positive and finite");
    if(m_options.rows < 2 || m_options.cols < 1)
      throw Invalid_argument("spin descriptors: need at least 2 image rows and 1 column");
    if(!(m_central_radius > 0) || !(m_lrf_radius > 0) || !(angle > 0) || !(m_options.samples_per_bin > 0))
      throw Invalid_argument("spin descriptors: central_radius, lrf_radius, support_angle and face_samples_per_bin must be positive");
    // Faces in the order of the mesh's iteration (the row order of the flat copy).
    auto fim = CGAL::get_initialized_face_index_map(tm, np);
    m_face_index = [fim](face_descriptor fd) { return static_cast<std::size_t>(get(fim, fd)); };
    m_face_row.assign(num_faces(tm), 0);
    std::size_t f = 0;
    for(face_descriptor fd : faces(tm)) {
      const std::size_t i = m_face_index(fd);
      if(i >= m_face_row.size()) throw Invalid_argument("spin descriptors: the face index map is not initialized");
      m_face_row[i] = f++;
    }
  }

  /// The support length L (mesh units).
  double support_length() const { return m_options.support; }
  /// Number of rows (beta samples).
  std::size_t rows() const { return m_options.rows; }
  /// Number of columns (alpha samples).
  std::size_t columns() const { return m_options.cols; }
  /// The default axis of the oriented points.
  Spin_axis axis() const { return m_axis; }
  /// Mean edge length (the thesis's mesh resolution mr).
  double mesh_resolution() const { return m_geometry.mean_edge_length; }
  /// Diagonal of the axis-aligned bounding box.
  double bounding_box_diagonal() const { return m_geometry.bbox_diagonal; }
  /// Twice the largest distance of a vertex from the area centroid: the default support length.
  double extent() const { return m_geometry.extent; }
  /// The area centroid of the surface (the target of the central point direction).
  Eigen::Vector3d centroid() const { return m_geometry.centroid; }
  /// The 0-based index of `v`.
  std::size_t index(vertex_descriptor v) const { return m_mesh.index(v); }

  /// The oriented point at vertex v with the constructor's axis (or `axis`).
  Oriented_point oriented_point(vertex_descriptor v) const { return oriented_point(v, m_axis); }
  /// The oriented point at vertex v with axis `axis`.
  Oriented_point oriented_point(vertex_descriptor v, Spin_axis axis) const {
    const std::size_t i = m_mesh.index(v);
    Oriented_point op;
    op.point = m_geometry.a.point(i);
    m_geometry.set_axis(op, axis, m_geometry.normal_at_vertex(i), m_central_radius, m_lrf_radius);
    return op;
  }
  /// The oriented point at a surface point; NORMAL is the normal of its face.
  Oriented_point oriented_point(const Face_location& loc) const { return oriented_point(loc, m_axis); }
  /// The oriented point at a surface point with axis `axis`.
  Oriented_point oriented_point(const Face_location& loc, Spin_axis axis) const {
    const std::size_t f = face_row(loc.first);
    Oriented_point op;
    // CGAL's barycentric order: source(h), target(h), target(next(h)) with h = halfedge(face).
    const TriangleMesh& tm = m_mesh.mesh();
    const auto h = halfedge(loc.first, tm);
    const std::size_t corner[3] = {m_mesh.index(source(h, tm)), m_mesh.index(target(h, tm)), m_mesh.index(target(next(h, tm), tm))};
    op.point = Eigen::Vector3d::Zero();
    for(int k = 0; k < 3; ++k) op.point += loc.second[static_cast<std::size_t>(k)] * m_geometry.a.point(corner[k]);
    m_geometry.set_axis(op, axis, m_geometry.normal_of_face(f), m_central_radius, m_lrf_radius);
    return op;
  }
  /// The SHOT local reference frame at a point (columns x, y, z); false when undefined there.
  bool shot_frame(const Eigen::Vector3d& p, Eigen::Matrix3d& frame) const { return m_geometry.shot_frame(p, m_lrf_radius, frame); }

  /// Johnson & Hebert's spin image: vertices in the support, bilinear splatting.
  Spin_image spin_image(const Oriented_point& op) const { return internal::vertex_spin_image(m_geometry, op, m_options); }
  /// The face-based spin image (area-weighted, approximate method of Carmichael et al.).
  Spin_image face_spin_image(const Oriented_point& op) const { return internal::face_spin_image(m_geometry, op, m_options); }
  /// The face-based spin image, exact method of Carmichael et al.: each bin holds the area of the
  /// surface inside its volume (between two planes beta = const and two cylinders alpha = const), to
  /// rounding; no interpolation between bins. Slower than `face_spin_image`.
  Spin_image exact_face_spin_image(const Oriented_point& op) const { return internal::exact_face_spin_image(m_geometry, op, m_options); }
  /// The Spin Contour (thesis's fast construction), coordinates normalized by the support length.
  Spin_contour spin_contour(const Oriented_point& op) const {
    thread_local internal::Spin_contour_workspace ws;
    return internal::spin_contour(m_geometry, op, m_options, ws);
  }

  /// The batch forms, in parallel over many oriented points (as `Geodesic_spin_descriptors`'
  /// `geodesic_spin_contours`): one descriptor per point, in order; `progress(done, total)` when
  /// given.
  std::vector<Spin_image> spin_images(const std::vector<Oriented_point>& ops, const Progress& progress = {}) const {
    return for_each_point<Spin_image>(ops, [&](const Oriented_point& op) { return spin_image(op); }, progress);
  }
  /// (batch form of `face_spin_image`)
  std::vector<Spin_image> face_spin_images(const std::vector<Oriented_point>& ops, const Progress& progress = {}) const {
    return for_each_point<Spin_image>(ops, [&](const Oriented_point& op) { return face_spin_image(op); }, progress);
  }
  /// (batch form of `exact_face_spin_image`)
  std::vector<Spin_image> exact_face_spin_images(const std::vector<Oriented_point>& ops, const Progress& progress = {}) const {
    return for_each_point<Spin_image>(ops, [&](const Oriented_point& op) { return exact_face_spin_image(op); }, progress);
  }
  /// (batch form of `spin_contour`)
  std::vector<Spin_contour> spin_contours(const std::vector<Oriented_point>& ops, const Progress& progress = {}) const {
    return for_each_point<Spin_contour>(ops, [&](const Oriented_point& op) { return spin_contour(op); }, progress);
  }

private:
  // fn(op) for many oriented points in parallel, with progress reports.
  template <typename Descriptor, typename Fn>
  std::vector<Descriptor> for_each_point(const std::vector<Oriented_point>& ops, Fn&& fn,
                                         const std::function<void(std::size_t, std::size_t)>& progress = {}) const {
    std::vector<Descriptor> out(ops.size());
    std::atomic<std::size_t> done(0);
    std::mutex report;
    parallel_for(ops.size(), m_threads, [&](std::size_t i, unsigned) {
      out[i] = fn(ops[i]);
      const std::size_t d = ++done;
      if(progress && (d % 64 == 0 || d == ops.size())) {
        std::lock_guard<std::mutex> lock(report);
        progress(d, ops.size());
      }
    });
    return out;
  }

  std::size_t face_row(face_descriptor fd) const {
    const std::size_t i = m_face_index(fd);
    if(i >= m_face_row.size()) throw Invalid_argument("spin descriptors: the face location is not on this mesh");
    return m_face_row[i];
  }

  internal::Indexed_mesh<TriangleMesh> m_mesh;
  internal::Spin_geometry m_geometry;
  internal::Spin_options m_options;
  Spin_axis m_axis = Spin_axis::NORMAL;
  double m_central_radius = 0, m_lrf_radius = 0;
  unsigned m_threads = 1;
  std::function<std::size_t(face_descriptor)> m_face_index;
  std::vector<std::size_t> m_face_row; // face index -> row of the flat copy
};

namespace internal {
template <typename Descriptor, typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters, typename Fn>
void compute_for_vertices(const TriangleMesh& tm, const VertexRange& vertices_, DescriptorMap map, const NamedParameters& np, Fn&& fn) {
  const Spin_descriptors<TriangleMesh> sd(tm, np);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vs(vertices_.begin(), vertices_.end());
  std::vector<Oriented_point> ops;
  ops.reserve(vs.size());
  for(auto v : vs) ops.push_back(sd.oriented_point(v));
  const std::vector<Descriptor> d = fn(sd, ops, progress_of(np));
  for(std::size_t i = 0; i < vs.size(); ++i) put(map, vs[i], d[i]);
}
} // namespace internal

/// \ingroup PkgShapeCorrDescriptors
/// Spin images (Johnson & Hebert 1999) of the vertices of `vertices`, written into `images`
/// (a `WritablePropertyMap` from `vertex_descriptor` to `Spin_image`). With
/// `spin_axis(Spin_axis::SHOT_LRF)` this is the improved spin image (ISI).
/// \param np the named parameters of `Spin_descriptors`, and `progress_callback`
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_spin_images(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap images,
                         const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::compute_for_vertices<Spin_image>(tm, vertices, images, np, [](const auto& sd, const auto& ops, const auto& progress) { return sd.spin_images(ops, progress); });
}

/// \ingroup PkgShapeCorrDescriptors
/// Face-based spin images (Carmichael et al. 1999) of the vertices of `vertices`, as `compute_spin_images`.
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_face_spin_images(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap images,
                              const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::compute_for_vertices<Spin_image>(tm, vertices, images, np, [](const auto& sd, const auto& ops, const auto& progress) { return sd.face_spin_images(ops, progress); });
}

/// \ingroup PkgShapeCorrDescriptors
/// Face-based spin images with exact areas (`Spin_descriptors::exact_face_spin_image`) of the
/// vertices of `vertices`, as `compute_spin_images`.
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_exact_face_spin_images(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap images,
                                    const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::compute_for_vertices<Spin_image>(tm, vertices, images, np,
                                             [](const auto& sd, const auto& ops, const auto& progress) { return sd.exact_face_spin_images(ops, progress); });
}

/// \ingroup PkgShapeCorrDescriptors
/// Spin Contours (thesis chapter 3) of the vertices of `vertices`, written into `contours` (a
/// `WritablePropertyMap` from `vertex_descriptor` to `Spin_contour`); compare them with
/// `contour_l1_distance`.
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_spin_contours(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap contours,
                           const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::compute_for_vertices<Spin_contour>(tm, vertices, contours, np, [](const auto& sd, const auto& ops, const auto& progress) { return sd.spin_contours(ops, progress); });
}

} // namespace shapecorr

#endif
