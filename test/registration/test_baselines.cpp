// The baselines of the thesis's chapter 6 (Andresen 2001, Pauly 2005, CPD, GMM-L2): each undoes a
// synthetic smooth deformation of an ellipsoid (target: the deformed ellipsoid, triangulated
// apart, of comparable density as CPD and GMM-L2 need), template over three mesh types; the
// callback, the iteration bound and bad input; the fast Gauss sum and the low-rank kernel against
// their exact counterparts.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/evaluation/surface_distance.h>
#include <shapecorr/internal/gauss_sum.h>
#include <shapecorr/internal/low_rank_kernel.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/boost/graph/copy_face_graph.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <string>

namespace SP = shapecorr::parameters;
using shapecorr::Stop_reason;

namespace {
// The smooth deformation to undo: about 0.1 at most, against semi-axes 1, 0.8, 0.6.
Eigen::Vector3d bend(const Eigen::Vector3d& p) {
  return p + 0.1 * Eigen::Vector3d(std::sin(2 * p.y()), std::sin(2 * p.z()), std::sin(2 * p.x()));
}
// An icosphere of `subdivisions`, turned (seed > 0) so that its vertices are not the template's,
// on the ellipsoid (1, 0.8, 0.6), then bent (or not).
template <typename Mesh>
void make_shape(Mesh& m, int subdivisions, unsigned turn_seed, bool bent) {
  shapecorr::make_icosphere(m, subdivisions);
  const Eigen::Matrix3d turn = turn_seed ? Eigen::Matrix3d(test::random_rigid_motion(turn_seed).linear()) : Eigen::Matrix3d::Identity();
  test::transform_points(m, [&](const Eigen::Vector3d& q) {
    const Eigen::Vector3d p = turn * q;
    const Eigen::Vector3d e(p.x(), 0.8 * p.y(), 0.6 * p.z());
    return bent ? bend(e) : e;
  });
}

enum class Method { andresen, pauly, cpd, gmm_l2 };
const char* name(Method m) {
  switch(m) {
    case Method::andresen: return "andresen";
    case Method::pauly: return "pauly";
    case Method::cpd: return "cpd";
    case Method::gmm_l2: return "gmm-l2";
  }
  return "";
}
template <typename Mesh, typename Target, typename Map, typename NP = shapecorr::parameters::Default_named_parameters>
shapecorr::Registration_report run(Method m, const Mesh& tmpl, const Target& target, Map out, const NP& np = CGAL::parameters::default_values()) {
  switch(m) {
    case Method::andresen: return shapecorr::andresen_registration(tmpl, target, out, np);
    case Method::pauly: return shapecorr::pauly_registration(tmpl, target, out, np);
    case Method::cpd: return shapecorr::cpd_registration(tmpl, target, out, np);
    case Method::gmm_l2: return shapecorr::gmm_l2_registration(tmpl, target, out, np);
  }
  throw std::logic_error("unknown method");
}
const Method all_methods[] = {Method::andresen, Method::pauly, Method::cpd, Method::gmm_l2};
} // namespace

TEMPLATE_LIST_TEST_CASE("the baselines undo a smooth deformation of an ellipsoid", "[registration][baselines]", test::Mesh_types) {
  TestType tmpl;
  make_shape(tmpl, 3, 0, false);
  test::Surface_mesh target;
  make_shape(target, 3, 31, true);
  const auto before = shapecorr::surface_distance(tmpl, target);
  const auto vs = test::vertices_in_index_order(tmpl);
  double moved = 0; // mean |φ(y) − y| over the template's vertices
  for(auto v : vs) {
    const auto& p = get(CGAL::vertex_point, tmpl, v);
    const Eigen::Vector3d y(p.x(), p.y(), p.z());
    moved += (bend(y) - y).norm() / static_cast<double>(vs.size());
  }
  for(Method m : all_methods) {
    auto out = get(CGAL::dynamic_vertex_property_t<test::Point>(), tmpl);
    const shapecorr::Registration_report r = run(m, tmpl, target, out);
    test::Surface_mesh fitted;
    std::vector<std::pair<typename boost::graph_traits<TestType>::vertex_descriptor, test::Surface_mesh::Vertex_index>> copied;
    CGAL::copy_face_graph(tmpl, fitted, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(copied)));
    for(const auto& c : copied) fitted.point(c.second) = get(out, c.first);
    const auto after = shapecorr::surface_distance(fitted, target);
    double error = 0; // mean |fit(y) − φ(y)|: the deformation undone point for point
    for(auto v : vs) {
      const auto& p = get(CGAL::vertex_point, tmpl, v);
      const auto& q = get(out, v);
      error += (Eigen::Vector3d(q.x(), q.y(), q.z()) - bend(Eigen::Vector3d(p.x(), p.y(), p.z()))).norm() / static_cast<double>(vs.size());
    }
    INFO(name(m) << ": l2 " << before.l2 << " -> " << after.l2 << ", lmax " << before.lmax << " -> " << after.lmax << ", mean |fit − φ| " << error
                 << " (mean |φ − id| " << moved << "), " << r.iterations.size() << " iterations (" << shapecorr::to_string(r.stop) << "), rms "
                 << r.initial_rms << " -> " << r.final_rms);
    REQUIRE_FALSE(r.iterations.empty());
    CHECK(std::isfinite(after.lmax));
    CHECK(r.initial_rms == Approx(before.l2).epsilon(0.5)); // vertices against the area integral: the same order
    CHECK(after.l2 < 0.2 * before.l2);
    CHECK(r.final_rms < 0.3 * r.initial_rms);
    // the tangential part of φ is invisible to closest points: the vertices reach the surface, not φ(y)
    CHECK(error < moved);
  }
}

TEST_CASE("the baselines: callback, iteration bound, bad input", "[registration][baselines]") {
  test::Polyhedron tmpl;
  make_shape(tmpl, 2, 0, false);
  test::Surface_mesh target, empty;
  make_shape(target, 2, 31, true);
  test::Surface_mesh nan_target = target;
  nan_target.point(*vertices(nan_target).begin()) = test::Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  auto out = get(CGAL::dynamic_vertex_property_t<test::Point>(), tmpl);
  for(Method m : all_methods) {
    INFO(name(m));
    std::size_t calls = 0;
    const std::function<bool(const shapecorr::Iteration_record&)> stop_after_two = [&](const shapecorr::Iteration_record&) { return ++calls < 2; };
    const auto r = run(m, tmpl, target, out, SP::iteration_callback(stop_after_two));
    CHECK(calls == 2);
    CHECK(r.iterations.size() == 2);
    CHECK(r.stop == Stop_reason::CANCELLED);
    const auto r3 = run(m, tmpl, target, out, SP::number_of_iterations(3));
    CHECK(r3.iterations.size() <= (m == Method::gmm_l2 ? 12u : 3u)); // GMM-L2: per level, 4 levels
    CHECK_THROWS_AS(run(m, tmpl, empty, out), shapecorr::Invalid_input);
    CHECK_THROWS_AS(run(m, tmpl, nan_target, out), shapecorr::Invalid_input);
    CHECK_THROWS_AS(run(m, tmpl, target, out, SP::number_of_iterations(std::size_t(1) << 40)), shapecorr::Invalid_argument);
  }
  CHECK_THROWS_AS(shapecorr::andresen_registration(tmpl, target, out, SP::time_step(0.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::andresen_registration(tmpl, target, out, SP::time_step(1.5)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::pauly_registration(tmpl, target, out, SP::alpha_decay(0.5)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::cpd_registration(tmpl, target, out, SP::kernel_width(0.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::cpd_registration(tmpl, target, out, SP::outlier_weight(1.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::cpd_registration(tmpl, target, out, SP::regularization_weight(-1.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::cpd_registration(tmpl, target, out, SP::kernel_rank(std::size_t(0))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::gmm_l2_registration(tmpl, target, out, SP::scale_schedule(std::vector<double>{0.1, 0.05})), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::gmm_l2_registration(tmpl, target, out, SP::scale_schedule(std::vector<double>{-1.0}).regularization_schedule(std::vector<double>{0.0})),
                  shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::gmm_l2_registration(tmpl, target, out, SP::number_of_control_points(std::size_t(0))), shapecorr::Invalid_argument);
}

TEST_CASE("fast Gauss sum: truncated and clustered sums against the exact sum", "[registration][baselines]") {
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0, 1);
  const Eigen::Index n = 4000;
  Eigen::MatrixXd P(n, 3);
  for(Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized(); // on the unit sphere: a surface, as the methods see
    P.row(i) = d.transpose();
  }
  Eigen::VectorXd w = Eigen::VectorXd::Random(n).cwiseAbs();
  const Eigen::MatrixXd V = w.asDiagonal() * P;
  for(double s : {0.02, 0.1, 0.5, 2.0}) {
    const shapecorr::internal::Gauss_sum fast(P, w, V, s);
    double worst = 0, worst_vector = 0; // errors over (exact + 1e-6 Σw), (Σ k |v| + 1e-6 Σw): the truncation's bound is 1e-6 Σw
    for(int q = 0; q < 50; ++q) {
      const Eigen::Vector3d x = 1.2 * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * std::abs(std::cos(q));
      double exact = 0, magnitude = 0; // magnitude: Σ k |v_j|, the scale of the vector sum (its terms may cancel)
      Eigen::Vector3d exact_v = Eigen::Vector3d::Zero();
      for(Eigen::Index j = 0; j < n; ++j) {
        const double k = std::exp(-(P.row(j).transpose() - x).squaredNorm() / (2 * s * s));
        exact += w(j) * k;
        exact_v += k * V.row(j).transpose();
        magnitude += k * V.row(j).norm();
      }
      Eigen::Vector3d v;
      const double a = fast(x, &v);
      worst = std::max(worst, std::abs(a - exact) / (exact + 1e-6 * w.sum()));
      worst_vector = std::max(worst_vector, (v - exact_v).norm() / (magnitude + 1e-6 * w.sum()));
    }
    INFO("s = " << s << ": clustered " << fast.clustered() << " (" << fast.size() << " sources), worst error " << worst << ", of the vector sum " << worst_vector);
    if(s <= 0.1) CHECK_FALSE(fast.clustered());
    if(s >= 0.5) CHECK(fast.clustered());
    CHECK(worst < (fast.clustered() ? 1e-2 : 1.0));
    CHECK(worst_vector < (fast.clustered() ? 1e-2 : 1.0));
  }
}

TEST_CASE("low-rank Gaussian kernel: the Nyström eigenpairs against the dense decomposition", "[registration][baselines]") {
  test::Surface_mesh m;
  make_shape(m, 3, 0, false); // 642 points
  const auto a = shapecorr::internal::Indexed_mesh<test::Surface_mesh>(m, CGAL::parameters::default_values()).arrays();
  const Eigen::MatrixXd Y = a.V;
  const Eigen::Index M = Y.rows();
  for(double beta : {0.3, 1.0}) {
    Eigen::MatrixXd G(M, M);
    for(Eigen::Index i = 0; i < M; ++i)
      for(Eigen::Index j = 0; j < M; ++j) G(i, j) = std::exp(-(Y.row(i) - Y.row(j)).squaredNorm() / (2 * beta * beta));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense(G);
    const auto full = shapecorr::internal::gaussian_kernel_eigenpairs(Y, beta, 20, static_cast<std::size_t>(M));
    const auto nystrom = shapecorr::internal::gaussian_kernel_eigenpairs(Y, beta, 20, 200);
    REQUIRE(full.lambda.size() == 20);
    REQUIRE(nystrom.lambda.size() == 20);
    double worst_full = 0, worst_nystrom = 0;
    for(Eigen::Index k = 0; k < 20; ++k) {
      const double exact = dense.eigenvalues()(M - 1 - k);
      worst_full = std::max(worst_full, std::abs(full.lambda(k) - exact) / dense.eigenvalues()(M - 1));
      worst_nystrom = std::max(worst_nystrom, std::abs(nystrom.lambda(k) - exact) / dense.eigenvalues()(M - 1));
    }
    const double orthonormal = (nystrom.Q.transpose() * nystrom.Q - Eigen::MatrixXd::Identity(20, 20)).cwiseAbs().maxCoeff();
    INFO("beta " << beta << ": largest eigenvalue " << dense.eigenvalues()(M - 1) << "; errors relative to it: all points " << worst_full << ", 200 landmarks "
                 << worst_nystrom << "; |QᵀQ − I| " << orthonormal);
    CHECK(worst_full < 1e-9);
    CHECK(worst_nystrom < 1e-3);
    CHECK(orthonormal < 1e-8);
  }
}
