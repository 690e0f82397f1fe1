// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file furthest_point_sampling.h
#ifndef SHAPECORR_SAMPLING_FURTHEST_POINT_SAMPLING_H
#define SHAPECORR_SAMPLING_FURTHEST_POINT_SAMPLING_H

#include <shapecorr/geodesics/with_geodesic_engine.h>
#include <shapecorr/internal/furthest_point_order.h>
#include <shapecorr/internal/indexed_mesh.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrSampling
/// Distance used by furthest point sampling (named parameter `distance_metric`).
enum class Distance_metric { GEODESIC, EUCLIDEAN };

/// \ingroup PkgShapeCorrSampling
/// Furthest point sampling over any distance, by index: the order of `furthest_point_sampling`
/// for distances that the caller provides (precomputed matrices, a subset of vertices, another
/// metric). Starts at `first`, then repeatedly takes the index farthest from those taken (ties to
/// the lowest index), `count + 1` in all, and drops `first` unless `keep_first`.
/// \tparam DistancesFrom callable `(std::size_t i) -> Eigen::VectorXd` giving the n distances from
///   index i; `+infinity` counts as farthest (an unreached component), and a **negative distance
///   excludes** an index from ever being chosen
/// \param n number of indices, \param count number of samples wanted
/// \returns the sample indices in selection order (fewer than `count` when fewer indices qualify)
/// \code
///   // 10 samples among the vertices with ground truth, by fast marching
///   auto samples = shapecorr::furthest_point_sampling_indices(n, 10, first, [&](std::size_t s) {
///     Eigen::VectorXd d = engine.distances_from(s);
///     for(std::size_t v = 0; v < n; ++v) if(!has_truth[v]) d[v] = -1;
///     return d;
///   });
/// \endcode
template <typename DistancesFrom>
std::vector<std::size_t> furthest_point_sampling_indices(std::size_t n, std::size_t count, std::size_t first,
                                                         DistancesFrom&& distances_from, bool keep_first = false) {
  if(first >= n) throw Invalid_argument("furthest point sampling: first index " + std::to_string(first) + " out of range (" + std::to_string(n) + " indices)");
  return internal::furthest_point_sampling_indices(n, count, first, keep_first, distances_from);
}

/// \ingroup PkgShapeCorrSampling
/// Furthest point sampling (thesis, chapter 5): start at an arbitrary vertex (drawn with the seed,
/// or `first_vertex`), then repeatedly add the vertex farthest from the chosen set until there are
/// `count + 1`, and drop the arbitrary first one (`keep_first_vertex(true)` keeps it and stops at
/// `count`). Every step is one single-source distance query.
/// \param count number of samples (at most the number of vertices)
/// \param out output iterator receiving `vertex_descriptor`s in selection order
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `distance_metric` | `GEODESIC` or `EUCLIDEAN` | `Distance_metric` | `GEODESIC` |
/// | `random_seed` | seed of the start vertex | `unsigned` | 0 |
/// | `first_vertex` | start vertex (overrides the seed) | `vertex_descriptor` | drawn |
/// | `keep_first_vertex` | keep the start vertex as a sample | `bool` | `false` |
/// | `geodesic_method`, `geodesic_engine`, engine parameters | distance backend | | heat method |
/// Vertices of components not yet reached count as infinitely far, so every component gets samples.
/// \returns the output iterator past the last sample
template <typename TriangleMesh, typename OutputIterator, typename NamedParameters = parameters::Default_named_parameters>
OutputIterator furthest_point_sampling(const TriangleMesh& tm, std::size_t count, OutputIterator out,
                                       const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t n = num_vertices(tm);
  if(n == 0) throw Invalid_input(Mesh_defect::empty_mesh, "furthest point sampling: the mesh has no vertex");
  if(count == 0) return out;
  const bool keep_first = choose_parameter(get_parameter(np, internal_np::keep_first_vertex), false);
  const unsigned seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const Distance_metric metric = choose_parameter(get_parameter(np, internal_np::distance_metric), Distance_metric::GEODESIC);
  auto run = [&](const auto& engine, auto&& distances_from) {
    std::size_t first;
    auto given = get_parameter(np, internal_np::first_vertex);
    if constexpr(!std::is_same<decltype(given), CGAL::internal_np::Param_not_found>::value) {
      first = engine.index(static_cast<vertex_descriptor>(given));
    } else {
      first = internal::seeded_start_vertex(seed, n);
    }
    for(std::size_t s : internal::furthest_point_sampling_indices(n, count, first, keep_first, distances_from))
      *out++ = engine.vertex(s);
    return 0;
  };
  if(metric == Distance_metric::EUCLIDEAN) {
    const internal::Indexed_mesh<TriangleMesh> im(tm, np);
    const auto& V = im.arrays().V;
    run(im, [&](std::size_t s) -> Eigen::VectorXd { return (V.rowwise() - V.row(static_cast<Eigen::Index>(s))).rowwise().norm(); });
  } else {
    with_geodesic_engine(tm, np, [&](const auto& engine) {
      return run(engine, [&](std::size_t s) { return engine.distances_from(s); });
    });
  }
  return out;
}

} // namespace shapecorr

#endif
