// The template fit: a sphere template fitted to a moved ellipsoid (the rigid alignment finds the
// motion, NICPS the stretch: every fitted vertex near the analytic surface), with landmark pairs
// (they steer both stages), and mismatched landmark counts; the template over three mesh types.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/mesh/primitives.h>
#include <shapecorr/shape_model/fit_template.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace SP = shapecorr::parameters;

namespace {
const double ax = 1.3, ay = 0.9, az = 0.7;
}

TEMPLATE_LIST_TEST_CASE("fit_template: a sphere onto a moved ellipsoid", "[shape_model][fit]", test::Mesh_types) {
  TestType tmpl;
  shapecorr::make_icosphere(tmpl, 2);
  test::Surface_mesh specimen;
  shapecorr::make_icosphere(specimen, 3);
  const Eigen::Isometry3d T = test::random_rigid_motion(4);
  test::transform_points(specimen, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(T * Eigen::Vector3d(ax * p.x(), ay * p.y(), az * p.z())); });
  // the analytic residual of a point: |(x/a)² + (y/b)² + (z/c)² − 1| / 2 in the ellipsoid's frame
  auto residual = [&](double x, double y, double z) {
    const Eigen::Vector3d q = T.inverse() * Eigen::Vector3d(x, y, z);
    return std::abs(q.x() * q.x() / (ax * ax) + q.y() * q.y() / (ay * ay) + q.z() * q.z() / (az * az) - 1) / 2;
  };
  typedef typename boost::property_traits<typename boost::property_map<TestType, CGAL::vertex_point_t>::type>::value_type Point;
  auto fitted = get(CGAL::dynamic_vertex_property_t<Point>(), tmpl);

  SECTION("principal axes") {
    const shapecorr::Template_fit_report r = shapecorr::fit_template(tmpl, specimen, fitted);
    CHECK(r.before.l2 > 1.0);          // far apart as given
    CHECK(r.after_rigid.l2 < 0.25);    // the motion found: what is left is the stretch
    CHECK(r.after.l2 < 0.01);
    CHECK(r.after.l2 < r.after_rigid.l2 / 10);
    double worst = 0;
    for(auto v : vertices(tmpl)) worst = std::max(worst, residual(get(fitted, v).x(), get(fitted, v).y(), get(fitted, v).z()));
    CHECK(worst < 0.02);
    CHECK(r.landmark_vertices.empty());
    CHECK(!r.nicps.iterations.empty());
  }
  SECTION("landmarks") {
    // the six poles, on the template and on the specimen
    std::vector<test::Point> on_template, on_specimen;
    for(int axis = 0; axis < 3; ++axis)
      for(double sign : {-1.0, 1.0}) {
        Eigen::Vector3d u = Eigen::Vector3d::Zero();
        u[axis] = sign;
        on_template.emplace_back(u.x(), u.y(), u.z());
        const Eigen::Vector3d s = T * Eigen::Vector3d(ax * u.x(), ay * u.y(), az * u.z());
        on_specimen.emplace_back(s.x(), s.y(), s.z());
      }
    const shapecorr::Template_fit_report r = shapecorr::fit_template(tmpl, specimen, fitted, SP::landmark_points(on_template), SP::landmark_points(on_specimen));
    CHECK(r.rigid.initialization == shapecorr::Rigid_initialization::LANDMARKS);
    REQUIRE(r.landmark_vertices.size() == 6);
    REQUIRE(r.landmark_distances_after.size() == 6);
    for(std::size_t l = 0; l < 6; ++l) {
      CHECK(r.landmark_distances_after[l] < 0.05);
      CHECK(r.landmark_distances_after[l] < r.landmark_distances_before[l]);
    }
    CHECK(r.after.l2 < 0.01);
    on_specimen.pop_back();
    CHECK_THROWS_AS(shapecorr::fit_template(tmpl, specimen, fitted, SP::landmark_points(on_template), SP::landmark_points(on_specimen)),
                    shapecorr::Invalid_argument);
  }
}
