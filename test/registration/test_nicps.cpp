// NICPS: a sphere deformed onto an ellipsoid (every vertex near the analytic surface, with each
// regularizer), a resampled copy under a small rigid motion (l2 after ≈ 0), vertex renumbering,
// the iteration callback, landmarks, bad input; template over three mesh types, target another.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"
#include "test_renumbering.h"

#include <shapecorr/evaluation/surface_distance.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <random>

namespace SP = shapecorr::parameters;
using shapecorr::Nicps_regularizer;
using shapecorr::Stop_reason;

namespace {
// An icosphere of `subdivisions` turned on the unit sphere (so that its vertices are not those of
// another subdivision level), mapped to the ellipsoid with semi-axes (a, b, c).
template <typename Mesh>
void make_ellipsoid(Mesh& m, int subdivisions, double a, double b, double c, unsigned turn_seed = 0) {
  shapecorr::make_icosphere(m, subdivisions);
  const Eigen::Matrix3d turn = turn_seed ? Eigen::Matrix3d(test::random_rigid_motion(turn_seed).linear()) : Eigen::Matrix3d::Identity();
  test::transform_points(m, [&](const Eigen::Vector3d& q) {
    const Eigen::Vector3d p = turn * q;
    return Eigen::Vector3d(a * p.x(), b * p.y(), c * p.z());
  });
}
// Largest |(x/a)² + (y/b)² + (z/c)² − 1| / 2 over the points: about the relative distance to the ellipsoid.
template <typename Mesh, typename Map>
double ellipsoid_residual(const Mesh& m, Map points, double a, double b, double c) {
  double worst = 0;
  for(auto v : vertices(m)) {
    const auto& p = get(points, v);
    const double e = (p.x() / a) * (p.x() / a) + (p.y() / b) * (p.y() / b) + (p.z() / c) * (p.z() / c);
    worst = std::max(worst, std::abs(e - 1) / 2);
  }
  return worst;
}
} // namespace

TEMPLATE_LIST_TEST_CASE("NICPS deforms a sphere onto an ellipsoid of another triangulation", "[registration][nicps]", test::Mesh_types) {
  TestType sphere;
  make_ellipsoid(sphere, 3, 1, 1, 1);
  test::Surface_mesh ellipsoid;
  make_ellipsoid(ellipsoid, 4, 1.3, 0.9, 0.75, 17);
  for(auto reg : {Nicps_regularizer::COMBINATORIAL_LAPLACIAN, Nicps_regularizer::COTANGENT_LAPLACIAN, Nicps_regularizer::EDGE}) {
    auto out = get(CGAL::dynamic_vertex_property_t<test::Point>(), sphere);
    const shapecorr::Nicps_report r = shapecorr::nicps(sphere, ellipsoid, out, SP::nicps_regularizer(reg));
    const double residual = ellipsoid_residual(sphere, out, 1.3, 0.9, 0.75);
    INFO("regularizer " << static_cast<int>(reg) << ": rms " << r.initial_rms << " -> " << r.final_rms << " in " << r.iterations.size()
                        << " iterations (" << shapecorr::to_string(r.stop) << "), worst relative residual " << residual);
    REQUIRE_FALSE(r.iterations.empty());
    CHECK(r.initial_rms > 0.1);
    CHECK(r.final_rms < 0.01);
    CHECK(residual < 0.03);
    CHECK(r.iterations.front().forward_pairs >= num_vertices(sphere));
    CHECK(r.iterations.front().inverse_pairs > 0);
    CHECK(r.iterations.front().alpha == 100.0);
    if(r.iterations.size() > 1) CHECK(r.iterations[1].alpha == Approx(100.0 / 1.1));
  }
}

TEST_CASE("NICPS: a resampled copy under a small rigid motion is reached; renumbering changes nothing", "[registration][nicps]") {
  test::Surface_mesh tmpl, target;
  make_ellipsoid(tmpl, 3, 1.0, 0.7, 0.5);
  make_ellipsoid(target, 4, 1.0, 0.7, 0.5, 23);
  shapecorr::Similarity_transform M;
  M.rotation = Eigen::AngleAxisd(0.08, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  M.translation = Eigen::Vector3d(0.05, -0.03, 0.02);
  shapecorr::apply_transform(target, M);
  auto out = tmpl.add_property_map<test::Surface_mesh::Vertex_index, test::Point>("v:fit").first;
  const auto r = shapecorr::nicps(tmpl, target, out);
  test::Surface_mesh fitted = tmpl;
  for(auto v : vertices(fitted)) fitted.point(v) = out[v];
  const auto d = shapecorr::surface_distance(fitted, target);
  const auto before = shapecorr::surface_distance(tmpl, target);
  INFO("l2 " << before.l2 << " -> " << d.l2 << ", " << r.iterations.size() << " iterations, " << shapecorr::to_string(r.stop));
  CHECK(d.l2 < 0.003);
  CHECK(d.l2 < 0.1 * before.l2);

  // the same template with its vertices in another order: the same fit, vertex for vertex
  const std::size_t n = tmpl.number_of_vertices();
  std::vector<std::size_t> perm;
  test::Surface_mesh shuffled = test::renumbered_copy(tmpl, 5, perm);
  auto out2 = shuffled.add_property_map<test::Surface_mesh::Vertex_index, test::Point>("v:fit").first;
  const auto r2 = shapecorr::nicps(shuffled, target, out2);
  CHECK(r2.iterations.size() == r.iterations.size());
  double diff = 0;
  for(std::size_t i = 0; i < n; ++i)
    diff = std::max(diff, std::sqrt(CGAL::squared_distance(out[test::Surface_mesh::Vertex_index(static_cast<unsigned>(i))],
                                                           out2[test::Surface_mesh::Vertex_index(static_cast<unsigned>(perm[i]))])));
  INFO("largest difference between the two fits " << diff);
  CHECK(diff < 1e-6);
}

TEST_CASE("NICPS: callback, landmarks, bad input", "[registration][nicps]") {
  test::Polyhedron sphere;
  make_ellipsoid(sphere, 2, 1, 1, 1);
  test::Surface_mesh ellipsoid, empty;
  make_ellipsoid(ellipsoid, 3, 1.3, 0.9, 0.75, 17);
  auto out = get(CGAL::dynamic_vertex_property_t<test::Point>(), sphere);

  std::size_t calls = 0;
  const std::function<bool(const shapecorr::Nicps_iteration_record&)> stop_after_two = [&](const shapecorr::Nicps_iteration_record&) {
    return ++calls < 2;
  };
  const auto r = shapecorr::nicps(sphere, ellipsoid, out, SP::iteration_callback(stop_after_two));
  CHECK(calls == 2);
  CHECK(r.iterations.size() == 2);
  CHECK(r.stop == Stop_reason::CANCELLED);

  // a landmark pulls vertex 0 to a chosen point of the ellipsoid
  const Eigen::Vector3d goal(0, 0.9, 0); // on the ellipsoid: the end of its y axis
  const auto vs = test::vertices_in_index_order(sphere);
  const std::vector<std::pair<std::size_t, Eigen::Vector3d>> landmarks = {{0, goal}};
  shapecorr::nicps(sphere, ellipsoid, out, SP::landmark_correspondences(landmarks).landmark_weight(100.0));
  const auto& p0 = get(out, vs[0]);
  INFO("vertex 0 at " << p0);
  CHECK((Eigen::Vector3d(p0.x(), p0.y(), p0.z()) - goal).norm() < 0.05);

  CHECK_THROWS_AS(shapecorr::nicps(sphere, empty, out), shapecorr::Invalid_input);
  CHECK_THROWS_AS(shapecorr::nicps(sphere, ellipsoid, out, SP::landmark_correspondences(std::vector<std::pair<std::size_t, Eigen::Vector3d>>{{9999, goal}})),
                  shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::nicps(sphere, ellipsoid, out, SP::alpha_initial(-1.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::nicps(sphere, ellipsoid, out, SP::alpha_decay(0.5)), shapecorr::Invalid_argument);
  test::Surface_mesh bad = ellipsoid;
  bad.point(*vertices(bad).begin()) = test::Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK_THROWS_AS(shapecorr::nicps(sphere, bad, out), shapecorr::Invalid_input);
}
