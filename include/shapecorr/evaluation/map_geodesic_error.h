// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file map_geodesic_error.h
/// The geodesic error of a correspondence at ground-truth pairs (the Princeton protocol of Kim,
/// Lipman and Funkhouser 2011): per pair, the geodesic distance on the target between where the
/// map sends the source point and where it should go, divided by the square root of the target's
/// area; summaries and the cumulative curve.
#ifndef SHAPECORR_EVALUATION_MAP_GEODESIC_ERROR_H
#define SHAPECORR_EVALUATION_MAP_GEODESIC_ERROR_H

#include <shapecorr/exceptions.h>
#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/geodesics/average_geodesic_distance.h>
#include <shapecorr/parallel.h>
#include <shapecorr/parameters.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrEvaluation
/// The geodesic errors of several correspondences at the same ground-truth target vertices:
/// `errors[l][k]` = g(`found[l][k]`, `truth[k]`) / sqrt(area of `target`), g the fast-marching
/// geodesic distance on `target` (0-based vertex indices of the vertex index map). Typical lists:
/// a map's image of the true pairs' source points (`found[0][k] = map[source_k]`) and of their
/// mirror images (`found[1][k] = map[mirror_k]`: an intrinsic method may return the left-right
/// flipped map), or the maps of several methods. One single-source fast marching per distinct
/// true vertex serves every list (the fields are not kept), in parallel.
/// \param np `vertex_point_map`, `vertex_index_map`, `number_of_threads` (0: all)
/// \throws Invalid_argument when a list's length differs from `truth`'s or an index is out of range
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<std::vector<double>> map_geodesic_errors(const TriangleMesh& target, const std::vector<std::size_t>& truth,
                                                     const std::vector<std::vector<std::size_t>>& found,
                                                     const NamedParameters& np = CGAL::parameters::default_values()) {
  const Fast_marching_geodesics<TriangleMesh> engine(target, np);
  const std::size_t n = engine.number_of_vertices();
  for(const auto& list : found)
    if(list.size() != truth.size())
      throw Invalid_argument("map geodesic errors: a list has " + std::to_string(list.size()) + " vertices, the truth " + std::to_string(truth.size()));
  for(std::size_t k = 0; k < truth.size(); ++k) {
    bool ok = truth[k] < n;
    for(const auto& list : found) ok = ok && list[k] < n;
    if(!ok) throw Invalid_argument("map geodesic errors: pair " + std::to_string(k) + " names a vertex the target does not have");
  }
  const double area = internal::incident_triangle_areas(engine.arrays()).sum() / 3.0; // (each triangle counted at its 3 corners)
  if(!(area > 0) || !std::isfinite(area)) throw Invalid_argument("map geodesic errors: the target has no area");
  const double scale = 1.0 / std::sqrt(area);
  std::map<std::size_t, std::vector<std::size_t>> pairs_of; // true vertex -> the pairs that name it
  for(std::size_t k = 0; k < truth.size(); ++k) pairs_of[truth[k]].push_back(k);
  std::vector<const std::pair<const std::size_t, std::vector<std::size_t>>*> groups;
  for(const auto& g : pairs_of) groups.push_back(&g);
  std::vector<std::vector<double>> errors(found.size(), std::vector<double>(truth.size(), 0.0));
  parallel_for(groups.size(), engine.number_of_threads(), [&](std::size_t i, unsigned) {
    const Eigen::VectorXd field = engine.distances_from(groups[i]->first);
    for(std::size_t l = 0; l < found.size(); ++l)
      for(std::size_t k : groups[i]->second) errors[l][k] = field[Eigen::Index(found[l][k])] * scale; // (distinct k per group)
  });
  return errors;
}

/// \ingroup PkgShapeCorrEvaluation
/// Mean, largest and the fraction of errors at most `threshold` of a list of errors.
struct Map_error_summary {
  std::size_t pairs = 0;         ///< number of errors
  double mean = 0;               ///< mean error
  double largest = 0;            ///< largest error
  double fraction_within = 0;    ///< fraction of errors <= threshold
  double threshold = 0.25;       ///< the threshold of `fraction_within`
};

/// \ingroup PkgShapeCorrEvaluation
/// The summary of `errors` (all zero for an empty list).
inline Map_error_summary summarize_map_errors(const std::vector<double>& errors, double threshold = 0.25) {
  Map_error_summary s;
  s.threshold = threshold;
  s.pairs = errors.size();
  if(errors.empty()) return s;
  std::size_t within = 0;
  for(double e : errors) {
    s.mean += e;
    s.largest = std::max(s.largest, e);
    within += e <= threshold ? 1 : 0;
  }
  s.mean /= double(errors.size());
  s.fraction_within = double(within) / double(errors.size());
  return s;
}

/// \ingroup PkgShapeCorrEvaluation
/// The cumulative curve of the Princeton protocol: for each of `steps` + 1 thresholds evenly
/// spaced over [0, `largest`], the fraction of errors at most that threshold (curve[i] at
/// threshold i x largest / steps).
/// \throws Invalid_argument when steps is 0 or largest is not positive
inline std::vector<double> cumulative_error_curve(std::vector<double> errors, double largest = 0.25, std::size_t steps = 50) {
  if(steps == 0 || !(largest > 0)) throw Invalid_argument("cumulative error curve: need steps > 0 and a positive largest threshold");
  std::sort(errors.begin(), errors.end());
  std::vector<double> curve(steps + 1, 0.0);
  for(std::size_t i = 0; i <= steps; ++i) {
    const double t = largest * double(i) / double(steps);
    const auto count = std::upper_bound(errors.begin(), errors.end(), t) - errors.begin();
    curve[i] = errors.empty() ? 0.0 : double(count) / double(errors.size());
  }
  return curve;
}

} // namespace shapecorr

#endif
