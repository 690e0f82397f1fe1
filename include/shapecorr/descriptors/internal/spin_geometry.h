// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: per-mesh data of the rigid descriptors (face areas, normals and centres, vertex
// normals, the area centroid, kd-trees of vertices and face centres) and the oriented-point axes:
// normal, central point direction (global and local) and the SHOT local reference frame.
#ifndef SHAPECORR_DESCRIPTORS_INTERNAL_SPIN_GEOMETRY_H
#define SHAPECORR_DESCRIPTORS_INTERNAL_SPIN_GEOMETRY_H

#include <shapecorr/descriptors/internal/contour_construction.h>
#include <shapecorr/exceptions.h>
#include <shapecorr/internal/kd_tree.h>
#include <shapecorr/internal/indexed_mesh.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// The direction n of an oriented point (P, n), the axis of its spin map (ALGORITHMS.md, chapter 3).
enum class Spin_axis {
  NORMAL,                  ///< the face normal at a surface point; the area-weighted normal at a vertex
  CENTRAL_DIRECTION,       ///< towards the area centroid of the whole surface (thesis eq. 3.1)
  LOCAL_CENTRAL_DIRECTION, ///< towards the area centroid of the faces within `central_radius` (eq. 3.2)
  SHOT_LRF                 ///< the third axis of the SHOT local reference frame (Tombari et al. 2010): the improved spin image
};

/// \ingroup PkgShapeCorrDescriptors
/// A point with a unit direction: the origin of a spin map.
struct Oriented_point {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  /// true when the requested axis was degenerate there and the normal was used instead
  bool fell_back_to_normal = false;
};

namespace internal {

class Spin_geometry {
public:
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Rows3;

  explicit Spin_geometry(Triangle_arrays arrays) : a(std::move(arrays)) {
    const Eigen::Index n = a.V.rows(), m = a.F.rows();
    if(n == 0 || m == 0) throw Invalid_input(Mesh_defect::empty_mesh, "spin descriptors: the mesh has no vertex or no face");
    if(!a.V.allFinite()) throw Invalid_input(Mesh_defect::non_finite_coordinate, "spin descriptors: a vertex has a non-finite coordinate");
    face_area.resize(m);
    face_normal.resize(m, 3);
    face_center.resize(m, 3);
    vertex_normal = Rows3::Zero(n, 3);
    Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
    double total = 0, edges = 0;
    std::vector<Kd_tree<3>::Point> centers(static_cast<std::size_t>(m)), verts(static_cast<std::size_t>(n));
    for(Eigen::Index f = 0; f < m; ++f) {
      const Eigen::Vector3d p0 = a.V.row(a.F(f, 0)), p1 = a.V.row(a.F(f, 1)), p2 = a.V.row(a.F(f, 2));
      const Eigen::Vector3d c = (p1 - p0).cross(p2 - p0);
      const double twice = c.norm();
      face_area[f] = 0.5 * twice;
      face_normal.row(f) = twice > 0 ? Eigen::Vector3d(c / twice) : Eigen::Vector3d::Zero();
      face_center.row(f) = (p0 + p1 + p2) / 3.0;
      for(int k = 0; k < 3; ++k) vertex_normal.row(a.F(f, k)) += 0.5 * c; // area-weighted
      weighted += face_area[f] * face_center.row(f).transpose();
      total += face_area[f];
      edges += (p1 - p0).norm() + (p2 - p1).norm() + (p0 - p2).norm();
      for(const Eigen::Vector3d* q : {&p0, &p1, &p2}) max_face_radius = std::max(max_face_radius, (*q - face_center.row(f).transpose()).norm());
      centers[static_cast<std::size_t>(f)] = {face_center(f, 0), face_center(f, 1), face_center(f, 2)};
    }
    if(!(total > 0)) throw Invalid_input(Mesh_defect::degenerate_face, "spin descriptors: the surface has zero area");
    area = total;
    centroid = weighted / total;
    mean_edge_length = edges / (3.0 * static_cast<double>(m));
    for(Eigen::Index v = 0; v < n; ++v) {
      const double l = vertex_normal.row(v).norm();
      if(l > 0) vertex_normal.row(v) /= l;
      verts[static_cast<std::size_t>(v)] = {a.V(v, 0), a.V(v, 1), a.V(v, 2)};
    }
    bbox_diagonal = (a.V.colwise().maxCoeff() - a.V.colwise().minCoeff()).norm();
    double far = 0;
    for(Eigen::Index v = 0; v < n; ++v) far = std::max(far, (a.V.row(v).transpose() - centroid).norm());
    extent = 2 * far;
    face_tree = Kd_tree<3>(std::move(centers));
    face_links = build_face_links(a);
    half_edges = build_half_edge_links(face_links);
    vertex_tree = Kd_tree<3>(std::move(verts));
  }

  /// The normal at vertex v; throws when the faces around it cancel (no defined normal).
  Eigen::Vector3d normal_at_vertex(std::size_t v) const {
    const Eigen::Vector3d n = vertex_normal.row(static_cast<Eigen::Index>(v));
    if(n.squaredNorm() < 0.5)
      throw Invalid_input(Mesh_defect::degenerate_face, "spin descriptors: vertex " + std::to_string(v) +
                                                           " has no normal (no incident face of nonzero area, or they cancel)");
    return n;
  }
  Eigen::Vector3d normal_of_face(std::size_t f) const {
    const Eigen::Vector3d n = face_normal.row(static_cast<Eigen::Index>(f));
    if(n.squaredNorm() < 0.5)
      throw Invalid_input(Mesh_defect::degenerate_face, "spin descriptors: face " + std::to_string(f) + " has zero area (no normal)");
    return n;
  }

  /// Fills op.axis by `axis` at op.point; `normal` is the fallback for degenerate places.
  /// Central direction: degenerate when |c - P| < 1e-6 bbox diagonal. Local central direction:
  /// faces whose centre lies within `radius` of P (choice), degenerate when |c - P| < 1e-3 radius
  /// (a flat disc around P has its centroid at P). SHOT frame: vertices within `radius`, weights
  /// radius - d; degenerate with fewer than 3 neighbours or a repeated smallest eigenvalue.
  void set_axis(Oriented_point& op, Spin_axis axis, const Eigen::Vector3d& normal, double central_radius, double lrf_radius) const {
    op.axis = normal;
    op.fell_back_to_normal = false;
    switch(axis) {
    case Spin_axis::NORMAL: return;
    case Spin_axis::CENTRAL_DIRECTION: {
      const Eigen::Vector3d d = centroid - op.point;
      if(d.norm() < 1e-6 * bbox_diagonal) op.fell_back_to_normal = true;
      else op.axis = d.normalized();
      return;
    }
    case Spin_axis::LOCAL_CENTRAL_DIRECTION: {
      Eigen::Vector3d w = Eigen::Vector3d::Zero();
      double s = 0;
      face_tree.for_each_within({op.point.x(), op.point.y(), op.point.z()}, central_radius, [&](std::size_t f, double) {
        w += face_area[static_cast<Eigen::Index>(f)] * face_center.row(static_cast<Eigen::Index>(f)).transpose();
        s += face_area[static_cast<Eigen::Index>(f)];
      });
      const Eigen::Vector3d d = s > 0 ? Eigen::Vector3d(w / s - op.point) : Eigen::Vector3d::Zero();
      if(!(s > 0) || d.norm() < 1e-3 * central_radius) op.fell_back_to_normal = true;
      else op.axis = d.normalized();
      return;
    }
    case Spin_axis::SHOT_LRF: {
      Eigen::Matrix3d frame;
      if(shot_frame(op.point, lrf_radius, frame)) op.axis = frame.col(2);
      else op.fell_back_to_normal = true;
      return;
    }
    }
  }

  /// The SHOT local reference frame at p (columns x, y, z; Tombari, Salti & Di Stefano 2010):
  /// eigenvectors of the distance-weighted covariance of the vertices within r around p (not
  /// their mean), x and z oriented towards the majority of the neighbours, y = z x x.
  /// Returns false when it is undefined (fewer than 3 neighbours, a repeated eigenvalue).
  bool shot_frame(const Eigen::Vector3d& p, double r, Eigen::Matrix3d& frame) const {
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    double s = 0;
    std::vector<std::size_t> nb;
    vertex_tree.for_each_within({p.x(), p.y(), p.z()}, r, [&](std::size_t v, double d2) {
      const Eigen::Vector3d q = a.V.row(static_cast<Eigen::Index>(v)).transpose() - p;
      const double w = r - std::sqrt(d2);
      M += w * q * q.transpose();
      s += w;
      nb.push_back(v);
    });
    if(nb.size() < 3 || !(s > 0)) return false;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M / s);
    const Eigen::Vector3d ev = es.eigenvalues(); // ascending
    if(!(ev[2] > 0) || ev[1] - ev[0] < 1e-9 * ev[2] || ev[2] - ev[1] < 1e-9 * ev[2]) return false;
    Eigen::Vector3d x = es.eigenvectors().col(2), z = es.eigenvectors().col(0);
    auto orient = [&](Eigen::Vector3d& axis) {
      long positive = 0;
      for(std::size_t v : nb) positive += (a.V.row(static_cast<Eigen::Index>(v)).transpose() - p).dot(axis) >= 0 ? 1 : -1;
      if(positive < 0) axis = -axis;
    };
    orient(x);
    orient(z);
    frame.col(0) = x;
    frame.col(1) = z.cross(x);
    frame.col(2) = z;
    return true;
  }

  Triangle_arrays a;
  Eigen::VectorXd face_area;
  Rows3 face_normal, face_center, vertex_normal;
  Eigen::Vector3d centroid;
  double area = 0, bbox_diagonal = 0, mean_edge_length = 0;
  double extent = 0;          // 2 x the largest distance of a vertex from the centroid (rotation invariant)
  double max_face_radius = 0; // largest distance from a face centre to its corners
  Kd_tree<3> face_tree, vertex_tree;
  std::vector<Face_link> face_links; // corners, neighbours across edges, for the contour walk
  std::vector<Half_edge_link> half_edges; // the walk's steps
};

} // namespace internal
} // namespace shapecorr

#endif
