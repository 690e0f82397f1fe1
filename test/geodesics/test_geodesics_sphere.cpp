// Analytic oracle: on the unit sphere, antipodal points are pi apart, and gd(p, q) = acos(p.q).
#include "test_meshes.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace {
const double pi = 3.14159265358979323846;

template <typename Mesh, typename Engine>
void check_sphere(const Mesh& m, const Engine& engine, double max_antipode_rel, double max_mean_rel) {
  // icosahedron vertices 0 = (-1, t, 0) and 3 = (1, -t, 0) are antipodal; vertex ids 0..11 are kept
  const auto vs = test::vertices_in_index_order(m);
  const Eigen::VectorXd d = engine.distances_from(0);
  INFO("antipode distance " << d[3]);
  CHECK(std::abs(d[3] - pi) / pi <= max_antipode_rel);
  // against the great-circle distance everywhere
  auto vpm = get(CGAL::vertex_point, m);
  const auto p0 = get(vpm, vs[0]);
  double err = 0;
  for(std::size_t i = 0; i < vs.size(); ++i) {
    const auto p = get(vpm, vs[i]);
    const double c = std::max(-1.0, std::min(1.0, (p.x() * p0.x() + p.y() * p0.y() + p.z() * p0.z())));
    err += std::abs(d[static_cast<Eigen::Index>(i)] - std::acos(c));
  }
  err /= static_cast<double>(vs.size());
  INFO("mean |error| / pi = " << err / pi);
  CHECK(err / pi <= max_mean_rel);
}
} // namespace

TEMPLATE_LIST_TEST_CASE("unit sphere: antipodes at pi, great-circle distances", "[geodesics][sphere]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 4); // 2562 vertices, mean edge 0.047
  SECTION("exact (CGAL shortest paths): only the polyhedral approximation error") {
    shapecorr::Exact_geodesics<TestType> exact(m);
    check_sphere(m, exact, 0.002, 0.001); // measured 0.07%, 0.03%
  }
  SECTION("heat method") {
    shapecorr::Heat_method_geodesics<TestType> heat(m);
    check_sphere(m, heat, 0.012, 0.006); // measured 0.93%, 0.42%
  }
  SECTION("heat method on the intrinsic Delaunay triangulation") {
    shapecorr::Heat_method_geodesics<TestType> heat(m, shapecorr::parameters::use_intrinsic_delaunay(true));
    check_sphere(m, heat, 0.012, 0.006);
  }
  SECTION("fast marching") {
    shapecorr::Fast_marching_geodesics<TestType> fmm(m);
    // first order; the antipode is where all fronts collide (cut locus): measured 1.3% there, 0.19% mean
    check_sphere(m, fmm, 0.02, 0.003);
  }
}
