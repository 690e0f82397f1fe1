// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the furthest point order over any distance oracle, shared by furthest point sampling
// (sampling/) and the sources of the global average geodesic distance (geodesics/).
#ifndef SHAPECORR_INTERNAL_FURTHEST_POINT_ORDER_H
#define SHAPECORR_INTERNAL_FURTHEST_POINT_ORDER_H

#include <CGAL/Random.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace shapecorr {
namespace internal {

/// The start vertex the seed draws (shared by every seeded use of furthest point sampling).
inline std::size_t seeded_start_vertex(unsigned seed, std::size_t n) {
  CGAL::Random rng(seed);
  return static_cast<std::size_t>(rng.get_int(0, static_cast<int>(n)));
}

/// Sample indices in selection order; `distances_from(i)` gives the distance of every vertex to
/// vertex i (n values).
template <typename DistancesFrom>
std::vector<std::size_t> furthest_point_sampling_indices(std::size_t n, std::size_t count, std::size_t first, bool keep_first,
                                           DistancesFrom&& distances_from) {
  std::vector<double> mind(n, std::numeric_limits<double>::infinity());
  const std::size_t total = keep_first ? count : count + 1; // the thesis drops the arbitrary start
  std::size_t next = first;
  std::vector<std::size_t> chosen;
  std::vector<char> taken(n, 0);
  while(chosen.size() < std::min(total, n)) {
    chosen.push_back(next);
    taken[next] = 1;
    const Eigen::VectorXd d = distances_from(next);
    for(std::size_t i = 0; i < n; ++i) mind[i] = std::min(mind[i], d[static_cast<Eigen::Index>(i)]);
    // farthest untaken vertex; +infinity (another component) wins, ties to the lowest index
    double best = -1;
    std::size_t arg = n;
    for(std::size_t i = 0; i < n; ++i)
      if(!taken[i] && mind[i] > best) { best = mind[i]; arg = i; }
    if(arg == n) break;
    next = arg;
  }
  if(!keep_first && chosen.size() > count) chosen.erase(chosen.begin());
  return chosen;
}

} // namespace internal
} // namespace shapecorr

#endif
