// Named parameters: ShapeCorr's and CGAL's tags chain in any order and are read back.
#include <shapecorr/parameters.h>

#include <catch2/catch.hpp>

TEST_CASE("named parameters mix ShapeCorr and CGAL tags", "[parameters]") {
  namespace SP = shapecorr::parameters;
  const auto np = SP::time_step_factor(2.5).random_seed(7u).use_intrinsic_delaunay(true);
  using SP::choose_parameter;
  using SP::get_parameter;
  CHECK(choose_parameter(get_parameter(np, shapecorr::internal_np::time_step_factor), 1.0) == 2.5);
  CHECK(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u) == 7u);
  CHECK(choose_parameter(get_parameter(np, shapecorr::internal_np::use_intrinsic_delaunay), false));
  // absent: the default
  CHECK(choose_parameter(get_parameter(np, shapecorr::internal_np::batch_size), std::size_t(64)) == 64);
  // CGAL's builder first, ours not chainable after it: CGAL's own chains still read fine
  const auto cgal_np = CGAL::parameters::number_of_iterations(3);
  CHECK(choose_parameter(get_parameter(cgal_np, CGAL::internal_np::number_of_iterations), 0) == 3);
  const auto ours_first = SP::number_of_iterations(4).batch_size(std::size_t(8));
  CHECK(choose_parameter(get_parameter(ours_first, CGAL::internal_np::number_of_iterations), 0) == 4);
  CHECK(choose_parameter(get_parameter(ours_first, shapecorr::internal_np::batch_size), std::size_t(1)) == 8);
}
