// The geodesic error of a map at ground-truth pairs: on a flat unit square (area 1, geodesics are
// straight lines) the errors are the Euclidean distances; summaries and the cumulative curve by
// hand; bad input.
#include "test_meshes.h"

#include <shapecorr/evaluation/map_geodesic_error.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

TEMPLATE_LIST_TEST_CASE("map geodesic errors on a flat square: the distances between found and true vertices", "[evaluation]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 40, 40); // vertex (i, j): j * 41 + i, at (i / 40, j / 40); area 1
  auto id = [](std::size_t i, std::size_t j) { return j * 41 + i; };
  const std::vector<std::size_t> truth = {id(20, 20), id(0, 0), id(10, 30), id(20, 20)};
  // list 0: the truth itself; list 1: 8 columns to the right (0.2), 4 rows up (0.1), 0, 10 columns left (0.25)
  const std::vector<std::vector<std::size_t>> found = {truth, {id(28, 20), id(0, 4), id(10, 30), id(10, 20)}};
  const auto e = shapecorr::map_geodesic_errors(m, truth, found);
  REQUIRE(e.size() == 2);
  for(double x : e[0]) CHECK(x == 0.0);
  const double expected[4] = {0.2, 0.1, 0.0, 0.25};
  for(std::size_t k = 0; k < 4; ++k) CHECK(e[1][k] == Approx(expected[k]).margin(1e-6));
  const shapecorr::Map_error_summary s = shapecorr::summarize_map_errors(e[1]);
  CHECK(s.pairs == 4);
  CHECK(s.mean == Approx(0.55 / 4).margin(1e-6));
  CHECK(s.largest == Approx(0.25).margin(1e-6));
  CHECK(s.fraction_within == (e[1][3] <= 0.25 ? 1.0 : 0.75));
}

TEST_CASE("map geodesic errors: the cumulative curve and the summary", "[evaluation]") {
  const std::vector<double> errors = {0.0, 0.05, 0.1, 0.3};
  const std::vector<double> curve = shapecorr::cumulative_error_curve(errors, 0.25, 5); // thresholds 0, 0.05, ..., 0.25
  REQUIRE(curve.size() == 6);
  const double expected[6] = {0.25, 0.5, 0.75, 0.75, 0.75, 0.75};
  for(std::size_t i = 0; i < 6; ++i) CHECK(curve[i] == Approx(expected[i]));
  const auto s = shapecorr::summarize_map_errors(errors, 0.1);
  CHECK(s.fraction_within == Approx(0.75));
  CHECK(s.largest == 0.3);
  CHECK(shapecorr::summarize_map_errors({}).pairs == 0);
  CHECK_THROWS_AS(shapecorr::cumulative_error_curve(errors, 0.25, 0), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::cumulative_error_curve(errors, 0.0), shapecorr::Invalid_argument);
}

TEST_CASE("map geodesic errors: bad input", "[evaluation][errors]") {
  test::Surface_mesh m;
  shapecorr::make_grid(m, 4, 4);
  CHECK_THROWS_AS(shapecorr::map_geodesic_errors(m, {0, 1}, {{0}}), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::map_geodesic_errors(m, {0, 1}, {{0, 25}}), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::map_geodesic_errors(m, {99}, {{0}}), shapecorr::Invalid_argument);
  CHECK(shapecorr::map_geodesic_errors(m, {}, {{}}).at(0).empty());
}
