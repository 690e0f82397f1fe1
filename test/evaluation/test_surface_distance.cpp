// Surface distances (thesis chapter 6 metrics): a tilted square over a plane (exact l1, l2, lmax,
// per-vertex distances), concentric spheres (bounds from the meshes' own geometry), CGAL's
// approximate Hausdorff distance, the quadrature's error bound and its O(h²) convergence, rigid
// invariance, landmark distances, bad input; R and T of different mesh types.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/evaluation/surface_distance.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Polygon_mesh_processing/distance.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

namespace SP = shapecorr::parameters;

namespace {
// The unit square [0,1]² tilted to z = x (n x n cells): its distance to the plane z = 0 is x.
template <typename Mesh>
void make_tilted_square(Mesh& m, int n) {
  shapecorr::make_grid(m, n, n);
  test::transform_points(m, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x(), p.y(), p.x()); });
}
// The plane z = 0 over [-1, 2]², two triangles.
void make_ground(test::Polyhedron& m) {
  shapecorr::make_grid(m, 1, 1, 3.0, 3.0);
  test::transform_points(m, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x() - 1, p.y() - 1, 0); });
}
// Smallest distance from the origin to the plane of a face: the mesh lies between this radius and
// its vertices' radius.
template <typename Mesh>
double smallest_face_plane_distance(const Mesh& m) {
  double r = std::numeric_limits<double>::infinity();
  auto vpm = get(CGAL::vertex_point, m);
  for(auto f : faces(m)) {
    std::vector<Eigen::Vector3d> p;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) {
      const auto& q = get(vpm, v);
      p.emplace_back(q.x(), q.y(), q.z());
    }
    const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    r = std::min(r, std::abs(n.dot(p[0])));
  }
  return r;
}
} // namespace

TEMPLATE_LIST_TEST_CASE("surface distance of a tilted square to a plane: l1 = 1/2, l2 = sqrt(1/3), lmax = 1", "[evaluation][surface-distance]",
                        test::Mesh_types) {
  TestType R;
  make_tilted_square(R, 4);
  test::Polyhedron T;
  make_ground(T);
  const double tolerance = 1e3 * test::coordinate_epsilon<TestType>();
  const shapecorr::Surface_distance d = shapecorr::surface_distance(R, T);
  INFO("l1 " << d.l1 << ", l2 " << d.l2 << ", lmax " << d.lmax << ", bound " << d.error_bound << ", samples " << d.samples);
  CHECK(d.area == Approx(std::sqrt(2.0)).epsilon(tolerance));
  CHECK(std::abs(d.l1 - 0.5) < tolerance); // the midpoint rule integrates a linear function exactly
  CHECK(std::abs(d.lmax - 1.0) < tolerance); // at the vertices x = 1
  CHECK(std::abs(d.l2 - std::sqrt(1.0 / 3.0)) <= d.error_bound);
  CHECK(d.error_bound > 0);
  CHECK(d.error_bound < 0.1);

  // O(h²): halving the step divides the l2 error by about 4, and it stays within the bound
  double previous = 0;
  for(double step : {0.2, 0.1, 0.05}) {
    const auto e = shapecorr::surface_distance(R, T, SP::quadrature_step(step));
    const double error = std::abs(e.l2 - std::sqrt(1.0 / 3.0));
    INFO("step " << step << ": l2 error " << error << ", bound " << e.error_bound);
    CHECK(error <= e.error_bound);
    CHECK(e.error_bound <= step);
    if(previous > 0) CHECK(error < 0.4 * previous);
    previous = error;
  }

  // the distance of every vertex is its x
  auto dmap = get(CGAL::dynamic_vertex_property_t<double>(), R);
  shapecorr::compute_distances_to_surface(R, T, dmap);
  auto vpm = get(CGAL::vertex_point, R);
  for(auto v : vertices(R)) CHECK(std::abs(get(dmap, v) - get(vpm, v).x()) < tolerance);
}

TEST_CASE("surface distance between concentric spheres of radii 1 and 2 is 1, within the meshes' own chord error", "[evaluation][surface-distance]") {
  test::Surface_mesh inner;
  test::Polyhedron outer;
  shapecorr::make_icosphere(inner, 3, 1.0);
  shapecorr::make_icosphere(outer, 4, 2.0);
  // every point of a mesh lies between its smallest face-plane distance and its radius
  const double rho_inner = smallest_face_plane_distance(inner), rho_outer = smallest_face_plane_distance(outer);
  const double lo = rho_outer - 1.0, hi = 2.0 - rho_inner;
  INFO("distances lie in [" << lo << ", " << hi << "]");
  REQUIRE(hi - lo < 0.02);
  const shapecorr::Symmetric_surface_distance s = shapecorr::symmetric_surface_distance(inner, outer);
  for(const shapecorr::Surface_distance* d : {&s.forward, &s.backward}) {
    INFO("l1 " << d->l1 << ", l2 " << d->l2 << ", lmax " << d->lmax << ", bound " << d->error_bound);
    for(double x : {d->l1, d->l2, d->lmax}) {
      CHECK(x >= lo - d->error_bound);
      CHECK(x <= hi + d->error_bound);
    }
  }
  CHECK(s.forward.area < s.backward.area);
  CHECK(s.forward.area == Approx(4 * CGAL_PI).epsilon(0.01));
  CHECK(s.lmax == std::max(s.forward.lmax, s.backward.lmax));
  CHECK(s.l1 >= std::min(s.forward.l1, s.backward.l1));
  CHECK(s.l1 <= std::max(s.forward.l1, s.backward.l1));
  CHECK(s.l2 >= s.l1);
}

TEST_CASE("lmax agrees with CGAL's approximate Hausdorff distance; distances are invariant under a rigid motion", "[evaluation][surface-distance]") {
  test::Surface_mesh R, T;
  shapecorr::make_icosphere(R, 3);
  test::transform_points(R, [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d((1.0 + 0.2 * std::sin(3 * p.x() + 1) * std::cos(2 * p.y() + 0.5)) * p);
  });
  shapecorr::make_icosphere(T, 4);
  test::transform_points(T, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(1.1 * p.x(), 0.9 * p.y(), p.z()); });
  const shapecorr::Surface_distance d = shapecorr::surface_distance(R, T);
  const double spacing = 0.005;
  const double cgal = CGAL::Polygon_mesh_processing::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
      R, T, CGAL::parameters::use_grid_sampling(true).grid_spacing(spacing), CGAL::parameters::default_values());
  INFO("ours " << d.lmax << " (bound " << d.error_bound << "), CGAL " << cgal << " (grid " << spacing << ")");
  CHECK(d.lmax > 0.05);
  CHECK(std::abs(d.lmax - cgal) <= d.error_bound + spacing);

  test::Surface_mesh R2 = R, T2 = T;
  const Eigen::Isometry3d M = test::random_rigid_motion(3);
  test::transform_points(R2, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(M * p); });
  test::transform_points(T2, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(M * p); });
  const shapecorr::Surface_distance e = shapecorr::surface_distance(R2, T2);
  CHECK(e.l1 == Approx(d.l1).epsilon(1e-9));
  CHECK(e.l2 == Approx(d.l2).epsilon(1e-9));
  CHECK(e.lmax == Approx(d.lmax).epsilon(1e-9));
  CHECK(e.samples == d.samples);
}

TEST_CASE("landmark distances and bad input", "[evaluation][surface-distance]") {
  const std::vector<test::Point> a = {{0, 0, 0}, {1, 0, 0}}, b = {{0, 3, 4}, {1, 0, 0}};
  const std::vector<double> d = shapecorr::landmark_distances(a, b);
  REQUIRE(d.size() == 2);
  CHECK(d[0] == 5.0);
  CHECK(d[1] == 0.0);
  CHECK_THROWS_AS(shapecorr::landmark_distances(a, std::vector<test::Point>{{0, 0, 0}}), shapecorr::Invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(shapecorr::landmark_distances(a, std::vector<test::Point>{{0, 0, 0}, {nan, 0, 0}}), shapecorr::Invalid_argument);

  test::Surface_mesh square, empty, bad;
  make_tilted_square(square, 2);
  CHECK_THROWS_AS(shapecorr::surface_distance(square, empty), shapecorr::Invalid_input);
  CHECK_THROWS_AS(shapecorr::surface_distance(empty, square), shapecorr::Invalid_input);
  CHECK_THROWS_AS(shapecorr::surface_distance(square, square, SP::quadrature_step(0.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::surface_distance(square, square, SP::quadrature_step(-1.0)), shapecorr::Invalid_argument);
  bad = square;
  bad.point(*vertices(bad).begin()) = test::Point(nan, 0, 0);
  try {
    shapecorr::surface_distance(square, bad);
    FAIL("a NaN coordinate was accepted");
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(e.defect() == shapecorr::Mesh_defect::non_finite_coordinate);
  }
  CHECK(shapecorr::surface_distance(square, square).lmax == 0.0);
}
