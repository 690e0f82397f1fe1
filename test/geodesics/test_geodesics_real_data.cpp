// Real data (../shared/data, skipped when absent): the TOSCA wolf, approximate engines against
// CGAL's exact distances. Bounds are the measured errors (heat ~1.0% of D, fast marching ~0.5%)
// with a margin, not tuned to pass.
#include "test_meshes.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>

#include <catch2/catch.hpp>

TEMPLATE_LIST_TEST_CASE("TOSCA wolf: approximate vs exact geodesics", "[geodesics][real-data]", test::Mesh_types) {
  const std::string dir = test::data_dir();
  if(dir.empty()) {
    WARN("../shared/data not found: skipping the real-data test");
    return;
  }
  TestType m;
  shapecorr::read_triangle_mesh(dir + "/tosca5k/meshes/wolf0.off", m);
  REQUIRE(num_vertices(m) == 4344);
  shapecorr::Exact_geodesics<TestType> exact(m);
  shapecorr::Heat_method_geodesics<TestType> heat(m, shapecorr::parameters::use_intrinsic_delaunay(true));
  shapecorr::Fast_marching_geodesics<TestType> fmm(m);
  std::size_t a = 0, b = 0;
  const double D = shapecorr::internal::diameter_by_sweeps(exact, 0, 3, &a, &b);
  double eh = 0, ef = 0;
  int count = 0;
  for(std::size_t s : {a, b, std::size_t(2000)}) {
    const Eigen::VectorXd e = exact.distances_from(s);
    eh += (heat.distances_from(s) - e).cwiseAbs().sum();
    ef += (fmm.distances_from(s) - e).cwiseAbs().sum();
    count += static_cast<int>(e.size());
  }
  eh /= count * D;
  ef /= count * D;
  INFO("D = " << D << ", mean |heat - exact| = " << 100 * eh << "% D, mean |fmm - exact| = " << 100 * ef << "% D");
  CHECK(eh < 0.015);
  CHECK(ef < 0.0075);
}
