// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file geodesic_diameter.h
#ifndef SHAPECORR_GEODESICS_GEODESIC_DIAMETER_H
#define SHAPECORR_GEODESICS_GEODESIC_DIAMETER_H

#include <shapecorr/geodesics/with_geodesic_engine.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace shapecorr {
namespace internal {

/// Iterated farthest-point sweeps: from a vertex, jump to the farthest vertex, repeat until the
/// eccentricity stops growing. Returns the largest finite distance seen (a lower bound on the
/// diameter, equal to it on most shapes) and the two vertices realizing it.
template <typename GeodesicDistanceEngine>
double diameter_by_sweeps(const GeodesicDistanceEngine& engine, std::size_t start, int max_sweeps,
                          std::size_t* end_a = nullptr, std::size_t* end_b = nullptr) {
  double best = 0;
  std::size_t cur = start, a = start, b = start;
  for(int sweep = 0; sweep < max_sweeps; ++sweep) {
    const Eigen::VectorXd d = engine.distances_from(cur);
    std::size_t far = cur;
    double dmax = -1;
    for(Eigen::Index i = 0; i < d.size(); ++i)
      if(std::isfinite(d[i]) && d[i] > dmax) { dmax = d[i]; far = static_cast<std::size_t>(i); }
    if(dmax <= best * (1 + 1e-9)) break;
    best = dmax;
    a = cur;
    b = far;
    cur = far;
  }
  if(end_a) *end_a = a;
  if(end_b) *end_b = b;
  return best;
}

/// The vertex farthest from the vertices' centroid: a start for the sweeps that does not depend
/// on the numbering of the vertices.
inline std::size_t canonical_start_vertex(const Triangle_arrays& a) {
  if(a.V.rows() == 0) return 0;
  const Eigen::RowVector3d c = a.V.colwise().mean();
  Eigen::Index far = 0;
  (a.V.rowwise() - c).rowwise().squaredNorm().maxCoeff(&far);
  return static_cast<std::size_t>(far);
}

} // namespace internal

/// \ingroup PkgShapeCorrGeodesics
/// Geodesic diameter D: the largest geodesic distance between two vertices (within a component).
/// Computed by iterated farthest-point sweeps (each one a single-source query) from the vertex
/// farthest from the centroid (independent of the vertex numbering); exact for the
/// chosen backend on convex-like and elongated shapes, a lower bound in general. For the exact
/// maximum over all pairs use `Geodesic_distance_matrix::diameter()`.
/// \param np `geodesic_method`, `geodesic_engine`, `number_of_iterations` (sweeps, default 6),
///        and the engine's parameters
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double geodesic_diameter(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const int sweeps = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 6);
  return with_geodesic_engine(tm, np, [&](const auto& engine) {
    return internal::diameter_by_sweeps(engine, internal::canonical_start_vertex(engine.arrays()), sweeps);
  });
}

} // namespace shapecorr

#endif
