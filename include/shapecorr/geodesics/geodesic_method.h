// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file geodesic_method.h
#ifndef SHAPECORR_GEODESICS_GEODESIC_METHOD_H
#define SHAPECORR_GEODESICS_GEODESIC_METHOD_H

#include <shapecorr/exceptions.h>

#include <string>

namespace shapecorr {

/// \ingroup PkgShapeCorrGeodesics
/// Which geodesic distance backend a one-call function builds (named parameter `geodesic_method`).
enum class Geodesic_method {
  HEAT,  ///< `Heat_method_geodesics`: fast, approximate (default)
  EXACT,         ///< `Exact_geodesics`: CGAL's exact shortest paths, the reference
  FAST_MARCHING  ///< `Fast_marching_geodesics`: fast marching, more accurate than heat, slower for all pairs
};

/// Parses "heat", "exact" or "fmm" (also "fast-marching").
inline Geodesic_method geodesic_method_from_string(const std::string& s) {
  if(s == "heat") return Geodesic_method::HEAT;
  if(s == "exact") return Geodesic_method::EXACT;
  if(s == "fmm" || s == "fast-marching") return Geodesic_method::FAST_MARCHING;
  throw Invalid_argument("unknown geodesic method '" + s + "' (expected heat, exact or fmm)");
}

} // namespace shapecorr

#endif
