// Part of a shape (CGAL::Face_filtered_graph): geodesics, average geodesic distance and furthest
// point sampling on the patch equal those on a copy of it (CGAL::copy_face_graph).
#include "test_patches.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/sampling.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace SP = shapecorr::parameters;
typedef test::Patch::vertex_descriptor vertex_descriptor;

TEST_CASE("patch: geodesic distances of every engine equal the copy's", "[partial][geodesics]") {
  const auto p = test::sphere_patch();
  const auto& patch = *p->filtered;
  REQUIRE(p->filtered->is_selection_valid());
  REQUIRE(num_vertices(patch) < p->whole.number_of_vertices());
  REQUIRE(num_vertices(patch) == p->copy.number_of_vertices());
  // the patch's vertices are not the first ones of the sphere: an index map is needed
  std::size_t beyond = 0;
  for(vertex_descriptor v : vertices(patch)) beyond += v.idx() >= num_vertices(patch);
  REQUIRE(beyond > 0);

  const vertex_descriptor source = *vertices(patch).begin();
  for(auto method : {shapecorr::Geodesic_method::HEAT, shapecorr::Geodesic_method::EXACT, shapecorr::Geodesic_method::FAST_MARCHING}) {
    auto on_patch = p->whole.add_property_map<vertex_descriptor, double>("v:patch", -1).first;
    auto on_copy = p->copy.add_property_map<vertex_descriptor, double>("v:copy", -1).first;
    shapecorr::compute_geodesic_distances(patch, source, on_patch, SP::geodesic_method(method));
    shapecorr::compute_geodesic_distances(p->copy, p->to_copy.at(source), on_copy, SP::geodesic_method(method));
    double largest = 0, diff = 0;
    for(vertex_descriptor v : vertices(patch)) {
      largest = std::max(largest, on_patch[v]);
      diff = std::max(diff, std::abs(on_patch[v] - on_copy[p->to_copy.at(v)]));
    }
    INFO("method " << static_cast<int>(method) << ": largest distance " << largest << ", max difference " << diff);
    CHECK(largest > 2.0); // most of a unit sphere
    CHECK(diff < 1e-9);
    // vertices outside the patch are left alone
    std::size_t touched_outside = 0;
    for(vertex_descriptor v : vertices(p->whole)) touched_outside += !patch.is_in_cc(v) && on_patch[v] != -1;
    CHECK(touched_outside == 0);
    p->whole.remove_property_map(on_patch);
    p->copy.remove_property_map(on_copy);
  }
  CHECK(shapecorr::geodesic_diameter(patch) == Approx(shapecorr::geodesic_diameter(p->copy)).epsilon(1e-9));
}

TEST_CASE("patch: local average geodesic distance equals the copy's", "[partial][agd]") {
  const auto p = test::sphere_patch();
  auto on_patch = p->whole.add_property_map<vertex_descriptor, double>("v:agd", 0).first;
  auto on_copy = p->copy.add_property_map<vertex_descriptor, double>("v:agd", 0).first;
  shapecorr::compute_local_average_geodesic_distance(*p->filtered, 0.5, on_patch);
  shapecorr::compute_local_average_geodesic_distance(p->copy, 0.5, on_copy);
  double diff = 0;
  for(vertex_descriptor v : vertices(*p->filtered)) diff = std::max(diff, std::abs(on_patch[v] - on_copy[p->to_copy.at(v)]));
  CHECK(diff < 1e-9);
}

TEST_CASE("patch: furthest point samples are the copy's", "[partial][sampling]") {
  const auto p = test::sphere_patch();
  const vertex_descriptor first = *std::next(vertices(*p->filtered).begin(), 7);
  for(auto metric : {shapecorr::Distance_metric::GEODESIC, shapecorr::Distance_metric::EUCLIDEAN}) {
    std::vector<vertex_descriptor> on_patch, on_copy;
    shapecorr::furthest_point_sampling(*p->filtered, 12, std::back_inserter(on_patch), SP::first_vertex(first).distance_metric(metric));
    shapecorr::furthest_point_sampling(p->copy, 12, std::back_inserter(on_copy), SP::first_vertex(p->to_copy.at(first)).distance_metric(metric));
    REQUIRE(on_patch.size() == 12);
    REQUIRE(on_copy.size() == 12);
    for(std::size_t i = 0; i < on_patch.size(); ++i) {
      INFO("sample " << i);
      CHECK(p->filtered->is_in_cc(on_patch[i]));
      CHECK(p->to_copy.at(on_patch[i]) == on_copy[i]);
    }
  }
}
