// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file surface_distance.h
/// Distances between surfaces, the registration metrics of the thesis (ALGORITHMS.md, chapter 6):
/// with d(p, T) the distance from a point p to the surface T and |R| the area of R,
/// l1 = (1/|R|) ∫_R d(p, T) dp, l2 = sqrt((1/|R|) ∫_R d(p, T)² dp), lmax = max_{p ∈ R} d(p, T);
/// their symmetric versions, the distance of every vertex to the other surface, and landmark
/// distances.
#ifndef SHAPECORR_EVALUATION_SURFACE_DISTANCE_H
#define SHAPECORR_EVALUATION_SURFACE_DISTANCE_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/closest_point_tree.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/internal/surface_quadrature.h>
#include <shapecorr/parallel.h>
#include <shapecorr/parameters.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrEvaluation
/// One-sided distance from a surface R to a surface T (`surface_distance()`), in mesh units.
struct Surface_distance {
  double l1 = 0;   ///< (1/|R|) ∫_R d(p, T) dp: the mean distance
  double l2 = 0;   ///< sqrt((1/|R|) ∫_R d(p, T)² dp): the root mean square distance
  double lmax = 0; ///< max_{p ∈ R} d(p, T): the one-sided Hausdorff distance
  double area = 0; ///< |R|
  /// l1, l2 and lmax are each within this of the exact integrals and maximum (the quadrature's
  /// rigorous bound: d is 1-Lipschitz; where d is smooth the actual error is far smaller)
  double error_bound = 0;
  std::size_t samples = 0; ///< closest-point queries made
};

/// \ingroup PkgShapeCorrEvaluation
/// Distances in both directions and their combination (`symmetric_surface_distance()`).
struct Symmetric_surface_distance {
  Surface_distance forward;  ///< R to T
  Surface_distance backward; ///< T to R
  /// (∫_R d(p, T) + ∫_T d(q, R)) / (|R| + |T|): the mean over both surfaces
  double l1 = 0;
  /// sqrt((∫_R d(p, T)² + ∫_T d(q, R)²) / (|R| + |T|))
  double l2 = 0;
  /// max(forward.lmax, backward.lmax): the Hausdorff distance
  double lmax = 0;
};

namespace internal {
template <typename TriangleMesh, typename NamedParameters>
Triangle_arrays surface_arrays(const TriangleMesh& tm, const NamedParameters& np, const char* which) {
  return finite_triangle_arrays(tm, np, "surface distance", which);
}

template <typename NamedParameters>
double quadrature_step_of(const Triangle_arrays& R, const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double mean_edge = mean_edge_length(R);
  return choose_parameter(get_parameter(np, internal_np::quadrature_step), 0.25 * mean_edge);
}

inline Surface_distance to_surface_distance(const Surface_integrals& s) {
  Surface_distance d;
  d.l1 = s.mean;
  d.l2 = s.root_mean_square;
  d.lmax = s.maximum;
  d.area = s.area;
  d.error_bound = s.error_bound;
  d.samples = s.samples;
  return d;
}

template <typename NamedParameters>
Surface_distance one_sided_distance(const Triangle_arrays& R, const Triangle_arrays& T, const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Closest_point_tree tree(T);
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0u);
  return to_surface_distance(integrate_over_surface(R, quadrature_step_of(R, np), [&](const Eigen::Vector3d& p) { return tree.distance(p); }, threads));
}
} // namespace internal

/// \ingroup PkgShapeCorrEvaluation
/// The distances from the surface `R` to the surface `T` (thesis chapter 6: l1, l2, lmax), in
/// mesh units. d(p, T) is the exact distance to T's triangles (closest points through CGAL's AABB
/// tree). The integrals over R use the composite midpoint rule: every triangle of R is cut into
/// s × s congruent sub-triangles with edges at most `quadrature_step`, and d is evaluated at their
/// centroids (lmax also at the vertices). Since d is 1-Lipschitz, l1, l2 and lmax are each within
/// `error_bound` (the largest centroid-to-corner distance of a sub-triangle, reported) of their
/// exact values; on smooth parts the error is O(step²).
///
/// `R` and `T` may be of different mesh types.
///
/// | named parameter (np1: R, np2: T) | meaning | type | default |
/// |---|---|---|---|
/// | `vertex_point_map` | positions | `ReadablePropertyMap` | the mesh's |
/// | `vertex_index_map` | vertex indices | `ReadablePropertyMap` | the mesh's, or a fresh one |
/// | `quadrature_step` (np1) | longest sub-triangle edge, mesh units | `double` | 1/4 of R's mean edge length |
/// | `number_of_threads` (np1) | threads for the queries (0: all) | `unsigned` | 0 |
///
/// Cost: building the tree over T, O(m_T log m_T); one query per sample, about
/// 2 (s² + 1.5) per triangle of R.
/// \throws Invalid_input when a mesh has no triangle or a non-finite coordinate, or R has zero
///         area; Invalid_argument for a step that is not positive
/// \code
///   const shapecorr::Surface_distance d = shapecorr::surface_distance(fitted, target);
///   std::cout << d.l1 << " " << d.l2 << " " << d.lmax << " (within " << d.error_bound << ")\n";
/// \endcode
template <typename TriangleMeshR, typename TriangleMeshT, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Surface_distance surface_distance(const TriangleMeshR& R, const TriangleMeshT& T,
                                  const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                  const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  return internal::one_sided_distance(internal::surface_arrays(R, np1, "R"), internal::surface_arrays(T, np2, "T"), np1);
}

/// \ingroup PkgShapeCorrEvaluation
/// `surface_distance()` in both directions (R to T with np1's quadrature step, T to R with np2's)
/// and the combinations of `Symmetric_surface_distance`.
/// \throws as `surface_distance()`
template <typename TriangleMeshR, typename TriangleMeshT, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Symmetric_surface_distance symmetric_surface_distance(const TriangleMeshR& R, const TriangleMeshT& T,
                                                      const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                                      const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  const internal::Triangle_arrays a = internal::surface_arrays(R, np1, "R"), b = internal::surface_arrays(T, np2, "T");
  Symmetric_surface_distance s;
  s.forward = internal::one_sided_distance(a, b, np1);
  s.backward = internal::one_sided_distance(b, a, np2);
  const double area = s.forward.area + s.backward.area;
  s.l1 = (s.forward.l1 * s.forward.area + s.backward.l1 * s.backward.area) / area;
  s.l2 = std::sqrt((s.forward.l2 * s.forward.l2 * s.forward.area + s.backward.l2 * s.backward.l2 * s.backward.area) / area);
  s.lmax = std::max(s.forward.lmax, s.backward.lmax);
  return s;
}

/// \ingroup PkgShapeCorrEvaluation
/// The distance from every vertex of `R` to the surface `T`, written into `distances` (a
/// `WritablePropertyMap` from R's `vertex_descriptor` to `double`): the map to colour a fitted
/// template by its residual.
/// \param np1 `vertex_point_map`, `vertex_index_map`, `number_of_threads` of R
/// \param np2 `vertex_point_map`, `vertex_index_map` of T
/// \throws Invalid_input when T has no triangle or a coordinate is not finite
template <typename TriangleMeshR, typename TriangleMeshT, typename VertexDistanceMap,
          typename NamedParameters1 = parameters::Default_named_parameters, typename NamedParameters2 = parameters::Default_named_parameters>
void compute_distances_to_surface(const TriangleMeshR& R, const TriangleMeshT& T, VertexDistanceMap distances,
                                  const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                  const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const internal::Indexed_mesh<TriangleMeshR> r(R, np1);
  const internal::Closest_point_tree tree(internal::surface_arrays(T, np2, "T"));
  std::vector<double> d(r.number_of_vertices());
  parallel_for(d.size(), choose_parameter(get_parameter(np1, internal_np::number_of_threads), 0u),
               [&](std::size_t i, unsigned) { d[i] = tree.distance(r.arrays().point(i)); });
  for(std::size_t i = 0; i < d.size(); ++i) put(distances, r.vertex(i), d[i]);
}

/// \ingroup PkgShapeCorrEvaluation
/// Euclidean distances between corresponding landmarks: `result[i] = |a[i] − b[i]|`. Points are
/// any type with `x()`, `y()`, `z()` (a CGAL kernel's `Point_3`).
/// \throws Invalid_argument when the two lists differ in length or a coordinate is not finite
template <typename PointRangeA, typename PointRangeB>
std::vector<double> landmark_distances(const PointRangeA& a, const PointRangeB& b) {
  const std::size_t n = static_cast<std::size_t>(std::distance(a.begin(), a.end()));
  if(n != static_cast<std::size_t>(std::distance(b.begin(), b.end())))
    throw Invalid_argument("landmark_distances: " + std::to_string(n) + " landmarks against " +
                           std::to_string(std::distance(b.begin(), b.end())));
  std::vector<double> d;
  d.reserve(n);
  auto ib = b.begin();
  std::size_t i = 0;
  for(auto ia = a.begin(); ia != a.end(); ++ia, ++ib, ++i) {
    const double dx = CGAL::to_double(ia->x()) - CGAL::to_double(ib->x()), dy = CGAL::to_double(ia->y()) - CGAL::to_double(ib->y()),
                 dz = CGAL::to_double(ia->z()) - CGAL::to_double(ib->z());
    d.push_back(std::sqrt(dx * dx + dy * dy + dz * dz));
    if(!std::isfinite(d.back())) throw Invalid_argument("landmark_distances: landmark " + std::to_string(i) + " has a non-finite coordinate");
  }
  return d;
}

} // namespace shapecorr

#endif
