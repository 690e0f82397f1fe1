// Rigid descriptors (thesis chapter 3): analytic contours of a plane patch and a cylinder, rigid
// motion invariance of every descriptor and axis, resampling robustness of the Spin Contour, the
// L1 contour distance's properties and its agreement with the kd-tree version, axis fallbacks,
// matching, errors; over Surface_mesh and Polyhedron_3.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace SP = shapecorr::parameters;
using shapecorr::Oriented_point;
using shapecorr::Spin_axis;

namespace {

// A sphere with a smooth, non-symmetric radial bump field (fixed seed).
template <typename Mesh>
void make_bumpy_sphere(Mesh& m, int subdivisions) {
  shapecorr::make_icosphere(m, subdivisions);
  test::transform_points(m, [](const Eigen::Vector3d& p) {
    const double r = 1.0 + 0.15 * std::sin(3 * p.x() + 1) * std::cos(2 * p.y()) + 0.1 * p.z() * p.z() * p.x() + 0.05 * p.y() +
                     0.08 * p.z() * p.z() * p.z() + 0.06 * p.x() * p.z();
    return Eigen::Vector3d(r * p);
  });
}

// An open tube of radius rho around z, z in [-H/2, H/2], N sides, S stacks.
template <typename Mesh>
void make_tube(Mesh& m, double rho, double H, int N, int S) {
  std::vector<std::array<double, 3>> P;
  std::vector<std::array<std::size_t, 3>> T;
  for(int s = 0; s <= S; ++s)
    for(int i = 0; i < N; ++i) {
      const double a = 2 * CGAL_PI * i / N;
      P.push_back({rho * std::cos(a), rho * std::sin(a), -H / 2 + H * s / S});
    }
  auto id = [&](int s, int i) { return static_cast<std::size_t>(s * N + (i % N)); };
  for(int s = 0; s < S; ++s)
    for(int i = 0; i < N; ++i) {
      T.push_back({id(s, i), id(s, i + 1), id(s + 1, i + 1)});
      T.push_back({id(s, i), id(s + 1, i + 1), id(s + 1, i)});
    }
  shapecorr::internal::soup_to_mesh(P, T, m);
}

template <typename Mesh>
typename boost::graph_traits<Mesh>::vertex_descriptor vertex_at(const Mesh& m, std::size_t i) {
  return test::vertices_in_index_order(m)[i];
}

bool same_contour(const shapecorr::Spin_contour& a, const shapecorr::Spin_contour& b, double tol) {
  if(a.rows() != b.rows()) return false;
  for(std::size_t r = 0; r < a.rows(); ++r) {
    if(a.row_end(r) - a.row_begin(r) != b.row_end(r) - b.row_begin(r)) return false;
    for(std::size_t i = a.row_begin(r), j = b.row_begin(r); i < a.row_end(r); ++i, ++j)
      if(std::abs(a.alphas()[i] - b.alphas()[j]) > tol) return false;
  }
  return true;
}

double image_difference(const shapecorr::Spin_image& a, const shapecorr::Spin_image& b) {
  double d = 0, s = 0;
  for(std::size_t i = 0; i < a.values().size(); ++i) {
    d += std::abs(a.values()[i] - b.values()[i]);
    s += std::abs(a.values()[i]);
  }
  return d / std::max(s, 1e-300);
}

} // namespace

TEMPLATE_LIST_TEST_CASE("Spin Contour of a flat square seen along an in-plane axis is the rectangle [0,1] x [-1,1]", "[descriptors][spin-contour]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 10, 10, 2.0, 2.0); // [0,2]^2, z = 0
  const shapecorr::Spin_descriptors<TestType> sd(m, SP::support_length(2.0).image_rows(std::size_t(120)).image_columns(std::size_t(60)));
  Oriented_point op;
  op.point = Eigen::Vector3d(1, 1, 0);
  op.axis = Eigen::Vector3d::UnitX(); // beta = x - 1 in [-1, 1], alpha = |y - 1| in [0, 1]
  const shapecorr::Spin_contour c = sd.spin_contour(op);
  // Rows with |beta_r| <= 1 / L: r = 30 ... 89; every one holds the interval [0, 0.5] (normalized).
  std::size_t filled = 0;
  for(std::size_t r = 0; r < c.rows(); ++r) {
    const std::size_t k = c.row_end(r) - c.row_begin(r);
    if(std::abs(c.beta(r)) > 0.5) {
      CHECK(k == 0);
      continue;
    }
    ++filled;
    REQUIRE(k >= 2);
    CHECK(c.alphas()[c.row_begin(r)] == Approx(0.0).margin(1e-6));
    CHECK(c.alphas()[c.row_end(r) - 1] == Approx(0.5).epsilon(1e-6));
    // Closing: the first and last rows carry the 30 column samples of [0, 0.5]; inner rows only their ends.
    CHECK(k == ((r == 30 || r == 89) ? 32u : 2u));
  }
  CHECK(filled == 60);
  CHECK(c.size() == 58 * 2 + 2 * 32);
}

TEMPLATE_LIST_TEST_CASE("Spin Contour of a tube seen from its axis is two vertical lines of width rho(1 - cos(pi/N))", "[descriptors][spin-contour]", test::Mesh_types) {
  TestType m;
  const double rho = 0.5, H = 1.0;
  const int N = 32;
  make_tube(m, rho, H, N, 7);
  const double L = 1.0;
  const shapecorr::Spin_descriptors<TestType> sd(m, SP::support_length(L).image_rows(std::size_t(41)).image_columns(std::size_t(50)));
  Oriented_point op; // centre of the tube, along its axis
  op.point = Eigen::Vector3d::Zero();
  op.axis = Eigen::Vector3d::UnitZ();
  const shapecorr::Spin_contour c = sd.spin_contour(op);
  const double inner = rho * std::cos(CGAL_PI / N) / L, outer = rho / L;
  std::size_t filled = 0;
  for(std::size_t r = 0; r < c.rows(); ++r) {
    const bool inside = std::abs(c.beta(r)) <= H / 2 / L;
    const std::size_t k = c.row_end(r) - c.row_begin(r);
    CHECK((k > 0) == inside);
    if(!inside) continue;
    ++filled;
    CHECK(c.alphas()[c.row_begin(r)] == Approx(inner).epsilon(1e-5));
    CHECK(c.alphas()[c.row_end(r) - 1] == Approx(outer).epsilon(1e-5));
    for(std::size_t i = c.row_begin(r); i < c.row_end(r); ++i) CHECK(c.alphas()[i] >= inner - 1e-5);
  }
  CHECK(filled == 21); // beta_r = 1 - (r + 1/2) 2/41 within [-1/2, 1/2]: r = 10 ... 30
}

// Area of the square [0,2]^2 (z = 0) in bin (row i, column j) of the exact face-based image with
// P = (1, 1, 0), axis (cos e, 0, sin e), support 2, 40 x 20 bins: beta = cos(e) (x - 1),
// alpha^2 = sin(e)^2 (x - 1)^2 + (y - 1)^2. Midpoint rule in x over the slab, exact in y.
double tilted_square_bin_area(double e, int i, int j) {
  const double top = 2.0 - 0.1 * i, bottom = top - 0.1, c = std::cos(e), s = std::sin(e);
  const double x0 = std::max(0.0, 1 + bottom / c), x1 = std::min(2.0, 1 + top / c);
  if(x1 <= x0) return 0.0;
  auto within = [](double a2, double u2) { return a2 <= u2 ? 0.0 : std::min(1.0, std::sqrt(a2 - u2)); };
  const int n = 20000;
  double sum = 0;
  for(int k = 0; k < n; ++k) {
    const double x = x0 + (x1 - x0) * (k + 0.5) / n, u2 = (s * (x - 1)) * (s * (x - 1));
    sum += 2 * (within(0.01 * (j + 1) * (j + 1), u2) - within(0.01 * j * j, u2));
  }
  return sum * (x1 - x0) / n;
}

TEMPLATE_LIST_TEST_CASE("exact face-based spin image: areas of annuli, strips and tilted planes", "[descriptors][face-spin-image]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 7, 9, 2.0, 2.0); // [0,2]^2, z = 0, an uneven triangulation
  const shapecorr::Spin_descriptors<TestType> sd(m, SP::support_length(2.0).image_rows(std::size_t(40)).image_columns(std::size_t(20)));
  SECTION("axis along the normal: the columns are annuli of the square, all in one row") {
    Oriented_point op;
    op.point = Eigen::Vector3d(1, 1, -0.013); // beta = 0.013: row 19 (beta in [0, 0.1])
    op.axis = Eigen::Vector3d::UnitZ();
    const shapecorr::Spin_image img = sd.exact_face_spin_image(op);
    double total = 0;
    for(std::size_t r = 0; r < 40; ++r)
      for(std::size_t c = 0; c < 20; ++c) {
        total += img.at(r, c);
        if(r != 19) CHECK(img.at(r, c) == 0.0f);
      }
    CHECK(total == Approx(4.0).epsilon(1e-6));
    for(std::size_t c = 0; c < 10; ++c) CHECK(img.at(19, c) == Approx(CGAL_PI * 0.01 * (2.0 * c + 1)).epsilon(1e-6));
    // the corner columns: the square minus the disc of radius 1 spread over alpha in [1, sqrt 2]
    double corners = 0;
    for(std::size_t c = 10; c < 15; ++c) corners += img.at(19, c);
    CHECK(corners == Approx(4.0 - CGAL_PI).epsilon(1e-6));
  }
  SECTION("axis in the plane (and tilted by 1e-8, 1e-4 and 0.3 rad): strips and their tilted versions") {
    for(double e : {0.0, 1e-8, 1e-4, 0.3}) {
      INFO("tilt " << e);
      Oriented_point op;
      op.point = Eigen::Vector3d(1, 1, 0);
      op.axis = Eigen::Vector3d(std::cos(e), 0, std::sin(e));
      const shapecorr::Spin_image img = sd.exact_face_spin_image(op);
      for(int i = 0; i < 40; ++i)
        for(int j = 0; j < 20; ++j) {
          const double expected = e == 0.0 ? ((i >= 10 && i < 30 && j < 10) ? 0.02 : 0.0) : tilted_square_bin_area(e, i, j);
          INFO("bin " << i << ", " << j);
          CHECK(img.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) == Approx(expected).margin(2e-8).epsilon(1e-5));
        }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("exact face-based image and Spin Contour agree: every contour point lies in a bin of positive area",
                   "[descriptors][face-spin-image]", test::Mesh_types) {
  // Two independent constructions: a contour point (alpha, beta_r) is a surface point on the row's
  // centre plane, so the surface has positive area in its bin (row r, column floor(alpha / w)).
  TestType m;
  make_bumpy_sphere(m, 3);
  const std::size_t R = 40, C = 20;
  for(Spin_axis axis : {Spin_axis::NORMAL, Spin_axis::CENTRAL_DIRECTION}) {
    const shapecorr::Spin_descriptors<TestType> sd(m, SP::spin_axis(axis).support_length(1.5).image_rows(R).image_columns(C));
    for(std::size_t i : {0u, 17u, 200u, 411u}) {
      const Oriented_point op = sd.oriented_point(vertex_at(m, i));
      const shapecorr::Spin_contour c = sd.spin_contour(op);
      const shapecorr::Spin_image img = sd.exact_face_spin_image(op);
      std::size_t checked = 0;
      for(std::size_t r = 0; r < R; ++r)
        for(std::size_t k = c.row_begin(r); k < c.row_end(r); ++k) {
          const double x = c.alphas()[k] * static_cast<double>(C); // in columns
          if(std::abs(x - std::round(x)) < 1e-4 || x >= static_cast<double>(C)) continue; // on a column border
          INFO("vertex " << i << ", row " << r << ", alpha " << c.alphas()[k]);
          CHECK(img.at(r, static_cast<std::size_t>(x)) > 0.0f);
          ++checked;
        }
      CHECK(checked > 20);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("spin descriptors are invariant under a rigid motion, for every axis", "[descriptors][invariance]", test::Mesh_types) {
  TestType a, b;
  make_bumpy_sphere(a, 3);
  make_bumpy_sphere(b, 3);
  const Eigen::Isometry3d T = test::representable_rigid_motion<TestType>(11);
  test::transform_points(b, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(T * p); });
  for(Spin_axis axis : {Spin_axis::NORMAL, Spin_axis::CENTRAL_DIRECTION, Spin_axis::LOCAL_CENTRAL_DIRECTION, Spin_axis::SHOT_LRF}) {
    INFO("axis " << static_cast<int>(axis));
    const auto np = SP::spin_axis(axis).support_length(1.5).image_rows(std::size_t(40)).image_columns(std::size_t(20)).central_radius(0.6).lrf_radius(0.5);
    const shapecorr::Spin_descriptors<TestType> da(a, np), db(b, np);
    for(std::size_t i : {0u, 17u, 200u, 411u}) {
      const Oriented_point pa = da.oriented_point(vertex_at(a, i)), pb = db.oriented_point(vertex_at(b, i));
      CHECK((T.linear() * pa.axis - pb.axis).norm() < 1e-9);
      CHECK(pa.fell_back_to_normal == pb.fell_back_to_normal);
      CHECK(same_contour(da.spin_contour(pa), db.spin_contour(pb), 1e-5));
      CHECK(image_difference(da.spin_image(pa), db.spin_image(pb)) < 1e-5);
      CHECK(image_difference(da.face_spin_image(pa), db.face_spin_image(pb)) < 1e-5);
      CHECK(image_difference(da.exact_face_spin_image(pa), db.exact_face_spin_image(pb)) < 1e-5);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("Spin Contour is robust to resampling; the face-based image tracks area", "[descriptors][resampling]", test::Mesh_types) {
  // The same torus at two resolutions: vertex (0, 0) is the same point on both.
  TestType coarse, fine;
  shapecorr::make_torus(coarse, 2.0, 0.7, 48, 18);
  shapecorr::make_torus(fine, 2.0, 0.7, 96, 36);
  const auto np = SP::spin_axis(Spin_axis::CENTRAL_DIRECTION).support_length(3.0).image_rows(std::size_t(60)).image_columns(std::size_t(30));
  const shapecorr::Spin_descriptors<TestType> dc(coarse, np), df(fine, np);
  // Same point, and for contrast points a quarter tube around (vertex (0, 4) of the coarse one,
  // (0, 8) of the fine one, also the same point) and a different place.
  const auto sc0 = dc.spin_contour(dc.oriented_point(vertex_at(coarse, 0)));
  const auto sf0 = df.spin_contour(df.oriented_point(vertex_at(fine, 0)));
  const auto sc4 = dc.spin_contour(dc.oriented_point(vertex_at(coarse, 4)));
  const auto sf8 = df.spin_contour(df.oriented_point(vertex_at(fine, 8)));
  const double same0 = shapecorr::contour_l1_distance(sc0, sf0), same4 = shapecorr::contour_l1_distance(sc4, sf8);
  const double other = shapecorr::contour_l1_distance(sc0, sf8);
  INFO("same point " << same0 << ", " << same4 << ", other point " << other);
  CHECK(same0 < 0.01);
  CHECK(same4 < 0.01);
  CHECK(other > 5 * std::max(same0, same4));
  // Face-based images integrate area: the totals agree with the area inside the support.
  const auto fc = dc.face_spin_image(dc.oriented_point(vertex_at(coarse, 0)));
  const auto ff = df.face_spin_image(df.oriented_point(vertex_at(fine, 0)));
  CHECK(image_difference(fc, ff) < 0.15);
  CHECK(shapecorr::spin_image_correlation(fc, ff).first > 0.9);
}

TEMPLATE_LIST_TEST_CASE("Spin Contour walk: faces listed in inconsistent orientations give the same contour", "[descriptors][spin-contour]", test::Mesh_types) {
  // The walk steps across shared edges by half-edge records; a neighbour that lists the edge the
  // same way round (inconsistent orientation, possible in a user's face list) swaps the carried
  // corners. Level sets do not depend on orientation: flipping every third face changes nothing
  // but the order in which a crossing point is interpolated (last-digit differences).
  TestType m;
  make_bumpy_sphere(m, 3);
  const shapecorr::internal::Indexed_mesh<TestType> im(m, CGAL::parameters::default_values());
  shapecorr::internal::Triangle_arrays flipped = im.arrays();
  for(Eigen::Index f = 0; f < flipped.F.rows(); f += 3) std::swap(flipped.F(f, 1), flipped.F(f, 2));
  const shapecorr::internal::Spin_geometry ga(im.arrays()), gb(flipped);
  std::size_t same_way = 0;
  for(const auto& h : gb.half_edges) same_way += h.flips != 0 ? 1 : 0;
  REQUIRE(same_way > gb.half_edges.size() / 8); // the swapped path is taken
  for(const auto& h : ga.half_edges) REQUIRE(h.flips == 0);
  shapecorr::internal::Spin_options o;
  o.support = 0.6 * ga.extent;
  o.rows = 60;
  o.cols = 30;
  shapecorr::internal::Spin_contour_workspace ws;
  std::size_t points = 0;
  for(std::size_t v = 0; v < im.arrays().number_of_vertices(); v += 37) {
    Oriented_point op;
    op.point = im.arrays().point(v);
    op.axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    const shapecorr::Spin_contour ca = shapecorr::internal::spin_contour(ga, op, o, ws);
    const shapecorr::Spin_contour cb = shapecorr::internal::spin_contour(gb, op, o, ws);
    REQUIRE(ca.size() == cb.size());
    for(std::size_t r = 0; r < ca.rows(); ++r) REQUIRE(ca.row_end(r) == cb.row_end(r));
    for(std::size_t i = 0; i < ca.size(); ++i) REQUIRE(cb.alphas()[i] == Approx(ca.alphas()[i]).margin(1e-6));
    points += ca.size();
  }
  REQUIRE(points > 1000);
}

TEST_CASE("contour L1 distance: zero on identical, symmetric, equal to the kd-tree version", "[descriptors][contour-distance]") {
  test::Surface_mesh m;
  make_bumpy_sphere(m, 3);
  const shapecorr::Spin_descriptors<test::Surface_mesh> sd(m, SP::spin_axis(Spin_axis::CENTRAL_DIRECTION));
  std::vector<shapecorr::Spin_contour> c;
  for(std::size_t i : {0u, 5u, 99u, 300u, 640u}) c.push_back(sd.spin_contour(sd.oriented_point(vertex_at(m, i))));
  for(std::size_t i = 0; i < c.size(); ++i) {
    REQUIRE(c[i].size() > 50);
    CHECK(shapecorr::contour_l1_distance(c[i], c[i]) == 0.0);
    for(std::size_t j = 0; j < c.size(); ++j) {
      const double d = shapecorr::contour_l1_distance(c[i], c[j]);
      CHECK(d == Approx(shapecorr::contour_l1_distance(c[j], c[i])).epsilon(1e-12));
      CHECK(d == Approx(shapecorr::point_set_l1_distance(c[i].points(), c[j].points())).epsilon(1e-6));
      if(i != j) CHECK(d > 0);
    }
  }
  shapecorr::Spin_contour empty(120);
  CHECK(shapecorr::contour_l1_distance(empty, empty) == 0.0);
  CHECK(std::isinf(shapecorr::contour_l1_distance(empty, c[0])));
  CHECK_THROWS_AS(shapecorr::contour_l1_distance(shapecorr::Spin_contour(60), c[0]), shapecorr::Invalid_argument);
}

TEMPLATE_LIST_TEST_CASE("axes fall back to the normal where they are undefined", "[descriptors][axes]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 20, 20, 2.0, 2.0); // flat: centroid (1, 1, 0) is vertex (10, 10)
  const auto centre = vertex_at(m, 10 * 21 + 10), corner = vertex_at(m, 0), edge_mid = vertex_at(m, 10);
  const shapecorr::Spin_descriptors<TestType> sd(m, SP::central_radius(0.3).lrf_radius(0.3));
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  auto at = [&](auto v, Spin_axis a) { return sd.oriented_point(v, a); };
  CHECK(at(centre, Spin_axis::NORMAL).axis.isApprox(z, 1e-12));
  // global centre direction at the centroid itself: undefined
  CHECK(at(centre, Spin_axis::CENTRAL_DIRECTION).fell_back_to_normal);
  CHECK(at(centre, Spin_axis::CENTRAL_DIRECTION).axis.isApprox(z, 1e-12));
  const Oriented_point c0 = at(corner, Spin_axis::CENTRAL_DIRECTION);
  CHECK_FALSE(c0.fell_back_to_normal);
  CHECK(c0.axis.isApprox(Eigen::Vector3d(1, 1, 0).normalized(), 1e-9));
  // local centre of a full disc: undefined; at a border it points inwards
  CHECK(at(centre, Spin_axis::LOCAL_CENTRAL_DIRECTION).fell_back_to_normal);
  const Oriented_point e = at(edge_mid, Spin_axis::LOCAL_CENTRAL_DIRECTION);
  CHECK_FALSE(e.fell_back_to_normal);
  CHECK(e.axis.isApprox(Eigen::Vector3d::UnitY(), 1e-6));
  // SHOT frame on a flat, isotropic neighbourhood: undefined (repeated eigenvalue) or the normal
  const Oriented_point s = at(centre, Spin_axis::SHOT_LRF);
  CHECK(std::abs(s.axis.dot(z)) == Approx(1.0).epsilon(1e-9));
}

TEMPLATE_LIST_TEST_CASE("SHOT frame: orthonormal, right-handed, third axis along the normal of a curved patch", "[descriptors][axes]", test::Mesh_types) {
  TestType m;
  make_bumpy_sphere(m, 4);
  const shapecorr::Spin_descriptors<TestType> sd(m, SP::lrf_radius(0.25));
  std::size_t aligned = 0, tried = 0;
  for(std::size_t i = 0; i < num_vertices(m); i += 97) {
    const auto v = vertex_at(m, i);
    Eigen::Matrix3d F;
    if(!sd.shot_frame(sd.oriented_point(v).point, F)) continue;
    ++tried;
    CHECK((F.transpose() * F - Eigen::Matrix3d::Identity()).norm() < 1e-9);
    CHECK(F.determinant() == Approx(1.0).epsilon(1e-9));
    if(std::abs(F.col(2).dot(sd.oriented_point(v, Spin_axis::NORMAL).axis)) > 0.95) ++aligned;
  }
  REQUIRE(tried > 20);
  CHECK(aligned == tried);
}

TEMPLATE_LIST_TEST_CASE("surface points: a face location at a corner is that vertex; face normal axis", "[descriptors][surface-points]", test::Mesh_types) {
  TestType m;
  make_bumpy_sphere(m, 2);
  const shapecorr::Spin_descriptors<TestType> sd(m);
  const auto f = *faces(m).begin();
  const auto h = halfedge(f, m);
  const auto v0 = target(prev(h, m), m); // CGAL's first barycentric coordinate is source(halfedge(f))
  typename shapecorr::Spin_descriptors<TestType>::Face_location loc(f, {{1.0, 0.0, 0.0}});
  const Oriented_point op = sd.oriented_point(loc);
  CHECK((op.point - sd.oriented_point(v0).point).norm() < 1e-12);
  // the face normal is orthogonal to its edges
  const auto p = get(CGAL::vertex_point, m);
  const auto a = get(p, source(h, m)), b = get(p, target(h, m));
  CHECK(std::abs(op.axis.dot(Eigen::Vector3d(b.x() - a.x(), b.y() - a.y(), b.z() - a.z()))) < 1e-12);
}

TEMPLATE_LIST_TEST_CASE("matching descriptors of a moved copy finds every vertex itself", "[descriptors][matching]", test::Mesh_types) {
  TestType a, b;
  make_bumpy_sphere(a, 2);
  make_bumpy_sphere(b, 2);
  const Eigen::Isometry3d T = test::random_rigid_motion(3);
  test::transform_points(b, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(T * p); });
  const auto np = SP::spin_axis(Spin_axis::CENTRAL_DIRECTION).image_rows(std::size_t(40)).image_columns(std::size_t(20));
  auto ca = get(CGAL::dynamic_vertex_property_t<shapecorr::Spin_contour>(), a);
  auto cb = get(CGAL::dynamic_vertex_property_t<shapecorr::Spin_contour>(), b);
  shapecorr::compute_spin_contours(a, vertices(a), ca, np);
  shapecorr::compute_spin_contours(b, vertices(b), cb, np);
  const auto va = test::vertices_in_index_order(a), vb = test::vertices_in_index_order(b);
  std::vector<shapecorr::Spin_contour> sa, sb;
  for(std::size_t i = 0; i < va.size(); i += 7) sa.push_back(get(ca, va[i]));
  for(auto v : vb) sb.push_back(get(cb, v));
  const auto matches = shapecorr::match_descriptors(sa, sb, shapecorr::Contour_l1_distance());
  std::size_t correct = 0;
  for(const auto& mt : matches) {
    CHECK(mt.distance <= mt.second_distance);
    CHECK(mt.ratio() <= 1.0);
    correct += mt.target == 7 * mt.source;
  }
  CHECK(correct == matches.size());
  // The same through spin images and their correlation distance.
  auto ia = get(CGAL::dynamic_vertex_property_t<shapecorr::Spin_image>(), a);
  auto ib = get(CGAL::dynamic_vertex_property_t<shapecorr::Spin_image>(), b);
  shapecorr::compute_face_spin_images(a, vertices(a), ia, np);
  shapecorr::compute_face_spin_images(b, vertices(b), ib, np);
  std::vector<shapecorr::Spin_image> ja, jb;
  for(std::size_t i = 0; i < va.size(); i += 7) ja.push_back(get(ia, va[i]));
  for(auto v : vb) jb.push_back(get(ib, v));
  correct = 0;
  for(const auto& mt : shapecorr::match_descriptors(ja, jb, shapecorr::Spin_image_distance())) correct += mt.target == 7 * mt.source;
  CHECK(correct == ja.size());
  // And through the exact-area images, whose property-map form equals the member function.
  shapecorr::compute_exact_face_spin_images(a, vertices(a), ia, np);
  shapecorr::compute_exact_face_spin_images(b, vertices(b), ib, np);
  ja.clear();
  jb.clear();
  for(std::size_t i = 0; i < va.size(); i += 7) ja.push_back(get(ia, va[i]));
  for(auto v : vb) jb.push_back(get(ib, v));
  const shapecorr::Spin_descriptors<TestType> sda(a, np);
  CHECK(ja[3].values() == sda.exact_face_spin_image(sda.oriented_point(va[21])).values());
  correct = 0;
  for(const auto& mt : shapecorr::match_descriptors(ja, jb, shapecorr::Spin_image_distance())) correct += mt.target == 7 * mt.source;
  CHECK(correct == ja.size());
  // And through the contours' distance fields (approximate L1).
  std::vector<shapecorr::Contour_distance_field> fa, fb;
  for(const auto& c : sa) fa.emplace_back(c);
  for(const auto& c : sb) fb.emplace_back(c);
  correct = 0;
  for(const auto& mt : shapecorr::match_descriptors(fa, fb, shapecorr::Approximate_contour_l1_distance())) correct += mt.target == 7 * mt.source;
  CHECK(correct == fa.size());
  // And through the contours' nearest-point indices: the same matches and distances as the contours.
  std::vector<shapecorr::Contour_nearest_point_index> xa, xb;
  for(const auto& c : sa) xa.emplace_back(c);
  for(const auto& c : sb) xb.emplace_back(c);
  const auto indexed = shapecorr::match_descriptors(xa, xb, shapecorr::Indexed_contour_l1_distance());
  REQUIRE(indexed.size() == matches.size());
  for(std::size_t i = 0; i < matches.size(); ++i) {
    CHECK(indexed[i].target == matches[i].target);
    CHECK(indexed[i].distance == Approx(matches[i].distance).epsilon(1e-12));
  }
}

TEST_CASE("spin image comparison: correlation of proportional images is 1, similarity ranks", "[descriptors][spin-image]") {
  shapecorr::Spin_image a(4, 3, 1.0), b(4, 3, 1.0), c(4, 3, 1.0);
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0.1f, 1.0f);
  for(std::size_t i = 0; i < 12; ++i) {
    a.values()[i] = u(rng);
    b.values()[i] = 2.5f * a.values()[i];
    c.values()[i] = u(rng);
  }
  CHECK(shapecorr::spin_image_correlation(a, b).first == Approx(1.0).epsilon(1e-6));
  CHECK(shapecorr::spin_image_correlation(a, b).second == 12u);
  CHECK(shapecorr::Spin_image_distance()(a, b) == Approx(0.0).margin(1e-6));
  CHECK(shapecorr::spin_image_similarity(a, b) > shapecorr::spin_image_similarity(a, c));
  CHECK_THROWS_AS(shapecorr::spin_image_correlation(a, shapecorr::Spin_image(3, 3, 1.0)), shapecorr::Invalid_argument);
}

TEST_CASE("spin descriptors: bad parameters and meshes are typed errors", "[descriptors][errors]") {
  test::Surface_mesh m;
  shapecorr::make_icosphere(m, 1);
  CHECK_THROWS_AS(shapecorr::Spin_descriptors<test::Surface_mesh>(m, SP::support_length(-1.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Spin_descriptors<test::Surface_mesh>(m, SP::image_rows(std::size_t(1))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Spin_descriptors<test::Surface_mesh>(m, SP::lrf_radius(0.0)), shapecorr::Invalid_argument);
  test::Surface_mesh empty;
  CHECK_THROWS_AS(shapecorr::Spin_descriptors<test::Surface_mesh>(empty), shapecorr::Invalid_input);
  test::Surface_mesh bad;
  shapecorr::make_icosphere(bad, 1);
  put(get(CGAL::vertex_point, bad), *vertices(bad).begin(), test::Point(std::nan(""), 0, 0));
  CHECK_THROWS_AS(shapecorr::Spin_descriptors<test::Surface_mesh>(bad), shapecorr::Invalid_input);
}

TEST_CASE("contour L1 distance with a bound: exact below it, above it when exceeded", "[descriptors][contour-distance]") {
  test::Surface_mesh m;
  make_bumpy_sphere(m, 3);
  const shapecorr::Spin_descriptors<test::Surface_mesh> sd(m, SP::spin_axis(Spin_axis::CENTRAL_DIRECTION));
  const auto a = sd.spin_contour(sd.oriented_point(vertex_at(m, 3))), b = sd.spin_contour(sd.oriented_point(vertex_at(m, 400)));
  const double d = shapecorr::contour_l1_distance(a, b);
  REQUIRE(d > 0);
  CHECK(shapecorr::contour_l1_distance(a, b, 2 * d) == d);
  CHECK(shapecorr::contour_l1_distance(a, b, 0.5 * d) > 0.5 * d);
  CHECK(shapecorr::contour_l1_distance(a, b, 0.0) > 0.0);
}

namespace {
// The directed sum of contour_l1_distance: the points of X against Y.
double internal_sum(const shapecorr::Spin_contour& X, const shapecorr::Spin_contour& Y) {
  return shapecorr::internal::directed_contour_sum(X, Y, std::numeric_limits<double>::infinity());
}
// Distance from (alpha, row r) to the nearest point of c, by brute force.
double brute_distance(const shapecorr::Spin_contour& c, std::size_t r, double alpha) {
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t q = 0; q < c.rows(); ++q)
    for(std::size_t i = c.row_begin(q); i < c.row_end(q); ++i) {
      const double da = alpha - c.alphas()[i], db = (static_cast<double>(r) - static_cast<double>(q)) * c.row_spacing();
      best = std::min(best, std::sqrt(da * da + db * db));
    }
  return best;
}
// Spin Contours (central direction) of five vertices spread over a bumpy sphere.
template <typename Mesh>
std::vector<shapecorr::Spin_contour> spread_contours(const Mesh& m) {
  const shapecorr::Spin_descriptors<Mesh> sd(m, SP::spin_axis(Spin_axis::CENTRAL_DIRECTION));
  std::vector<shapecorr::Spin_contour> c;
  for(std::size_t i : {0u, 5u, 99u, 300u, 640u}) c.push_back(sd.spin_contour(sd.oriented_point(vertex_at(m, i))));
  return c;
}
} // namespace

TEMPLATE_LIST_TEST_CASE("contour distance field: exact samples, approximate L1 within its bound, symmetric", "[descriptors][contour-distance][distance-field]", test::Mesh_types) {
  TestType m;
  make_bumpy_sphere(m, 3);
  const std::vector<shapecorr::Spin_contour> c = spread_contours(m);
  for(std::size_t samples : {121u, 31u, 5u}) {
    std::vector<shapecorr::Contour_distance_field> f;
    for(const auto& x : c) f.emplace_back(x, samples);
    for(std::size_t i = 0; i < c.size(); ++i) {
      REQUIRE(f[i].alpha_samples() == samples);
      CHECK(f[i].alpha_min() == 0.0);
      CHECK(f[i].alpha_max() == 1.0);
      CHECK(f[i].error_bound() == Approx(0.5 / static_cast<double>(samples - 1)).margin(1e-4));
      // the samples are the nearest distances (to the 16-bit quantization)
      for(std::size_t r = 0; r < c[i].rows(); r += 7)
        for(std::size_t k = 0; k < samples; k += 3)
          CHECK(f[i].sample(r, k) == Approx(brute_distance(c[i], r, f[i].alpha_min() + static_cast<double>(k) * f[i].sample_spacing())).margin(1e-4));
      // a contour compared with itself: at most the bound
      CHECK(shapecorr::approximate_contour_l1_distance(f[i], f[i]) <= f[i].error_bound());
      for(std::size_t j = 0; j < c.size(); ++j) {
        const double exact = shapecorr::contour_l1_distance(c[i], c[j]);
        const double approx = shapecorr::approximate_contour_l1_distance(f[i], f[j]);
        CHECK(approx == shapecorr::approximate_contour_l1_distance(f[j], f[i]));
        // the same-grid path (precomputed cells) equals the general one (from the alphas)
        CHECK(f[j].sum_of_distances(f[i]) == Approx(f[j].sum_of_distances(c[i])).epsilon(1e-6));
        CHECK(std::abs(approx - exact) <= std::max(f[i].error_bound(), f[j].error_bound()));
        if(samples == 121u && i != j) CHECK(std::abs(approx - exact) <= 0.05 * exact);
      }
    }
    // interpolated distances of single points lie within the bound too
    for(std::size_t r = 0; r < c[0].rows(); r += 5)
      for(double a : {0.013, 0.25, 0.5001, 0.77, 0.999})
        CHECK(std::abs(f[0].distance(r, a) - brute_distance(c[0], r, a)) <= f[0].error_bound());
  }
}

TEST_CASE("contour distance field of hand-made contours: analytic distances, range, bounds and errors", "[descriptors][contour-distance][distance-field]") {
  // every row holds alpha = 0.3: the distance from (alpha, any row) is |alpha - 0.3|
  shapecorr::Spin_contour line(10);
  const std::vector<float> p{0.3f};
  for(std::size_t r = 0; r < 10; ++r) line.append_row(r, p.begin(), p.end());
  const shapecorr::Contour_distance_field fl(line, 11);
  CHECK(fl.sample_spacing() == Approx(0.1));
  for(std::size_t r = 0; r < 10; ++r) {
    CHECK(fl.distance(r, 0.8) == Approx(0.5).margin(1e-4));  // a cell away from 0.3: exact
    CHECK(fl.distance(r, 0.3) == Approx(0.0).margin(1e-4));  // on a sample
    CHECK(fl.distance(r, 0.35) == Approx(0.05).margin(1e-4)); // between samples 0.3 and 0.4: linear there
    CHECK(fl.distance(r, 1.5) == Approx(1.2).margin(1e-4));  // outside [0, 1]: the Lipschitz extension
  }
  // one point in row 0 at alpha 0.5: straight above it the distance is the row gap
  shapecorr::Spin_contour dot(10);
  const std::vector<float> q{0.5f}, none;
  dot.append_row(0, q.begin(), q.end());
  for(std::size_t r = 1; r < 10; ++r) dot.append_row(r, none.begin(), none.end());
  const shapecorr::Contour_distance_field fd(dot, 11);
  for(std::size_t r = 0; r < 10; ++r) {
    CHECK(fd.distance(r, 0.5) == Approx(static_cast<double>(r) * dot.row_spacing()).margin(1e-4));
    CHECK(fd.distance(r, 0.1) == Approx(std::hypot(0.4, static_cast<double>(r) * dot.row_spacing())).margin(1e-4));
  }
  // alphas beyond [0, 1] widen the sampled range
  shapecorr::Spin_contour wide(10);
  const std::vector<float> w{-0.5f, 1.25f};
  for(std::size_t r = 0; r < 10; ++r) wide.append_row(r, w.begin(), w.end());
  const shapecorr::Contour_distance_field fw(wide);
  CHECK(fw.alpha_min() == Approx(-0.5));
  CHECK(fw.alpha_max() == Approx(1.25));
  CHECK(fw.memory_bytes() == 10u * 121u * 2u);
  // fields on different grids (ranges or sample counts) compare through the general path
  const shapecorr::Contour_distance_field fl121(line);
  for(const auto* g : {&fl, &fl121}) {
    const double exact = shapecorr::contour_l1_distance(wide, line);
    CHECK(std::abs(shapecorr::approximate_contour_l1_distance(fw, *g) - exact) <= std::max(fw.error_bound(), g->error_bound()));
    CHECK(shapecorr::approximate_contour_l1_distance(fw, *g) == shapecorr::approximate_contour_l1_distance(*g, fw));
  }
  // the bound: exact below it, some value above it once exceeded
  const double d = shapecorr::approximate_contour_l1_distance(fl, fd);
  REQUIRE(d > 0);
  CHECK(shapecorr::approximate_contour_l1_distance(fl, fd, 2 * d) == d);
  CHECK(shapecorr::approximate_contour_l1_distance(fl, fd, 0.5 * d) > 0.5 * d);
  // empty contours as in contour_l1_distance; mismatched rows and too few samples are typed errors
  const shapecorr::Contour_distance_field fe(shapecorr::Spin_contour(10));
  CHECK(shapecorr::approximate_contour_l1_distance(fe, fe) == 0.0);
  CHECK(std::isinf(shapecorr::approximate_contour_l1_distance(fe, fl)));
  CHECK(std::isinf(fe.distance(0, 0.5)));
  CHECK_THROWS_AS(shapecorr::approximate_contour_l1_distance(shapecorr::Contour_distance_field(shapecorr::Spin_contour(12)), fl), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Contour_distance_field(line, 1), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(fl.distance(10, 0.5), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(fl.sum_of_distances(shapecorr::Spin_contour(12)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(fl.sum_of_distances(shapecorr::Contour_distance_field(shapecorr::Spin_contour(12))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Contour_distance_field(shapecorr::Spin_contour(0)), shapecorr::Invalid_argument);
}

namespace {
// |x - y| within rounding (the index evaluates each distance as contour_l1_distance does; only
// breakpoints between nearly equal alphas can round differently)
bool same_value(double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(1.0, std::abs(y)); }
} // namespace

TEMPLATE_LIST_TEST_CASE("contour nearest-point index: the exact L1 distance, at every cell count, on any grid", "[descriptors][contour-distance][nearest-point-index]", test::Mesh_types) {
  TestType m;
  make_bumpy_sphere(m, 3);
  const std::vector<shapecorr::Spin_contour> c = spread_contours(m);
  // the geodesic contours of the same mesh (alphas by the agd range, beta in [0, 1])
  const shapecorr::Geodesic_spin_descriptors<TestType> gs(m, SP::support_fraction(0.4).agd_radius_fraction(0.15));
  const std::vector<shapecorr::Spin_contour> g = gs.geodesic_spin_contours({0, 5, 99, 300, 640});
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-0.2f, 1.2f);
  for(const auto* set : {&c, &g}) {
    const auto& cs = *set;
    std::vector<shapecorr::Contour_nearest_point_index> fine, coarse;
    for(const auto& x : cs) {
      fine.emplace_back(x);       // 128 cells: few slow cells
      coarse.emplace_back(x, 1);  // one cell: most points take the row search
    }
    for(std::size_t i = 0; i < cs.size(); ++i) {
      REQUIRE(!cs[i].empty());
      CHECK(fine[i].cells_per_row() == 128);
      CHECK(fine[i].slow_cell_fraction() < 0.05);
      CHECK(coarse[i].slow_cell_fraction() > 0.2);
      CHECK(fine[i].number_of_pieces() >= cs[i].rows());
      CHECK(shapecorr::contour_l1_distance(fine[i], fine[i]) == 0.0);
      // single points, on and off the sampled range: the brute-force nearest distance
      for(std::size_t r = 0; r < cs[i].rows(); r += 3)
        for(int k = 0; k < 4; ++k) {
          const float a = u(rng);
          CHECK(fine[i].distance(r, a) == Approx(brute_distance(cs[i], r, a)).epsilon(1e-9).margin(1e-12));
          CHECK(coarse[i].distance(r, a) == Approx(brute_distance(cs[i], r, a)).epsilon(1e-9).margin(1e-12));
        }
      for(std::size_t j = 0; j < cs.size(); ++j) {
        const double exact = shapecorr::contour_l1_distance(cs[i], cs[j]);
        CHECK(same_value(shapecorr::contour_l1_distance(fine[i], fine[j]), exact));
        CHECK(same_value(shapecorr::contour_l1_distance(coarse[i], coarse[j]), exact));
        CHECK(same_value(shapecorr::contour_l1_distance(fine[i], coarse[j]), exact)); // different grids
        CHECK(shapecorr::contour_l1_distance(fine[i], fine[j]) == shapecorr::contour_l1_distance(fine[j], fine[i]));
        // the bound as in contour_l1_distance
        if(i != j) {
          CHECK(same_value(shapecorr::contour_l1_distance(fine[i], fine[j], 2 * exact), exact));
          CHECK(shapecorr::contour_l1_distance(fine[i], fine[j], 0.5 * exact) > 0.5 * exact);
        }
      }
    }
  }
}

TEST_CASE("contour nearest-point index of hand-made contours: analytic distances, dense rows, outer cells and errors", "[descriptors][contour-distance][nearest-point-index]") {
  // every row holds alpha = 0.3: the distance from (alpha, any row) is |alpha - 0.3|
  shapecorr::Spin_contour line(10);
  const std::vector<float> p{0.3f};
  for(std::size_t r = 0; r < 10; ++r) line.append_row(r, p.begin(), p.end());
  const shapecorr::Contour_nearest_point_index xl(line, 8);
  for(std::size_t r = 0; r < 10; ++r)
    for(float a : {-3.0f, 0.0f, 0.3f, 0.35f, 0.8f, 1.0f, 7.5f}) CHECK(xl.distance(r, a) == std::abs(static_cast<double>(a) - static_cast<double>(0.3f)));
  // one point in row 0 at alpha 0.5: straight above it the distance is the row gap
  shapecorr::Spin_contour dot(10);
  const std::vector<float> q{0.5f}, none;
  dot.append_row(0, q.begin(), q.end());
  for(std::size_t r = 1; r < 10; ++r) dot.append_row(r, none.begin(), none.end());
  const shapecorr::Contour_nearest_point_index xd(dot);
  for(std::size_t r = 0; r < 10; ++r) {
    CHECK(xd.distance(r, 0.5f) == Approx(static_cast<double>(r) * dot.row_spacing()).epsilon(1e-12));
    CHECK(xd.distance(r, 0.1f) == Approx(std::hypot(0.5 - static_cast<double>(0.1f), static_cast<double>(r) * dot.row_spacing())).epsilon(1e-12));
  }
  // alphas beyond [0, 1], a dense row (many pieces in one cell: the row search), equal alphas in
  // several rows, and queries beyond every cell
  shapecorr::Spin_contour wild(10);
  std::vector<std::vector<float>> rows(10);
  rows[0] = {-0.5f, 1.25f};
  for(int k = 0; k < 300; ++k) rows[3].push_back(0.4f + 1e-4f * static_cast<float>(k));
  rows[4] = {0.6f};
  rows[6] = {0.6f, 0.9f};
  rows[9] = {0.6f, 2.0f};
  for(std::size_t r = 0; r < 10; ++r) wild.append_row(r, rows[r].begin(), rows[r].end());
  const shapecorr::Contour_nearest_point_index xw(wild);
  CHECK(xw.slow_cell_fraction() > 0.0);
  shapecorr::Spin_contour far(10);
  std::vector<float> f{-2.0f, 0.41f, 0.6f, 3.0f};
  for(std::size_t r = 0; r < 10; ++r) far.append_row(r, f.begin(), f.end());
  const shapecorr::Contour_nearest_point_index xf(far, 3);
  for(std::size_t r = 0; r < 10; ++r)
    for(float a : {-2.0f, -0.7f, 0.0f, 0.41f, 0.4150f, 0.6f, 1.1f, 2.0f, 3.0f}) CHECK(xw.distance(r, a) == Approx(brute_distance(wild, r, a)).epsilon(1e-12));
  for(const auto* x : {&xl, &xd, &xw, &xf})
    for(const auto* y : {&xl, &xd, &xw, &xf}) {
      CHECK(same_value(shapecorr::contour_l1_distance(*x, *y), shapecorr::contour_l1_distance(x->contour(), y->contour())));
      CHECK(same_value(x->sum_of_distances(*y), internal_sum(y->contour(), x->contour())));
    }
  // empty contours as in contour_l1_distance; typed errors
  const shapecorr::Contour_nearest_point_index xe(shapecorr::Spin_contour(10));
  CHECK(shapecorr::contour_l1_distance(xe, xe) == 0.0);
  CHECK(std::isinf(shapecorr::contour_l1_distance(xe, xl)));
  CHECK(std::isinf(xe.distance(0, 0.5f)));
  CHECK(xe.memory_bytes() < xl.memory_bytes());
  CHECK_THROWS_AS(shapecorr::contour_l1_distance(shapecorr::Contour_nearest_point_index(shapecorr::Spin_contour(12)), xl), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(xl.sum_of_distances(shapecorr::Contour_nearest_point_index(shapecorr::Spin_contour(12))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Contour_nearest_point_index(line, 0), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Contour_nearest_point_index(line, 65537), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Contour_nearest_point_index(shapecorr::Spin_contour(0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(xl.distance(10, 0.5f), shapecorr::Invalid_argument);
  // a rigid and a geodesic contour (rows on different lines) are not comparable
  const shapecorr::Contour_nearest_point_index xg(shapecorr::Spin_contour(10, 1.0, 0.0, 1.0));
  CHECK_THROWS_AS(shapecorr::contour_l1_distance(xg, xl), shapecorr::Invalid_argument);
}
