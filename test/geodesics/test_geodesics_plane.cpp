// Analytic oracle: on a flat patch, geodesic distance is the Euclidean distance.
#include "test_meshes.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace {
template <typename Mesh>
Eigen::VectorXd euclidean_from(const Mesh& m, std::size_t s) {
  const auto vs = test::vertices_in_index_order(m);
  auto vpm = get(CGAL::vertex_point, m);
  Eigen::VectorXd d(static_cast<Eigen::Index>(vs.size()));
  for(std::size_t i = 0; i < vs.size(); ++i) d[static_cast<Eigen::Index>(i)] = std::sqrt(CGAL::squared_distance(get(vpm, vs[i]), get(vpm, vs[s])));
  return d;
}
} // namespace

TEMPLATE_LIST_TEST_CASE("flat patch: geodesic = Euclidean distance", "[geodesics][plane]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 24, 24); // unit square, convex: every straight segment lies on the surface
  const std::size_t centre = 12 * 25 + 12, corner = 0;
  for(std::size_t s : {centre, corner}) {
    const Eigen::VectorXd truth = euclidean_from(m, s);
    SECTION("exact, source " + std::to_string(s)) {
      shapecorr::Exact_geodesics<TestType> exact(m);
      CHECK((exact.distances_from(s) - truth).cwiseAbs().maxCoeff() < 1e-9);
    }
    SECTION("fast marching (virtual-source updates are exact on developable patches), source " + std::to_string(s)) {
      shapecorr::Fast_marching_geodesics<TestType> fmm(m);
      const double err = (fmm.distances_from(s) - truth).cwiseAbs().maxCoeff();
      INFO("max error " << err);
      CHECK(err < 1e-9);
    }
    SECTION("heat method: mean error below 1% of the patch diameter, source " + std::to_string(s)) {
      shapecorr::Heat_method_geodesics<TestType> heat(m);
      const double err = (heat.distances_from(s) - truth).cwiseAbs().mean();
      INFO("mean error " << err);
      CHECK(err < 0.01 * std::sqrt(2.0));
    }
  }
}
