// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file with_geodesic_engine.h
/// Runs a piece of work with the geodesic engine that named parameters ask for.
#ifndef SHAPECORR_GEODESICS_WITH_GEODESIC_ENGINE_H
#define SHAPECORR_GEODESICS_WITH_GEODESIC_ENGINE_H

#include <shapecorr/internal/progress.h>
#include <shapecorr/geodesics/Exact_geodesics.h>
#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/geodesics/Heat_method_geodesics.h>
#include <shapecorr/geodesics/geodesic_method.h>
#include <shapecorr/parameters.h>

#include <type_traits>

namespace shapecorr {

/// \ingroup PkgShapeCorrGeodesics
/// Calls `fn(engine)` with the geodesic distance engine (a model of `GeodesicDistanceEngine`, see
/// doc/concepts.md) that `np` asks for: the one passed as `parameters::geodesic_engine(&engine)`,
/// else a fresh `Exact_geodesics`, `Fast_marching_geodesics` or `Heat_method_geodesics` of `tm`
/// built with `np`, as `parameters::geodesic_method` names (default: `default_method`). This is how
/// every ShapeCorr function that needs distances chooses its engine; algorithms written on top of
/// the library use it to accept the same parameters.
/// \tparam Fn a callable accepting each engine type by const reference; its return type must be
///   the same for all of them
/// \param np optional named parameters: `geodesic_engine`, `geodesic_method`, and the chosen
///   engine's own parameters (`vertex_point_map`, `vertex_index_map`, `time_step_factor`, ...)
/// \returns what `fn` returns
/// \code
///   double d = shapecorr::with_geodesic_engine(tm, SP::geodesic_method(shapecorr::Geodesic_method::EXACT),
///       [](const auto& engine) { return engine.distances_from(0).maxCoeff(); });
/// \endcode
template <typename TriangleMesh, typename NamedParameters, typename Fn>
decltype(auto) with_geodesic_engine(const TriangleMesh& tm, const NamedParameters& np, Fn&& fn,
                                    Geodesic_method default_method = Geodesic_method::HEAT) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto given = get_parameter(np, internal_np::geodesic_engine);
  if constexpr(!std::is_same<decltype(given), CGAL::internal_np::Param_not_found>::value) {
    static_assert(std::is_pointer<decltype(given)>::value,
                  "geodesic_engine expects a pointer to an engine: parameters::geodesic_engine(&engine)");
    return fn(*given);
  } else {
    const Geodesic_method method = choose_parameter(get_parameter(np, internal_np::geodesic_method), default_method);
    if(method == Geodesic_method::EXACT) {
      Exact_geodesics<TriangleMesh, typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type> engine(tm, np);
      return fn(engine);
    }
    if(method == Geodesic_method::FAST_MARCHING) {
      Fast_marching_geodesics<TriangleMesh> engine(tm, np);
      return fn(engine);
    }
    Heat_method_geodesics<TriangleMesh> engine(tm, np);
    return fn(engine);
  }
}

} // namespace shapecorr

#endif
