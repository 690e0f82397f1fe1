// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file descriptor_ranking.h
/// The thesis's descriptor evaluation for near-isometric shapes (ALGORITHMS.md, chapter 4): every
/// source point ranks all N target vertices by descriptor distance; the hit rate and the average
/// geodesic error as functions of k (plotted against 100 k / N).
#ifndef SHAPECORR_EVALUATION_DESCRIPTOR_RANKING_H
#define SHAPECORR_EVALUATION_DESCRIPTOR_RANKING_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parallel.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <mutex>
#include <numeric>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrEvaluation
/// Hit rate and average geodesic error of a descriptor as functions of k = 1..N.
struct Ranking_curves {
  std::size_t number_of_sources = 0; ///< source points ranked
  std::size_t number_of_targets = 0; ///< N
  /// hit_rate[k-1]: fraction of source points whose true match is among their k nearest targets
  std::vector<double> hit_rate;
  /// geodesic_error[k-1]: mean over source points of the mean geodesic distance (on the target,
  /// divided by the normalization, e.g. sqrt(area)) from their k nearest targets to the true match
  std::vector<double> geodesic_error;
  /// The hit rate counting the symmetric counterpart of the true match as correct too (empty
  /// unless a symmetric ground truth was given)
  std::vector<double> hit_rate_symmetric;
  /// The geodesic error to the nearer of the true match and its symmetric counterpart (empty
  /// unless a symmetric ground truth was given)
  std::vector<double> geodesic_error_symmetric;
  /// The k of a percentage of the targets: max(1, round(percent N / 100)).
  std::size_t k_of_percent(double percent) const {
    const double k = std::round(percent * static_cast<double>(number_of_targets) / 100.0);
    return std::min(number_of_targets, std::max<std::size_t>(1, static_cast<std::size_t>(std::max(0.0, k))));
  }
  /// The hit rate at k = percent % of the target vertices.
  double hit_rate_at_percent(double percent) const { return hit_rate[k_of_percent(percent) - 1]; }
  /// The mean geodesic error at k = percent % of the target vertices.
  double geodesic_error_at_percent(double percent) const { return geodesic_error[k_of_percent(percent) - 1]; }
};

namespace internal {
template <typename DistanceFn, typename GeodesicFn, typename SymmetricGeodesicFn>
Ranking_curves evaluate_ranking(std::size_t sources, std::size_t targets, DistanceFn&& distance, const std::vector<std::size_t>& truth,
                                GeodesicFn&& geodesics_from, const std::vector<std::size_t>& symmetric_truth,
                                SymmetricGeodesicFn&& symmetric_geodesics_from, double normalization, unsigned threads) {
  if(sources == 0 || targets == 0 || truth.size() != sources)
    throw Invalid_argument("descriptor ranking: need source points, target vertices and one true match per source point");
  if(!symmetric_truth.empty() && symmetric_truth.size() != sources)
    throw Invalid_argument("descriptor ranking: one symmetric match per source point");
  if(!(normalization > 0)) throw Invalid_argument("descriptor ranking: the normalization must be positive");
  for(const auto* t : {&truth, &symmetric_truth})
    for(std::size_t v : *t)
      if(v >= targets) throw Invalid_argument("descriptor ranking: a true match is not a target vertex");
  const bool sym = !symmetric_truth.empty();
  Ranking_curves out;
  out.number_of_sources = sources;
  out.number_of_targets = targets;
  std::vector<double> hits(targets, 0.0), err(targets, 0.0), hits_s(sym ? targets : 0, 0.0), err_s(sym ? targets : 0, 0.0);
  std::mutex mtx;
  parallel_for(sources, resolve_thread_count(threads), [&](std::size_t i, unsigned) {
    std::vector<double> d(targets);
    for(std::size_t j = 0; j < targets; ++j) d[j] = distance(i, j);
    std::vector<std::size_t> order(targets);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d[a] < d[b]; });
    const Eigen::VectorXd g = geodesics_from(i);
    if(static_cast<std::size_t>(g.size()) != targets)
      throw Invalid_argument("descriptor ranking: the geodesic distances do not cover the target");
    Eigen::VectorXd gs;
    if(sym) {
      gs = symmetric_geodesics_from(i);
      if(static_cast<std::size_t>(gs.size()) != targets)
        throw Invalid_argument("descriptor ranking: the geodesic distances do not cover the target");
    }
    std::size_t rank = targets, rank_s = targets;
    std::vector<double> e(targets), es(sym ? targets : 0);
    double sum = 0, sum_s = 0;
    for(std::size_t k = 0; k < targets; ++k) {
      const std::size_t t = order[k];
      if(t == truth[i]) rank = std::min(rank, k);
      const double gk = g[static_cast<Eigen::Index>(t)];
      sum += std::isfinite(gk) ? gk : 0.0;
      e[k] = sum / static_cast<double>(k + 1) / normalization;
      if(sym) {
        if(t == truth[i] || t == symmetric_truth[i]) rank_s = std::min(rank_s, k);
        const double gm = std::min(gk, gs[static_cast<Eigen::Index>(t)]);
        sum_s += std::isfinite(gm) ? gm : 0.0;
        es[k] = sum_s / static_cast<double>(k + 1) / normalization;
      }
    }
    std::lock_guard<std::mutex> lock(mtx);
    for(std::size_t k = rank; k < targets; ++k) hits[k] += 1;
    for(std::size_t k = 0; k < targets; ++k) err[k] += e[k];
    if(sym) {
      for(std::size_t k = rank_s; k < targets; ++k) hits_s[k] += 1;
      for(std::size_t k = 0; k < targets; ++k) err_s[k] += es[k];
    }
  });
  const double S = static_cast<double>(sources);
  for(auto& x : hits) x /= S;
  for(auto& x : err) x /= S;
  for(auto& x : hits_s) x /= S;
  for(auto& x : err_s) x /= S;
  out.hit_rate = std::move(hits);
  out.geodesic_error = std::move(err);
  out.hit_rate_symmetric = std::move(hits_s);
  out.geodesic_error_symmetric = std::move(err_s);
  return out;
}
} // namespace internal

/// \ingroup PkgShapeCorrEvaluation
/// Evaluates a descriptor by the thesis's protocol. For source point i (0..sources-1) all `targets`
/// target vertices are ranked by `distance(i, j)` (ties by vertex index); `truth[i]` is the target
/// vertex that truly corresponds to it and `geodesics_from(i)` returns the geodesic distances on
/// the target from `truth[i]` to every target vertex (an `Eigen::VectorXd` of size `targets`);
/// geodesic errors are divided by `normalization` (the Princeton benchmark's sqrt(area)).
/// Source points run in parallel on `threads` threads (0: all cores); `distance` and
/// `geodesics_from` must be safe to call concurrently.
/// \throws Invalid_argument on sizes that do not fit or a non-positive normalization
template <typename DistanceFn, typename GeodesicFn>
Ranking_curves evaluate_descriptor_ranking(std::size_t sources, std::size_t targets, DistanceFn&& distance, const std::vector<std::size_t>& truth,
                                           GeodesicFn&& geodesics_from, double normalization, unsigned threads = 0) {
  return internal::evaluate_ranking(sources, targets, distance, truth, geodesics_from, {}, [](std::size_t) { return Eigen::VectorXd(); },
                                    normalization, threads);
}

/// \ingroup PkgShapeCorrEvaluation
/// As above, and also the curves that count the symmetric counterpart of the true match as
/// correct (`hit_rate_symmetric`, `geodesic_error_symmetric`: the error is the distance to the
/// nearer of `truth[i]` and `symmetric_truth[i]`, whose distances `symmetric_geodesics_from(i)`
/// returns). Intrinsic descriptors cannot tell left from right on a symmetric shape; TOSCA gives
/// the symmetric ground truth in its `.sym.vts` files.
template <typename DistanceFn, typename GeodesicFn, typename SymmetricGeodesicFn>
Ranking_curves evaluate_descriptor_ranking(std::size_t sources, std::size_t targets, DistanceFn&& distance, const std::vector<std::size_t>& truth,
                                           GeodesicFn&& geodesics_from, const std::vector<std::size_t>& symmetric_truth,
                                           SymmetricGeodesicFn&& symmetric_geodesics_from, double normalization, unsigned threads = 0) {
  if(symmetric_truth.size() != sources)
    throw Invalid_argument("descriptor ranking: one symmetric match per source point");
  return internal::evaluate_ranking(sources, targets, distance, truth, geodesics_from, symmetric_truth, symmetric_geodesics_from,
                                    normalization, threads);
}

/// \ingroup PkgShapeCorrEvaluation
/// Reads a TOSCA-style correspondence file (`.vts`: one 1-based vertex id per line) as 0-based ids.
/// \throws Invalid_input when unreadable, empty, or holding an id < 1
inline std::vector<std::size_t> read_vts(const std::string& path) {
  std::ifstream in(path);
  if(!in) throw Invalid_input(Mesh_defect::unreadable_file, path + ": cannot read");
  std::vector<std::size_t> ids;
  long long v;
  while(in >> v) {
    if(v < 1) throw Invalid_input(Mesh_defect::unreadable_file, path + ": vertex id " + std::to_string(v) + " (the file is 1-based)");
    ids.push_back(static_cast<std::size_t>(v - 1));
  }
  if(!in.eof()) throw Invalid_input(Mesh_defect::unreadable_file, path + ": not a list of integers");
  if(ids.empty()) throw Invalid_input(Mesh_defect::unreadable_file, path + ": no vertex ids");
  return ids;
}

} // namespace shapecorr

#endif
