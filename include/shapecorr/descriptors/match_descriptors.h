// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file match_descriptors.h
/// Nearest-descriptor matching with the nearest / second-nearest ratio, for any descriptor type.
#ifndef SHAPECORR_DESCRIPTORS_MATCH_DESCRIPTORS_H
#define SHAPECORR_DESCRIPTORS_MATCH_DESCRIPTORS_H

#include <shapecorr/internal/parallel.h>

#include <cmath>
#include <limits>
#include <vector>

namespace shapecorr {
namespace internal {
// distance(a, b, bound) when the functor offers an early-exit form, distance(a, b) otherwise.
template <typename Distance, typename A, typename B>
auto bounded_distance(const Distance& d, const A& a, const B& b, double bound, int) -> decltype(d(a, b, bound)) {
  return d(a, b, bound);
}
template <typename Distance, typename A, typename B>
double bounded_distance(const Distance& d, const A& a, const B& b, double, long) {
  return d(a, b);
}
} // namespace internal

/// \ingroup PkgShapeCorrDescriptors
/// The result of matching one source descriptor against a set of target descriptors.
struct Descriptor_match {
  std::size_t source = 0;          ///< position in the source range
  std::size_t target = 0;          ///< position of the nearest target descriptor
  double distance = std::numeric_limits<double>::infinity();        ///< its distance
  double second_distance = std::numeric_limits<double>::infinity(); ///< distance of the second nearest
  /// nearest / second-nearest distance (Lowe's ratio; 1 when undefined, e.g. a single target)
  double ratio() const {
    return second_distance > 0 && std::isfinite(second_distance) ? distance / second_distance : 1.0;
  }
};

/// \ingroup PkgShapeCorrDescriptors
/// Matches each of `sources` to the element of `targets` at the smallest `distance(s, t)` (ties:
/// the lower position), recording the second smallest too. Generic over the descriptor type:
/// `Contour_l1_distance` for spin contours, `Spin_image_distance` for spin images,
/// `spectral_descriptor_distance` wrapped in a lambda for HKS/WKS... Runs on `threads` threads (0 = all).
/// A functor that also offers `distance(s, t, bound)` (returning any value > bound once the
/// distance is known to exceed it, as `Contour_l1_distance` does) is called that way with the
/// current second-best distance: same matches, less work.
template <typename SourceRange, typename TargetRange, typename Distance>
std::vector<Descriptor_match> match_descriptors(const SourceRange& sources, const TargetRange& targets, const Distance& distance,
                                                unsigned threads = 0) {
  const std::vector<const typename SourceRange::value_type*> s = [&] {
    std::vector<const typename SourceRange::value_type*> v;
    for(const auto& d : sources) v.push_back(&d);
    return v;
  }();
  std::vector<const typename TargetRange::value_type*> t;
  for(const auto& d : targets) t.push_back(&d);
  std::vector<Descriptor_match> out(s.size());
  internal::parallel_for(s.size(), internal::resolve_thread_count(threads), [&](std::size_t i, unsigned) {
    Descriptor_match m;
    m.source = i;
    for(std::size_t j = 0; j < t.size(); ++j) {
      // Only distances below the second best matter: functors with a bound may stop early.
      const double d = internal::bounded_distance(distance, *s[i], *t[j], m.second_distance, 0);
      if(d < m.distance) {
        m.second_distance = m.distance;
        m.distance = d;
        m.target = j;
      } else if(d < m.second_distance)
        m.second_distance = d;
    }
    out[i] = m;
  });
  return out;
}

} // namespace shapecorr

#endif
