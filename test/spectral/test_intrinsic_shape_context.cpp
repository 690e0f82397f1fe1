// The intrinsic shape context: analytic oracles (a constant descriptor, a linear function on a flat
// disc, whose Fourier modulus over the directions is known in closed form), invariance under a
// rigid motion with renumbering, the ball overload, the property-map function, and bad input.
#include "spectral_test_helpers.h"
#include "test_renumbering.h"

#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/spectral.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace SP = shapecorr::parameters;

namespace {
const double pi = 3.14159265358979323846;

// The closed form of ring r's first Fourier modulus for f = linear with unit gradient on a flat
// disc, from the documented binning taken continuous: a point at (rho, theta) weighs
// rho * ring_weight(rho) (area element times the ring's tent), its direction bins see the mean
// of rho cos(theta - phi) under the angular tent, whose first Fourier coefficient is attenuated
// by sinc^2(pi / T); |X_1| = (1/2) x (weighted mean of rho) x sinc^2(pi / T).
double expected_first_harmonic(int r, int rings, int dirs, double R) {
  auto weight = [&](double rho) {
    const double c = rho / R * rings - 0.5;
    if(c <= 0) return r == 0 ? 1.0 : 0.0;
    if(c >= rings - 1) return r == rings - 1 ? 1.0 : 0.0;
    const double f = c - std::floor(c);
    const int r0 = static_cast<int>(std::floor(c));
    return r == r0 ? 1 - f : r == r0 + 1 ? f : 0.0;
  };
  double num = 0, den = 0;
  const int steps = 20000;
  for(int i = 0; i < steps; ++i) {
    const double rho = (i + 0.5) * R / steps, w = rho * weight(rho);
    num += w * rho;
    den += w;
  }
  const double s = std::sin(pi / dirs) / (pi / dirs);
  return 0.5 * num / den * s * s;
}
} // namespace

TEMPLATE_LIST_TEST_CASE("Intrinsic shape context of a constant descriptor: the constant at frequency 0, nothing else",
                        "[spectral][isc]", test::Mesh_types) {
  TestType m;
  test::make_ellipsoid(m, 3);
  const std::size_t n = num_vertices(m);
  const shapecorr::Intrinsic_shape_context<TestType> isc(m, Eigen::MatrixXd::Constant(long(n), 2, 0.7), SP::support_fraction(0.2));
  CHECK(isc.size() == 5 * 9 * 2);
  CHECK(isc.rings() == 5);
  CHECK(isc.directions() == 16);
  const Eigen::MatrixXd D = isc.descriptors({0, 100, 641});
  REQUIRE(D.rows() == 3);
  for(Eigen::Index p = 0; p < 3; ++p)
    for(Eigen::Index r = 0; r < 5; ++r)
      for(Eigen::Index k = 0; k < 9; ++k)
        for(Eigen::Index c = 0; c < 2; ++c) CHECK(D(p, (r * 9 + k) * 2 + c) == Approx(k == 0 ? 0.7 : 0.0).margin(1e-12));
}

TEMPLATE_LIST_TEST_CASE("Intrinsic shape context of a linear function on a flat disc: the closed form, whatever the gradient's direction",
                        "[spectral][isc]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 80, 80);
  const std::size_t n = num_vertices(m);
  const std::size_t centre = 40 * 81 + 40;
  // three linear functions of unit gradient, through the centre, along three directions
  const double phi[3] = {0.0, 0.7, 2.0};
  Eigen::MatrixXd f(long(n), 3);
  for(std::size_t v = 0; v < n; ++v) {
    const double x = double(v % 81) / 80 - 0.5, y = double(v / 81) / 80 - 0.5;
    for(int c = 0; c < 3; ++c) f(long(v), c) = x * std::cos(phi[c]) + y * std::sin(phi[c]);
  }
  const double R = 0.3;
  const shapecorr::Intrinsic_shape_context<TestType> isc(m, f, SP::support_length(R));
  const Eigen::MatrixXd D = isc.descriptors({centre});
  auto at = [&](int r, int k, int c) { return D(0, (r * 9 + k) * 3 + c); };
  for(int r = 1; r < 5; ++r) { // (ring 0: a few vertices around the centre, no continuum)
    const double expected = expected_first_harmonic(r, 5, 16, R);
    for(int c = 0; c < 3; ++c) {
      INFO("ring " << r << ", gradient direction " << phi[c] << ": |X_1| " << at(r, 1, c) << ", closed form " << expected);
      CHECK(at(r, 1, c) == Approx(expected).epsilon(0.05));
      CHECK(at(r, 0, c) < 0.05 * expected); // the ring's mean of a function odd about the centre
      for(int k = 2; k < 9; ++k) CHECK(at(r, k, c) < 0.1 * expected);
    }
  }
}

TEST_CASE("Intrinsic shape context is invariant under a rigid motion and vertex renumbering", "[spectral][isc][invariance]") {
  test::Surface_mesh a;
  test::make_ellipsoid(a, 4);
  std::vector<std::size_t> perm;
  test::Surface_mesh b = test::renumbered_copy(a, 3, perm);
  const Eigen::Isometry3d T = test::random_rigid_motion(5);
  test::transform_points(b, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(T * p); });
  // the same pointwise descriptor on both (the SI-HKS of a, carried by the renumbering)
  const auto basis = shapecorr::compute_laplace_beltrami_eigenbasis(a, 60);
  const Eigen::MatrixXd fa = shapecorr::scale_invariant_heat_kernel_signature_matrix(basis);
  Eigen::MatrixXd fb(fa.rows(), fa.cols());
  for(std::size_t i = 0; i < perm.size(); ++i) fb.row(long(perm[i])) = fa.row(long(i));
  const auto np = SP::support_fraction(0.15);
  const shapecorr::Intrinsic_shape_context<test::Surface_mesh> ia(a, fa, np), ib(b, fb, np);
  CHECK(ia.radius() == Approx(ib.radius()).epsilon(1e-9));
  std::vector<std::size_t> pa, pb;
  for(std::size_t i = 0; i < perm.size(); i += 97) {
    pa.push_back(i);
    pb.push_back(perm[i]);
  }
  const Eigen::MatrixXd Da = ia.descriptors(pa), Db = ib.descriptors(pb);
  // The frame's first axis depends on the coordinates: the histograms of a and b are the same up
  // to a rotation of the directions, which the Fourier modulus removes up to the linear binning.
  // That difference is small against the descriptor and against the distances to the other
  // points' descriptors (the median: the ellipsoid's mirror images of a point are alike).
  for(Eigen::Index p = 0; p < Da.rows(); ++p) {
    std::vector<double> others;
    for(Eigen::Index q = 0; q < Da.rows(); ++q)
      if(q != p) others.push_back((Da.row(p) - Da.row(q)).norm());
    std::nth_element(others.begin(), others.begin() + long(others.size() / 2), others.end());
    const double same = (Da.row(p) - Db.row(p)).norm();
    INFO("point " << pa[std::size_t(p)] << ": " << same << " from its moved copy, median to the others " << others[others.size() / 2]);
    CHECK(same < 0.02 * Da.row(p).norm());
    CHECK(same < 0.1 * others[others.size() / 2]);
  }
}

TEST_CASE("Intrinsic shape context: from a ball of distances, through a property map", "[spectral][isc]") {
  test::Surface_mesh m;
  test::make_ellipsoid(m, 3);
  const shapecorr::Intrinsic_shape_context<test::Surface_mesh> isc(m, SP::number_of_eigenpairs(40).support_fraction(0.2));
  CHECK(isc.signatures().rows() == 642);
  CHECK(isc.signatures().cols() == 19); // SI-HKS frequencies [2, 20]
  // the descriptor from a whole distance field (every vertex) equals the radius-limited one
  const shapecorr::Fast_marching_geodesics<test::Surface_mesh> fm(m);
  const Eigen::VectorXd d = fm.distances_from(17);
  shapecorr::Intrinsic_shape_context<test::Surface_mesh>::Ball ball;
  for(Eigen::Index v = 0; v < d.size(); ++v) ball.emplace_back(std::size_t(v), d[v]);
  shapecorr::Intrinsic_shape_context<test::Surface_mesh>::Workspace ws(isc);
  const Eigen::VectorXd from_ball = isc.descriptor(17, ball, ws);
  const Eigen::VectorXd direct = isc.descriptor(test::Surface_mesh::Vertex_index(17));
  CHECK((from_ball - direct).norm() <= 1e-12 * direct.norm());
  // the free function writes the same rows
  typedef test::Surface_mesh::Vertex_index V;
  auto map = m.add_property_map<V, std::vector<double>>("v:isc").first;
  const std::vector<V> some = {V(3), V(17), V(600)};
  shapecorr::compute_intrinsic_shape_contexts(m, some, map, SP::number_of_eigenpairs(40).support_fraction(0.2));
  const Eigen::MatrixXd rows = isc.descriptors({3, 17, 600});
  for(std::size_t i = 0; i < 3; ++i) {
    REQUIRE(map[some[i]].size() == isc.size());
    for(std::size_t c = 0; c < isc.size(); ++c) CHECK(map[some[i]][c] == Approx(rows(long(i), long(c))).margin(1e-12));
  }
  CHECK(shapecorr::spectral_descriptor_distance(map[some[1]], rows.row(1)) <= 1e-12);
}

TEST_CASE("Intrinsic shape context: bad input", "[spectral][isc][errors]") {
  test::Surface_mesh m;
  test::make_ellipsoid(m, 2);
  const long n = long(m.number_of_vertices());
  typedef shapecorr::Intrinsic_shape_context<test::Surface_mesh> Isc;
  const Eigen::MatrixXd f = Eigen::MatrixXd::Ones(n, 3);
  CHECK_THROWS_AS(Isc(test::Surface_mesh(), Eigen::MatrixXd()), shapecorr::Invalid_input);
  CHECK_THROWS_AS(Isc(m, f, SP::number_of_directions(std::size_t(15))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(Isc(m, f, SP::number_of_rings(std::size_t(0))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(Isc(m, f, SP::support_length(0.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(Isc(m, f, SP::support_fraction(std::numeric_limits<double>::quiet_NaN())), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(Isc(m, Eigen::MatrixXd::Ones(n - 1, 3)), shapecorr::Invalid_argument);
  Eigen::MatrixXd g = f;
  g(0, 0) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(Isc(m, g), shapecorr::Invalid_argument);
  test::Surface_mesh bad = m;
  bad.point(test::Surface_mesh::Vertex_index(0)) = test::Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK_THROWS_AS(Isc(bad, f), shapecorr::Invalid_input);
  const Isc a(m, f), b(m, f);
  CHECK_THROWS_AS(a.descriptors({std::size_t(n)}), shapecorr::Invalid_argument);
  Isc::Workspace wa(a), wb(b);
  CHECK_THROWS_AS(a.descriptor(test::Surface_mesh::Vertex_index(0), wb), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(a.descriptor(0, {{std::size_t(n + 5), 0.1}}, wa), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(a.descriptor(std::size_t(n), {{0, 0.1}}, wa), shapecorr::Invalid_argument);
}
