// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file match_descriptors.h
/// Nearest-descriptor matching for any descriptor type: the nearest with the nearest /
/// second-nearest ratio, the k nearest, and the distances from one descriptor to a set.
#ifndef SHAPECORR_DESCRIPTORS_MATCH_DESCRIPTORS_H
#define SHAPECORR_DESCRIPTORS_MATCH_DESCRIPTORS_H

#include <shapecorr/parallel.h>

#include <shapecorr/exceptions.h>

#include <algorithm>
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

// Pointers to the elements of a range, for random access by position.
template <typename Range>
std::vector<const typename Range::value_type*> element_pointers(const Range& r) {
  std::vector<const typename Range::value_type*> v;
  for(const auto& d : r) v.push_back(&d);
  return v;
}
} // namespace internal

/// \ingroup PkgShapeCorrDescriptors
/// The result of matching one source descriptor against a set of target descriptors.
struct Descriptor_match {
  std::size_t source = 0;          ///< position in the source range
  std::size_t target = 0;          ///< position of the nearest target descriptor
  double distance = std::numeric_limits<double>::infinity();        ///< its distance
  double second_distance = std::numeric_limits<double>::infinity(); ///< distance of the second nearest
  /// False when no target has a finite distance to the source ("no descriptor": an empty spin
  /// contour, say): then `target` means nothing and `distance` is infinite.
  bool has_match() const { return std::isfinite(distance); }
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
/// Distances that are not finite (an empty descriptor against a non-empty one, e.g. the spin
/// contour of a flat neighbourhood: "no descriptor") are skipped; a source with no finite
/// distance to any target gets `has_match() == false`.
template <typename SourceRange, typename TargetRange, typename Distance>
std::vector<Descriptor_match> match_descriptors(const SourceRange& sources, const TargetRange& targets, const Distance& distance,
                                                unsigned threads = 0) {
  const auto s = internal::element_pointers(sources);
  const auto t = internal::element_pointers(targets);
  std::vector<Descriptor_match> out(s.size());
  parallel_for(s.size(), resolve_thread_count(threads), [&](std::size_t i, unsigned) {
    Descriptor_match m;
    m.source = i;
    for(std::size_t j = 0; j < t.size(); ++j) {
      // Only distances below the second best matter: functors with a bound may stop early.
      const double d = internal::bounded_distance(distance, *s[i], *t[j], m.second_distance, 0);
      if(!std::isfinite(d)) continue;
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

/// \ingroup PkgShapeCorrDescriptors
/// One of the k nearest target descriptors of a source descriptor.
struct Descriptor_neighbor {
  std::size_t target = 0;                                    ///< position in the target range
  double distance = std::numeric_limits<double>::infinity(); ///< its descriptor distance
};

/// \ingroup PkgShapeCorrDescriptors
/// The `k` nearest elements of `targets` for each of `sources`, by `distance(s, t)`: row i lists
/// them by increasing distance (ties: the lower position first), `min(k, targets.size())` of
/// them. Candidate lists for correspondence search (several plausible matches per point) rather
/// than one match. Same distance functors and threads as `match_descriptors`; a functor with a
/// bounded form is called with the current k-th distance (same result, less work). With `k = 2`,
/// entries 0 and 1 are `match_descriptors`' nearest and second nearest. Targets at a distance that
/// is not finite ("no descriptor", as in `match_descriptors`) are never candidates, so a row may be
/// shorter than `min(k, targets.size())`, or empty.
/// Cost: sources x targets distances, O(log k) bookkeeping each.
/// \throws Invalid_argument when `k` is 0
/// \code
///   auto candidates = shapecorr::k_nearest_descriptors(source_contours, target_contours, shapecorr::Contour_l1_distance(), 5);
///   for(const shapecorr::Descriptor_neighbor& n : candidates[0]) use(n.target, n.distance);
/// \endcode
template <typename SourceRange, typename TargetRange, typename Distance>
std::vector<std::vector<Descriptor_neighbor>> k_nearest_descriptors(const SourceRange& sources, const TargetRange& targets,
                                                                    const Distance& distance, std::size_t k, unsigned threads = 0) {
  if(k == 0) throw Invalid_argument("k_nearest_descriptors: k must be at least 1");
  const auto s = internal::element_pointers(sources);
  const auto t = internal::element_pointers(targets);
  const std::size_t kk = std::min(k, t.size());
  // (distance, position) pairs: a max-heap of the kk best so far, its top the kk-th
  auto before = [](const Descriptor_neighbor& a, const Descriptor_neighbor& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.target < b.target);
  };
  std::vector<std::vector<Descriptor_neighbor>> out(s.size());
  parallel_for(s.size(), resolve_thread_count(threads), [&](std::size_t i, unsigned) {
    std::vector<Descriptor_neighbor> heap;
    heap.reserve(kk + 1);
    for(std::size_t j = 0; j < t.size(); ++j) {
      const double bound = heap.size() < kk ? std::numeric_limits<double>::infinity() : heap.front().distance;
      const Descriptor_neighbor c{j, internal::bounded_distance(distance, *s[i], *t[j], bound, 0)};
      if(!std::isfinite(c.distance)) continue;
      if(heap.size() < kk) {
        heap.push_back(c);
        std::push_heap(heap.begin(), heap.end(), before);
      } else if(before(c, heap.front())) {
        std::pop_heap(heap.begin(), heap.end(), before);
        heap.back() = c;
        std::push_heap(heap.begin(), heap.end(), before);
      }
    }
    std::sort_heap(heap.begin(), heap.end(), before);
    out[i] = std::move(heap);
  });
  return out;
}

/// \ingroup PkgShapeCorrDescriptors
/// The distance from `query` to every element of `targets` (in their order), in parallel: a
/// descriptor's distance map over a shape, for pictures of where a point's descriptor matches.
template <typename Descriptor, typename TargetRange, typename Distance>
std::vector<double> descriptor_distances(const Descriptor& query, const TargetRange& targets, const Distance& distance,
                                         unsigned threads = 0) {
  const auto t = internal::element_pointers(targets);
  std::vector<double> d(t.size());
  parallel_for(t.size(), resolve_thread_count(threads), [&](std::size_t j, unsigned) { d[j] = distance(query, *t[j]); });
  return d;
}

} // namespace shapecorr

#endif
