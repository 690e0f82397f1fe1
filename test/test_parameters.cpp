// Named parameters: ShapeCorr's and CGAL's tags chain in any order and are read back.
#include <shapecorr/parallel.h>
#include <shapecorr/parameters.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

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

TEST_CASE("parallel loop: every item once, exceptions rethrown, 0 threads = all cores", "[parameters][parallel]") {
  using shapecorr::parallel_for;
  std::vector<std::atomic<int>> seen(1000);
  for(auto& s : seen) s = 0;
  parallel_for(seen.size(), 3, [&](std::size_t i, unsigned tid) {
    CHECK(tid < 3u);
    ++seen[i];
  });
  for(const auto& s : seen) CHECK(s == 1);
  CHECK_THROWS_AS(parallel_for(10, 2, [](std::size_t i, unsigned) {
                    if(i == 7) throw std::runtime_error("item 7");
                  }),
                  std::runtime_error);
  // 0 threads: all hardware threads. Item 0 waits (up to 5 s) for another thread to take an item:
  // a serial loop would never let it.
  if(shapecorr::resolve_thread_count(0) < 2) return;
  std::atomic<bool> other(false);
  parallel_for(4, 0, [&](std::size_t i, unsigned tid) {
    if(tid != 0) other = true;
    if(i == 0)
      for(int k = 0; k < 5000 && !other; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  CHECK(other);
}
