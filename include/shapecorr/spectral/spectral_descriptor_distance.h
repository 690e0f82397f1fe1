// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file spectral_descriptor_distance.h
#ifndef SHAPECORR_SPECTRAL_SPECTRAL_DESCRIPTOR_DISTANCE_H
#define SHAPECORR_SPECTRAL_SPECTRAL_DESCRIPTOR_DISTANCE_H

#include <shapecorr/exceptions.h>

#include <cmath>
#include <iterator>

namespace shapecorr {

/// \ingroup PkgShapeCorrSpectral
/// The distance between two spectral descriptors (HKS, WKS, SI-HKS) of equal length: the Euclidean
/// (L2) norm of their difference. With the default `normalize_per_scale(true)` of HKS and WKS every
/// scale enters with the same weight (each was divided by its mean over its own surface).
/// \tparam Range a range of `double` (`std::vector<double>`, an Eigen vector...)
/// \throws Invalid_argument when the lengths differ
template <typename Range1, typename Range2>
double spectral_descriptor_distance(const Range1& a, const Range2& b) {
  auto ia = std::begin(a);
  auto ib = std::begin(b);
  double s = 0;
  for(; ia != std::end(a) && ib != std::end(b); ++ia, ++ib) {
    const double d = static_cast<double>(*ia) - static_cast<double>(*ib);
    s += d * d;
  }
  if(ia != std::end(a) || ib != std::end(b))
    throw Invalid_argument("spectral descriptor distance: descriptors of different lengths");
  return std::sqrt(s);
}

} // namespace shapecorr

#endif
