// Average geodesic distance against closed forms: on the unit sphere the global agd is pi/2
// everywhere and the local agd of radius r is (sin r - r cos r) / (1 - cos r); on a plane, the
// local agd of an interior point is 2r/3.
#include "test_meshes.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace SP = shapecorr::parameters;

TEMPLATE_LIST_TEST_CASE("global average geodesic distance on the unit sphere is pi/2", "[agd]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 3); // 642 vertices
  auto agd = get(CGAL::dynamic_vertex_property_t<double>(), m);
  const double half_pi = 1.5707963267948966;
  SECTION("every vertex a source, exact distances") {
    shapecorr::compute_average_geodesic_distance(m, agd, SP::number_of_sources(std::size_t(0)).geodesic_method(shapecorr::Geodesic_method::EXACT));
    for(auto v : vertices(m)) CHECK(get(agd, v) == Approx(half_pi).epsilon(0.01));
  }
  SECTION("100 furthest-point sources weighted by their Voronoi areas, heat method") {
    shapecorr::compute_average_geodesic_distance(m, agd, SP::number_of_sources(std::size_t(100)).random_seed(3u));
    for(auto v : vertices(m)) CHECK(get(agd, v) == Approx(half_pi).epsilon(0.03));
  }
}

TEMPLATE_LIST_TEST_CASE("local average geodesic distance: sphere and plane closed forms", "[agd]", test::Mesh_types) {
  SECTION("sphere") {
    TestType m;
    shapecorr::make_icosphere(m, 4);
    auto agd = get(CGAL::dynamic_vertex_property_t<double>(), m);
    const double r = 0.5, expected = (std::sin(r) - r * std::cos(r)) / (1 - std::cos(r));
    shapecorr::compute_local_average_geodesic_distance(m, r, agd);
    for(auto v : vertices(m)) CHECK(get(agd, v) == Approx(expected).epsilon(0.03));
  }
  SECTION("plane, interior vertices") {
    TestType m;
    shapecorr::make_grid(m, 60, 60); // h = 1/60
    auto agd = get(CGAL::dynamic_vertex_property_t<double>(), m);
    const double r = 0.2;
    shapecorr::compute_local_average_geodesic_distance(m, r, agd);
    const auto vs = test::vertices_in_index_order(m);
    for(int j = 15; j <= 45; j += 5)
      for(int i = 15; i <= 45; i += 5) CHECK(get(agd, vs[static_cast<std::size_t>(j * 61 + i)]) == Approx(2 * r / 3).epsilon(0.03));
  }
  SECTION("bad radius") {
    TestType m;
    shapecorr::make_icosphere(m, 1);
    auto agd = get(CGAL::dynamic_vertex_property_t<double>(), m);
    CHECK_THROWS_AS(shapecorr::compute_local_average_geodesic_distance(m, 0.0, agd), shapecorr::Invalid_argument);
  }
}
