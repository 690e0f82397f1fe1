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

namespace {
// An open tube of radius r along z over [−L/2, L/2] (nθ × nz quads, two triangles each; the seam
// turned by `turn` radians), then bent in the xz plane around the line x = Rb (bend = 0: straight):
// the axis becomes an arc of radius Rb, lengths along it kept.
template <typename Mesh>
void make_bent_tube(Mesh& m, std::size_t ntheta, std::size_t nz, double r, double L, double Rb, double turn) {
  std::vector<std::array<double, 3>> P;
  std::vector<std::array<std::size_t, 3>> T;
  for(std::size_t j = 0; j <= nz; ++j)
    for(std::size_t i = 0; i < ntheta; ++i) {
      const double th = turn + 2 * M_PI * double(i) / double(ntheta), z = -L / 2 + L * double(j) / double(nz);
      const double x = r * std::cos(th), y = r * std::sin(th);
      if(Rb == 0) {
        P.push_back({x, y, z});
      } else {
        const double phi = z / Rb;
        P.push_back({Rb - (Rb - x) * std::cos(phi), y, (Rb - x) * std::sin(phi)});
      }
    }
  for(std::size_t j = 0; j < nz; ++j)
    for(std::size_t i = 0; i < ntheta; ++i) {
      const std::size_t a = j * ntheta + i, b = j * ntheta + (i + 1) % ntheta, c = a + ntheta, d = b + ntheta;
      T.push_back({a, b, d});
      T.push_back({a, d, c});
    }
  shapecorr::internal::soup_to_mesh(P, T, m);
}
// Distance from p to the bent tube's surface: | |p − a| − r | with a the nearest point of the arc
// (centre (Rb, 0, 0), radius Rb, angles within ±L/(2 Rb)); and the arc angle of p.
double distance_to_bent_tube(const Eigen::Vector3d& p, double r, double L, double Rb, double* angle = nullptr) {
  double phi = std::atan2(p.z(), Rb - p.x());
  if(angle) *angle = phi;
  phi = std::max(-L / (2 * Rb), std::min(L / (2 * Rb), phi));
  const Eigen::Vector3d a(Rb - Rb * std::cos(phi), 0, Rb * std::sin(phi));
  return std::abs((p - a).norm() - r);
}
} // namespace

TEST_CASE("NICPS bends a straight tube onto a bent one of another triangulation, without sliding along it", "[registration][nicps]") {
  const double r = 0.3, L = 2.0, Rb = 2.0; // the ends turn by ±0.5 rad
  test::Surface_mesh straight, bent;
  make_bent_tube(straight, 24, 20, r, L, 0, 0);
  make_bent_tube(bent, 36, 30, r, L, Rb, 0.07);
  for(bool reject : {true, false}) {
    auto out = get(CGAL::dynamic_vertex_property_t<test::Point>(), straight);
    const auto rep = shapecorr::nicps(straight, bent, out, SP::reject_boundary_pairs(reject));
    double inner = 0, ends = 0, before = 0, end_angle = 0;
    for(auto v : vertices(straight)) {
      const auto& p0 = straight.point(v);
      const auto& p = get(out, v);
      before = std::max(before, distance_to_bent_tube(Eigen::Vector3d(p0.x(), p0.y(), p0.z()), r, L, Rb));
      double phi = 0;
      const double d = distance_to_bent_tube(Eigen::Vector3d(p.x(), p.y(), p.z()), r, L, Rb, &phi);
      (std::abs(p0.z()) < L / 2 - 0.15 ? inner : ends) = std::max(std::abs(p0.z()) < L / 2 - 0.15 ? inner : ends, d);
      if(std::abs(p0.z() - L / 2) < 1e-12) end_angle += phi / 24; // the mean arc angle of the top ring
    }
    INFO("boundary rejection " << reject << ": largest distance to the bent tube " << before << " -> " << inner << " (all but two rings at each end), "
                               << ends << " (those rings); r = " << r << "; top ring at angle " << end_angle << " (0.5 expected); "
                               << rep.iterations.size() << " iterations, " << shapecorr::to_string(rep.stop));
    CHECK(before > 0.2);
    CHECK(inner < 0.02 * r);
    // the end rings: with rejection, a template vertex whose closest point is on the target's cut
    // gets no pair (the regularizer places it); without, the cut holds it
    CHECK(ends < (reject ? 0.15 : 0.06) * r);
    CHECK(end_angle == Approx(0.5).margin(0.03));
  }
}

TEST_CASE("NICPS rejects pairs on the target's boundary: an overhanging template is not pulled onto the cut", "[registration][nicps]") {
  // the target: the unit square; the template: [−0.5, 1.5] x [0, 1], 0.05 above it
  test::Surface_mesh target, tmpl;
  shapecorr::make_grid(target, 24, 24);
  shapecorr::make_grid(tmpl, 40, 20, 2.0, 1.0);
  test::transform_points(tmpl, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x() - 0.5, p.y(), 0.05); });
  auto leftmost = [&](bool reject) {
    auto out = get(CGAL::dynamic_vertex_property_t<test::Point>(), tmpl);
    shapecorr::nicps(tmpl, target, out, SP::reject_boundary_pairs(reject).number_of_iterations(30));
    double x = 1e9, zmax = 0;
    for(auto v : vertices(tmpl)) {
      x = std::min(x, get(out, v).x());
      if(get(out, v).x() > 0.05 && get(out, v).x() < 0.95) zmax = std::max(zmax, std::abs(get(out, v).z()));
    }
    return std::make_pair(x, zmax);
  };
  const auto kept = leftmost(true), pulled = leftmost(false);
  INFO("leftmost template x: " << kept.first << " with rejection, " << pulled.first << " without; height over the target " << kept.second);
  CHECK(kept.first < -0.4);   // the overhang keeps its shape
  CHECK(pulled.first > -0.3); // without rejection the cut pulls it in
  CHECK(kept.second < 0.005); // and over the target the template lies on it
}

TEST_CASE("NICPS onto a target with a hole and a second, distant component", "[registration][nicps]") {
  // the target: an ellipsoid without the faces of a cap around +z (a hole), plus a small sphere far away
  test::Surface_mesh ellipsoid, target, tmpl;
  make_ellipsoid(ellipsoid, 4, 1.3, 0.9, 0.75, 17);
  std::vector<std::array<double, 3>> P;
  std::vector<std::array<std::size_t, 3>> T;
  for(auto v : vertices(ellipsoid)) P.push_back({ellipsoid.point(v).x(), ellipsoid.point(v).y(), ellipsoid.point(v).z()});
  for(auto f : faces(ellipsoid)) {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    double z = 0;
    for(auto v : CGAL::vertices_around_face(ellipsoid.halfedge(f), ellipsoid)) t[k++] = v.idx(), z += ellipsoid.point(v).z() / 3;
    if(z < 0.7) T.push_back(t); // the cap z > 0.7 (about 0.28 across) is the hole
  }
  const std::size_t offset = P.size();
  test::Surface_mesh small;
  shapecorr::make_icosphere(small, 1);
  for(auto v : vertices(small)) P.push_back({0.2 * small.point(v).x() + 5, 0.2 * small.point(v).y(), 0.2 * small.point(v).z()});
  for(auto f : faces(small)) {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(auto v : CGAL::vertices_around_face(small.halfedge(f), small)) t[k++] = offset + v.idx();
    T.push_back(t);
  }
  shapecorr::internal::soup_to_mesh(P, T, target);
  make_ellipsoid(tmpl, 3, 1, 1, 1);
  auto out = tmpl.add_property_map<test::Surface_mesh::Vertex_index, test::Point>("v:fit").first;
  // the thesis's two-way pairs: every target vertex seeks the template, the distant sphere too
  shapecorr::nicps(tmpl, target, out);
  double reach = 0;
  for(auto v : vertices(tmpl)) reach = std::max(reach, out[v].x());
  INFO("largest x of the fit without a pair distance limit: " << reach);
  CHECK(reach > 2.0); // pulled towards the sphere at x = 5
  // with a limit on the pair distance (0.5, above the largest initial distance 0.3), it is ignored
  const auto rep = shapecorr::nicps(tmpl, target, out, SP::maximum_pair_distance(0.5));
  const double residual = ellipsoid_residual(tmpl, out, 1.3, 0.9, 0.75);
  INFO("worst relative residual to the ellipsoid, hole included: " << residual << "; " << rep.iterations.size() << " iterations");
  CHECK(residual < 0.03); // the template closes the hole smoothly
  CHECK_THROWS_AS(shapecorr::nicps(tmpl, target, out, SP::maximum_pair_distance(0.0)), shapecorr::Invalid_argument);
}
