// Furthest point sampling: the thesis's procedure, seeded, geodesic or Euclidean.
#include "test_meshes.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/sampling.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

namespace SP = shapecorr::parameters;

TEMPLATE_LIST_TEST_CASE("furthest point sampling on a square picks the corners", "[sampling]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 10, 10);
  const auto vs = test::vertices_in_index_order(m);
  auto vim = CGAL::get_initialized_vertex_index_map(m);
  for(auto metric : {shapecorr::Distance_metric::EUCLIDEAN, shapecorr::Distance_metric::GEODESIC}) {
    std::vector<typename boost::graph_traits<TestType>::vertex_descriptor> s;
    // start at the centre (index 60), which the thesis's procedure then drops
    shapecorr::furthest_point_sampling(m, 4, std::back_inserter(s), SP::distance_metric(metric).first_vertex(vs[60])
                                                                         .geodesic_method(shapecorr::Geodesic_method::EXACT));
    std::set<std::size_t> got;
    for(auto v : s) got.insert(get(vim, v));
    CHECK(got == std::set<std::size_t>{0, 10, 110, 120});
  }
}

TEMPLATE_LIST_TEST_CASE("furthest point sampling: seeded, distinct, spreading", "[sampling]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 3);
  typedef typename boost::graph_traits<TestType>::vertex_descriptor vd;
  std::vector<vd> a, b, c;
  shapecorr::furthest_point_sampling(m, 20, std::back_inserter(a), SP::random_seed(11u));
  shapecorr::furthest_point_sampling(m, 20, std::back_inserter(b), SP::random_seed(11u));
  shapecorr::furthest_point_sampling(m, 20, std::back_inserter(c), SP::random_seed(12u));
  REQUIRE(a.size() == 20);
  CHECK(a == b);
  CHECK(std::set<vd>(a.begin(), a.end()).size() == 20);
  // the defining property of furthest point sampling (start kept): every vertex is closer to the
  // sample set than any two samples are to each other (covering radius <= packing distance)
  shapecorr::Exact_geodesics<TestType> exact(m);
  std::vector<vd> k;
  shapecorr::furthest_point_sampling(m, 20, std::back_inserter(k), SP::random_seed(11u).keep_first_vertex(true).geodesic_engine(&exact));
  std::vector<std::size_t> ids;
  for(vd v : k) ids.push_back(exact.index(v));
  const double cover = exact.distances_to_set(ids).maxCoeff();
  double packing = 1e9;
  for(std::size_t i = 0; i < ids.size(); ++i) {
    const Eigen::VectorXd d = exact.distances_from(ids[i]);
    for(std::size_t j = 0; j < ids.size(); ++j) if(j != i) packing = std::min(packing, d[static_cast<Eigen::Index>(ids[j])]);
  }
  INFO("covering radius " << cover << ", packing distance " << packing);
  CHECK(cover <= packing + 1e-12);
  CHECK(cover < 1.0);
  // asking for more samples than vertices gives every vertex once
  std::vector<vd> all;
  shapecorr::furthest_point_sampling(m, 10000, std::back_inserter(all));
  CHECK(all.size() == num_vertices(m));
}
