// Descriptor matching policies: k nearest descriptors against a brute-force sort, the contour
// comparison strategies of match_contours (exact = indexed bit for bit, fields within their
// bound), distances from one descriptor to a set; over the mesh types of test_meshes.h.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace SP = shapecorr::parameters;
using shapecorr::Contour_comparison;

namespace {
// Spin contours (central direction axis) of every vertex of a bumpy sphere (no symmetry) and of
// every 5th vertex of a moved copy.
template <typename Mesh>
void contour_sets(std::vector<shapecorr::Spin_contour>& sources, std::vector<shapecorr::Spin_contour>& targets) {
  Mesh a;
  shapecorr::make_icosphere(a, 2);
  test::transform_points(a, [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d((1.0 + 0.15 * std::sin(3 * p.x() + 1) * std::cos(2 * p.y() + 0.5) + 0.08 * p.z() * p.z() * p.z()) * p);
  });
  Mesh b = a;
  const Eigen::Isometry3d T = test::representable_rigid_motion<Mesh>(5);
  test::transform_points(b, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(T * p); });
  const auto np = SP::spin_axis(shapecorr::Spin_axis::CENTRAL_DIRECTION).image_rows(std::size_t(40)).image_columns(std::size_t(20));
  const shapecorr::Spin_descriptors<Mesh> sa(a, np), sb(b, np);
  const auto va = test::vertices_in_index_order(a), vb = test::vertices_in_index_order(b);
  for(std::size_t i = 0; i < va.size(); i += 5) sources.push_back(sa.spin_contour(sa.oriented_point(va[i])));
  for(auto v : vb) targets.push_back(sb.spin_contour(sb.oriented_point(v)));
}
} // namespace

TEST_CASE("k nearest descriptors: the first k of a full sort, ties by position, k = 2 is match_descriptors", "[descriptors][matching]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> value(0, 20); // few values: many ties
  std::vector<double> sources(30), targets(50);
  for(double& x : sources) x = value(rng);
  for(double& x : targets) x = value(rng);
  const auto distance = [](double a, double b) { return std::abs(a - b); };
  for(std::size_t k : {1u, 2u, 7u, 50u, 80u}) {
    const auto knn = shapecorr::k_nearest_descriptors(sources, targets, distance, k, 3);
    REQUIRE(knn.size() == sources.size());
    for(std::size_t i = 0; i < sources.size(); ++i) {
      std::vector<std::size_t> order(targets.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return distance(sources[i], targets[x]) < distance(sources[i], targets[y]); });
      REQUIRE(knn[i].size() == std::min<std::size_t>(k, targets.size()));
      for(std::size_t j = 0; j < knn[i].size(); ++j) {
        CHECK(knn[i][j].target == order[j]);
        CHECK(knn[i][j].distance == distance(sources[i], targets[order[j]]));
      }
    }
  }
  const auto best2 = shapecorr::k_nearest_descriptors(sources, targets, distance, 2);
  const auto matches = shapecorr::match_descriptors(sources, targets, distance);
  for(std::size_t i = 0; i < sources.size(); ++i) {
    CHECK(best2[i][0].target == matches[i].target);
    CHECK(best2[i][0].distance == matches[i].distance);
    CHECK(best2[i][1].distance == matches[i].second_distance);
  }
  CHECK_THROWS_AS(shapecorr::k_nearest_descriptors(sources, targets, distance, 0), shapecorr::Invalid_argument);
  CHECK(shapecorr::k_nearest_descriptors(sources, std::vector<double>{}, distance, 3)[0].empty());
  const std::vector<double> d = shapecorr::descriptor_distances(sources[4], targets, distance, 2);
  REQUIRE(d.size() == targets.size());
  for(std::size_t j = 0; j < targets.size(); ++j) CHECK(d[j] == distance(sources[4], targets[j]));
}

TEMPLATE_LIST_TEST_CASE("match_contours: every comparison strategy finds the moved copy; exact and indexed agree bit for bit",
                   "[descriptors][matching][contour-distance]", test::Mesh_types) {
  std::vector<shapecorr::Spin_contour> sources, targets;
  contour_sets<TestType>(sources, targets);
  REQUIRE(sources.size() >= shapecorr::indexed_contour_matching_threshold); // AUTOMATIC takes the indexed path
  const auto exact = shapecorr::match_contours(sources, targets, Contour_comparison::EXACT);
  const auto indexed = shapecorr::match_contours(sources, targets, Contour_comparison::NEAREST_POINT_INDEX);
  const auto automatic = shapecorr::match_contours(sources, targets);
  const auto fields = shapecorr::match_contours(sources, targets, Contour_comparison::DISTANCE_FIELD);
  REQUIRE(exact.size() == sources.size());
  for(std::size_t i = 0; i < sources.size(); ++i) {
    CHECK(exact[i].target == 5 * i);
    CHECK(indexed[i].target == exact[i].target);
    CHECK(indexed[i].distance == exact[i].distance);
    CHECK(indexed[i].second_distance == exact[i].second_distance);
    CHECK(automatic[i].distance == exact[i].distance);
    REQUIRE(fields[i].target == 5 * i);
    const double field_bound = std::max(shapecorr::Contour_distance_field(sources[i]).error_bound(),
                                        shapecorr::Contour_distance_field(targets[5 * i]).error_bound());
    CHECK(std::abs(fields[i].distance - exact[i].distance) <= field_bound);
  }
  // fewer sources than the threshold: AUTOMATIC compares exactly, the same result
  const std::vector<shapecorr::Spin_contour> few(sources.begin(), sources.begin() + 5);
  const auto few_auto = shapecorr::match_contours(few, targets);
  for(std::size_t i = 0; i < few.size(); ++i) CHECK(few_auto[i].distance == exact[i].distance);
  // the k nearest contours: the first is the match, distances ascending
  for(Contour_comparison how : {Contour_comparison::EXACT, Contour_comparison::NEAREST_POINT_INDEX}) {
    const auto knn = shapecorr::k_nearest_contours(sources, targets, 4, how);
    for(std::size_t i = 0; i < sources.size(); ++i) {
      REQUIRE(knn[i].size() == 4);
      CHECK(knn[i][0].target == exact[i].target);
      CHECK(knn[i][1].distance == exact[i].second_distance);
      for(std::size_t j = 1; j < 4; ++j) CHECK(knn[i][j - 1].distance <= knn[i][j].distance);
    }
  }
  CHECK(shapecorr::contour_comparison_from_string("fields") == Contour_comparison::DISTANCE_FIELD);
  CHECK_THROWS_AS(shapecorr::contour_comparison_from_string("fast"), shapecorr::Invalid_argument);
}
