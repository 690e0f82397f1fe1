// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file compute_geodesic_distances.h
#ifndef SHAPECORR_GEODESICS_COMPUTE_GEODESIC_DISTANCES_H
#define SHAPECORR_GEODESICS_COMPUTE_GEODESIC_DISTANCES_H

#include <shapecorr/geodesics/with_geodesic_engine.h>

#include <type_traits>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrGeodesics
/// Geodesic distance from every vertex of `tm` to the nearest of `sources` (one-call version of
/// the engines; to query many times, build an engine once and pass it as `geodesic_engine`).
/// \tparam VertexRange a range of `vertex_descriptor` (or a single `vertex_descriptor`)
/// \tparam VertexDistanceMap a `WritablePropertyMap` with key `vertex_descriptor` and value `double`
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `geodesic_method` | `HEAT` (fast, approximate), `EXACT` (CGAL shortest paths), `FAST_MARCHING` | `Geodesic_method` | `HEAT` |
/// | `geodesic_engine` | reuse a precomputed engine | pointer to a `GeodesicDistanceEngine` | none |
/// | `vertex_point_map`, `vertex_index_map`, heat parameters | see `Heat_method_geodesics` | | |
/// Distances to vertices of components without a source are `+infinity`.
template <typename TriangleMesh, typename VertexRange, typename VertexDistanceMap,
          typename NamedParameters = parameters::Default_named_parameters>
void compute_geodesic_distances(const TriangleMesh& tm, const VertexRange& sources, VertexDistanceMap distance_map,
                                const NamedParameters& np = CGAL::parameters::default_values()) {
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  if constexpr(std::is_convertible<VertexRange, vertex_descriptor>::value) {
    const std::vector<vertex_descriptor> one{sources};
    compute_geodesic_distances(tm, one, distance_map, np);
  } else {
    with_geodesic_engine(tm, np, [&](const auto& engine) {
      engine.compute_geodesic_distances(sources, distance_map);
      return 0;
    });
  }
}

} // namespace shapecorr

#endif
