// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: pieces shared by the geodesic distance engines.
#ifndef SHAPECORR_GEODESICS_INTERNAL_ENGINE_HELPERS_H
#define SHAPECORR_GEODESICS_INTERNAL_ENGINE_HELPERS_H

#include <shapecorr/parallel.h>

#include <Eigen/Dense>

#include <functional>
#include <mutex>
#include <vector>

namespace shapecorr {
namespace internal {

/// `for_each_batch` of engines that answer one source at a time: `distances(source, thread_id)`
/// gives the n distances from one source; `fn(k, 1, block)` receives them as an n x 1 block.
template <typename Distances, typename BlockFn>
void for_each_single_source(const std::vector<std::size_t>& sources, unsigned threads, Distances&& distances, BlockFn&& fn,
                            const std::function<void(std::size_t, std::size_t)>& progress) {
  std::mutex mtx;
  std::size_t done = 0;
  parallel_for(sources.size(), threads, [&](std::size_t k, unsigned tid) {
    const Eigen::MatrixXd block = distances(sources[k], tid);
    fn(k, std::size_t(1), block);
    if(progress) {
      std::lock_guard<std::mutex> lock(mtx);
      progress(++done, sources.size());
    }
  });
}

/// `compute_geodesic_distances` of every engine: distances to the nearest of `sources`
/// (vertex descriptors) written into a vertex property map.
template <typename Engine, typename VertexRange, typename VertexDistanceMap>
void write_distances_to_set(const Engine& engine, const VertexRange& sources, VertexDistanceMap distance_map) {
  std::vector<std::size_t> ids;
  for(const auto& v : sources) ids.push_back(engine.index(v));
  const Eigen::VectorXd d = engine.distances_to_set(ids);
  for(std::size_t i = 0; i < engine.number_of_vertices(); ++i) put(distance_map, engine.vertex(i), d[static_cast<Eigen::Index>(i)]);
}

} // namespace internal
} // namespace shapecorr

#endif
