// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: run a piece of work with the geodesic engine the named parameters ask for: the one
// passed as `geodesic_engine(&engine)`, or a fresh engine of the `geodesic_method` requested.
#ifndef SHAPECORR_GEODESICS_INTERNAL_WITH_GEODESIC_ENGINE_H
#define SHAPECORR_GEODESICS_INTERNAL_WITH_GEODESIC_ENGINE_H

#include <shapecorr/internal/progress.h>
#include <shapecorr/geodesics/Exact_geodesics.h>
#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/geodesics/Heat_method_geodesics.h>
#include <shapecorr/geodesics/geodesic_method.h>
#include <shapecorr/parameters.h>

#include <type_traits>

namespace shapecorr {
namespace internal {

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

} // namespace internal
} // namespace shapecorr

#endif
