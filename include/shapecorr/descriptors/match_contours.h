// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file match_contours.h
/// Matching spin contours (rigid or geodesic) with the comparison strategy chosen for the job.
#ifndef SHAPECORR_DESCRIPTORS_MATCH_CONTOURS_H
#define SHAPECORR_DESCRIPTORS_MATCH_CONTOURS_H

#include <shapecorr/descriptors/Contour_distance_field.h>
#include <shapecorr/descriptors/Contour_nearest_point_index.h>
#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/match_descriptors.h>
#include <shapecorr/exceptions.h>
#include <shapecorr/parallel.h>

#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// How contours are compared when many are matched (all give the contour L1 distance of thesis
/// section 3.4; they differ in preparation and cost).
enum class Contour_comparison {
  AUTOMATIC,           ///< `EXACT` for fewer than `indexed_contour_matching_threshold` sources, else `NEAREST_POINT_INDEX`: the exact distances, at the lower cost
  EXACT,               ///< `contour_l1_distance` on the contours as they are (no preparation)
  NEAREST_POINT_INDEX, ///< contours prepared as `Contour_nearest_point_index`: the same distances bit for bit, each comparison O(points) instead of a binary search per point
  DISTANCE_FIELD       ///< contours prepared as `Contour_distance_field`: approximate distances (at most `error_bound()` off, 1/240 with the default 121 samples), each comparison about half an indexed one
};

/// \ingroup PkgShapeCorrDescriptors
/// From this many sources on, `AUTOMATIC` prepares nearest-point indices: preparing a contour's
/// index costs about as much as a few tens of exact comparisons, so it pays off when each target
/// contour is compared with at least that many sources.
constexpr std::size_t indexed_contour_matching_threshold = 32;

/// \ingroup PkgShapeCorrDescriptors
/// Parses "automatic", "exact", "index" or "fields".
/// \throws Invalid_argument for any other name
inline Contour_comparison contour_comparison_from_string(const std::string& s) {
  if(s == "automatic") return Contour_comparison::AUTOMATIC;
  if(s == "exact") return Contour_comparison::EXACT;
  if(s == "index") return Contour_comparison::NEAREST_POINT_INDEX;
  if(s == "fields") return Contour_comparison::DISTANCE_FIELD;
  throw Invalid_argument("unknown contour comparison '" + s + "' (expected automatic, exact, index or fields)");
}

/// \ingroup PkgShapeCorrDescriptors
/// Each contour prepared for many comparisons (`Prepared` is `Contour_nearest_point_index` or
/// `Contour_distance_field`, built with its default resolution), in parallel on `threads` threads
/// (0 = all).
template <typename Prepared>
std::vector<Prepared> prepare_contours(const std::vector<Spin_contour>& contours, unsigned threads = 0) {
  std::vector<Prepared> prepared(contours.size());
  parallel_for(contours.size(), resolve_thread_count(threads), [&](std::size_t i, unsigned) { prepared[i] = Prepared(contours[i]); });
  return prepared;
}

namespace internal {
// fn(sources, targets, distance) with the contours prepared as `how` asks.
template <typename Fn>
decltype(auto) with_contour_comparison(const std::vector<Spin_contour>& sources, const std::vector<Spin_contour>& targets,
                                       Contour_comparison how, unsigned threads, Fn&& fn) {
  if(how == Contour_comparison::AUTOMATIC)
    how = sources.size() < indexed_contour_matching_threshold ? Contour_comparison::EXACT : Contour_comparison::NEAREST_POINT_INDEX;
  if(how == Contour_comparison::NEAREST_POINT_INDEX)
    return fn(prepare_contours<Contour_nearest_point_index>(sources, threads), prepare_contours<Contour_nearest_point_index>(targets, threads),
              Indexed_contour_l1_distance());
  if(how == Contour_comparison::DISTANCE_FIELD)
    return fn(prepare_contours<Contour_distance_field>(sources, threads), prepare_contours<Contour_distance_field>(targets, threads),
              Approximate_contour_l1_distance());
  return fn(sources, targets, Contour_l1_distance());
}
} // namespace internal

/// \ingroup PkgShapeCorrDescriptors
/// `match_descriptors` for spin contours: each source matched to the target contour at the
/// smallest contour L1 distance (and the second nearest), the contours compared as `how` says.
/// All contours must have the same rows (the same descriptor settings).
/// \throws Invalid_argument when two contours have different rows
/// \code
///   auto matches = shapecorr::match_contours(source_contours, target_contours);  // exact distances, fastest way
/// \endcode
inline std::vector<Descriptor_match> match_contours(const std::vector<Spin_contour>& sources, const std::vector<Spin_contour>& targets,
                                                    Contour_comparison how = Contour_comparison::AUTOMATIC, unsigned threads = 0) {
  return internal::with_contour_comparison(sources, targets, how, threads, [&](const auto& s, const auto& t, const auto& distance) {
    return match_descriptors(s, t, distance, threads);
  });
}

/// \ingroup PkgShapeCorrDescriptors
/// `k_nearest_descriptors` for spin contours: the `k` nearest target contours of each source by
/// increasing contour L1 distance, the contours compared as `how` says.
/// \throws Invalid_argument when `k` is 0 or two contours have different rows
inline std::vector<std::vector<Descriptor_neighbor>> k_nearest_contours(const std::vector<Spin_contour>& sources,
                                                                        const std::vector<Spin_contour>& targets, std::size_t k,
                                                                        Contour_comparison how = Contour_comparison::AUTOMATIC,
                                                                        unsigned threads = 0) {
  return internal::with_contour_comparison(sources, targets, how, threads, [&](const auto& s, const auto& t, const auto& distance) {
    return k_nearest_descriptors(s, t, distance, k, threads);
  });
}

} // namespace shapecorr

#endif
