// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: closest points on a triangle mesh (its flat copy, Triangle_arrays), through CGAL's AABB
// tree. Shared by the surface-distance metrics (evaluation/) and the registration methods.
#ifndef SHAPECORR_INTERNAL_CLOSEST_POINT_TREE_H
#define SHAPECORR_INTERNAL_CLOSEST_POINT_TREE_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/indexed_mesh.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace shapecorr {
namespace internal {

/// The closest point of a triangle mesh to a query point: the point, the triangle it lies on (row
/// of `Triangle_arrays::F`) and the distance.
struct Closest_point {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  std::size_t triangle = 0;
  double distance = 0;
};

/// An AABB tree over the triangles of a flat mesh copy; queries are const and thread-safe once
/// built (the constructor builds the tree and its distance-query accelerator).
class Closest_point_tree {
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

public:
  /// \throws Invalid_input when the mesh has no triangle
  explicit Closest_point_tree(const Triangle_arrays& a) {
    if(a.number_of_faces() == 0) throw Invalid_input(Mesh_defect::empty_mesh, "closest points: the mesh has no triangle");
    m_triangles.reserve(a.number_of_faces());
    auto point = [&](int i) { return K::Point_3(a.V(i, 0), a.V(i, 1), a.V(i, 2)); };
    for(Eigen::Index f = 0; f < a.F.rows(); ++f) m_triangles.emplace_back(point(a.F(f, 0)), point(a.F(f, 1)), point(a.F(f, 2)));
    m_tree.insert(m_triangles.begin(), m_triangles.end());
    m_tree.build();
    m_tree.accelerate_distance_queries();
  }
  Closest_point_tree(const Closest_point_tree&) = delete; // the tree points into m_triangles
  Closest_point_tree& operator=(const Closest_point_tree&) = delete;

  Closest_point closest(const Eigen::Vector3d& q) const {
    const K::Point_3 p(q.x(), q.y(), q.z());
    const auto hit = m_tree.closest_point_and_primitive(p);
    Closest_point c;
    c.point = Eigen::Vector3d(hit.first.x(), hit.first.y(), hit.first.z());
    c.triangle = static_cast<std::size_t>(hit.second - m_triangles.begin());
    c.distance = (c.point - q).norm();
    return c;
  }
  double distance(const Eigen::Vector3d& q) const { return closest(q).distance; }
  std::size_t number_of_triangles() const { return m_triangles.size(); }

private:
  std::vector<K::Triangle_3> m_triangles;
  Tree m_tree;
};

} // namespace internal
} // namespace shapecorr

#endif
