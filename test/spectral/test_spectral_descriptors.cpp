// HKS, WKS, SI-HKS: invariance under a rigid motion and vertex renumbering, SI-HKS under uniform
// scaling (where plain HKS at fixed times is not invariant), output through property maps, errors,
// and ranking of ground-truth matches on a TOSCA pair (skips without ../shared/data).
#include "spectral_test_helpers.h"
#include "test_renumbering.h"

#include <shapecorr/io.h>
#include <shapecorr/spectral.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <numeric>

namespace SP = shapecorr::parameters;

namespace {
double max_rel_diff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300);
}

template <typename Mesh>
std::vector<Eigen::MatrixXd> all_three(const Mesh& m, std::size_t k) {
  const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(m, k);
  return {shapecorr::heat_kernel_signature_matrix(b), shapecorr::wave_kernel_signature_matrix(b),
          shapecorr::scale_invariant_heat_kernel_signature_matrix(b)};
}
} // namespace

TEMPLATE_LIST_TEST_CASE("HKS, WKS, SI-HKS are invariant under a rigid motion", "[spectral][descriptors][invariance]", test::Mesh_types) {
  TestType a;
  test::make_ellipsoid(a, 3);
  TestType b = a;
  const Eigen::Isometry3d T = test::random_rigid_motion(11);
  test::transform_points(b, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(T * p); });
  const auto da = all_three(a, 40), db = all_three(b, 40);
  for(std::size_t i = 0; i < 3; ++i) {
    INFO("descriptor " << i << " (HKS, WKS, SI-HKS)");
    CHECK(da[i].rows() == 642);
    CHECK(max_rel_diff(da[i], db[i]) < 1e-6);
  }
}

TEST_CASE("HKS, WKS, SI-HKS are invariant under vertex renumbering; property-map output", "[spectral][descriptors][invariance]") {
  test::Surface_mesh a;
  test::make_ellipsoid(a, 3);
  const std::size_t n = a.number_of_vertices();
  std::vector<std::size_t> perm;
  test::Surface_mesh b = test::renumbered_copy(a, 5, perm);
  typedef test::Surface_mesh::Vertex_index V;
  auto ha = a.add_property_map<V, std::vector<double>>("v:hks").first;
  auto hb = b.add_property_map<V, std::vector<double>>("v:hks").first;
  auto wa = a.add_property_map<V, std::vector<double>>("v:wks").first;
  auto wb = b.add_property_map<V, std::vector<double>>("v:wks").first;
  auto sa = a.add_property_map<V, std::vector<double>>("v:sihks").first;
  auto sb = b.add_property_map<V, std::vector<double>>("v:sihks").first;
  shapecorr::compute_heat_kernel_signature(a, ha, SP::number_of_eigenpairs(40));
  shapecorr::compute_heat_kernel_signature(b, hb, SP::number_of_eigenpairs(40));
  shapecorr::compute_wave_kernel_signature(a, wa, SP::number_of_eigenpairs(40).number_of_scales(50));
  shapecorr::compute_wave_kernel_signature(b, wb, SP::number_of_eigenpairs(40).number_of_scales(50));
  const auto basis_a = shapecorr::compute_laplace_beltrami_eigenbasis(a, 40);
  const auto basis_b = shapecorr::compute_laplace_beltrami_eigenbasis(b, 40);
  shapecorr::compute_scale_invariant_heat_kernel_signature(a, sa, SP::eigenbasis(&basis_a));
  shapecorr::compute_scale_invariant_heat_kernel_signature(b, sb, SP::eigenbasis(&basis_b));
  double worst = 0, scale = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const V va(static_cast<unsigned>(i)), vb(static_cast<unsigned>(perm[i]));
    REQUIRE(ha[va].size() == 100);
    REQUIRE(wa[va].size() == 50);
    REQUIRE(sa[va].size() == 19);
    worst = std::max({worst, shapecorr::spectral_descriptor_distance(ha[va], hb[vb]) / std::sqrt(100.0),
                      shapecorr::spectral_descriptor_distance(wa[va], wb[vb]) / std::sqrt(50.0),
                      shapecorr::spectral_descriptor_distance(sa[va], sb[vb]) / std::sqrt(19.0)});
    scale = std::max(scale, *std::max_element(ha[va].begin(), ha[va].end()));
  }
  INFO("largest per-entry RMS difference " << worst << " (values of order " << scale << ")");
  CHECK(worst < 1e-6 * scale);
}

TEMPLATE_LIST_TEST_CASE("SI-HKS is invariant under uniform scaling, HKS at fixed times is not", "[spectral][descriptors][invariance]", test::Mesh_types) {
  TestType a;
  test::make_ellipsoid(a, 3);
  TestType b = a;
  test::transform_points(b, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(2.0 * p); });
  const auto ba = shapecorr::compute_laplace_beltrami_eigenbasis(a, 60), bb = shapecorr::compute_laplace_beltrami_eigenbasis(b, 60);
  // default time unit 1 / lambda_k moves with the scale: exact invariance
  CHECK(max_rel_diff(shapecorr::scale_invariant_heat_kernel_signature_matrix(ba), shapecorr::scale_invariant_heat_kernel_signature_matrix(bb)) < 1e-6);
  // one absolute time frame for both (t0 fixed): the invariance comes from log, derivative and
  // Fourier magnitude; the window tau in [-10, 20] holds the whole decay at both scales
  const auto np = SP::time_unit(0.01).log_time_range(std::make_pair(-10.0, 20.0));
  const Eigen::MatrixXd sa = shapecorr::scale_invariant_heat_kernel_signature_matrix(ba, np);
  const Eigen::MatrixXd sb = shapecorr::scale_invariant_heat_kernel_signature_matrix(bb, np);
  const double si = (sa - sb).norm() / sa.norm();
  const auto hp = SP::time_range(std::make_pair(0.01, 1.0)).normalize_per_scale(false);
  const Eigen::MatrixXd ha = shapecorr::heat_kernel_signature_matrix(ba, hp), hb = shapecorr::heat_kernel_signature_matrix(bb, hp);
  const double hks = (ha - hb).norm() / ha.norm();
  INFO("relative change under scaling by 2: SI-HKS " << si << ", HKS at fixed times " << hks);
  CHECK(si < 0.05);
  CHECK(hks > 0.5);
}

TEST_CASE("spectral descriptors: parameters out of range and foreign bases are typed errors", "[spectral][descriptors][errors]") {
  test::Surface_mesh m, other;
  shapecorr::make_icosphere(m, 2);
  shapecorr::make_icosphere(other, 1);
  const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(m, 20);
  const auto bo = shapecorr::compute_laplace_beltrami_eigenbasis(other, 20);
  auto map = m.add_property_map<test::Surface_mesh::Vertex_index, std::vector<double>>("v:d").first;
  CHECK_THROWS_AS(shapecorr::compute_heat_kernel_signature(m, map, SP::eigenbasis(&bo)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::heat_kernel_signature_matrix(b, SP::number_of_scales(std::size_t(0))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::heat_kernel_signature_matrix(b, SP::time_range(std::make_pair(-1.0, 1.0))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::scale_invariant_heat_kernel_signature_matrix(b, SP::frequency_range(std::make_pair(2, 5000))), shapecorr::Invalid_argument);
  const auto one = shapecorr::compute_laplace_beltrami_eigenbasis(m, 1); // only the zero eigenvalue
  CHECK_THROWS_AS(shapecorr::wave_kernel_signature_matrix(one), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::spectral_descriptor_distance(std::vector<double>(3), std::vector<double>(4)), shapecorr::Invalid_argument);
}

namespace {
std::vector<int> read_vts(const std::string& path) {
  std::ifstream in(path);
  std::vector<int> ids;
  int v;
  while(in >> v) ids.push_back(v - 1); // 1-based
  return ids;
}
} // namespace

TEST_CASE("TOSCA: ground-truth matches rank in the top percent by WKS distance", "[spectral][descriptors][real-data]") {
  const std::string data = test::data_dir();
  if(data.empty()) {
    WARN("../shared/data absent: skipping the TOSCA ranking test");
    return;
  }
  // measured (300 eigenpairs, 50 evenly spaced ground-truth rows): mean rank of the true match among
  // all target vertices, in % of them: wolf0->wolf2 0.09%, centaur0->centaur1 3.2%
  for(const auto& pair : {std::make_tuple("wolf0", "wolf2", 1.0), std::make_tuple("centaur0", "centaur1", 5.0)}) {
    const std::string sa = std::get<0>(pair), sb = std::get<1>(pair);
    test::Surface_mesh A, B;
    shapecorr::read_triangle_mesh(data + "/tosca5k/meshes/" + sa + ".off", A);
    shapecorr::read_triangle_mesh(data + "/tosca5k/meshes/" + sb + ".off", B);
    const std::vector<int> ca = read_vts(data + "/tosca5k/corres/" + sa + ".vts"), cb = read_vts(data + "/tosca5k/corres/" + sb + ".vts");
    REQUIRE(ca.size() == cb.size());
    const Eigen::MatrixXd WA = shapecorr::wave_kernel_signature_matrix(shapecorr::compute_laplace_beltrami_eigenbasis(A, 300));
    const Eigen::MatrixXd WB = shapecorr::wave_kernel_signature_matrix(shapecorr::compute_laplace_beltrami_eigenbasis(B, 300));
    double mean_rank = 0;
    int count = 0;
    for(std::size_t r = 0; r < ca.size(); r += ca.size() / 50, ++count) {
      const Eigen::VectorXd d = (WB.rowwise() - WA.row(ca[r])).rowwise().norm();
      mean_rank += 100.0 * static_cast<double>((d.array() < d[cb[r]]).count()) / static_cast<double>(d.size());
    }
    mean_rank /= count;
    INFO(sa << " -> " << sb << ": mean rank of the true match " << mean_rank << "% of " << WB.rows() << " vertices");
    CHECK(mean_rank < std::get<2>(pair));
  }
}

TEMPLATE_LIST_TEST_CASE("spectral_signature_matrix dispatches to the signature it names", "[spectral][descriptors]", test::Mesh_types) {
  TestType m;
  test::make_ellipsoid(m, 2);
  const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(m, 30);
  const auto np = SP::number_of_scales(std::size_t(17));
  using shapecorr::Spectral_signature;
  // exactly the matrices of the individual functions, with the same parameters
  CHECK(shapecorr::spectral_signature_matrix(b, Spectral_signature::HKS, np) == shapecorr::heat_kernel_signature_matrix(b, np));
  CHECK(shapecorr::spectral_signature_matrix(b, Spectral_signature::WKS, np) == shapecorr::wave_kernel_signature_matrix(b, np));
  CHECK(shapecorr::spectral_signature_matrix(b, Spectral_signature::SIHKS, np) == shapecorr::scale_invariant_heat_kernel_signature_matrix(b, np));
  CHECK(shapecorr::spectral_signature_matrix(b, Spectral_signature::HKS, np).cols() == 17);
  for(Spectral_signature s : {Spectral_signature::HKS, Spectral_signature::WKS, Spectral_signature::SIHKS})
    CHECK(shapecorr::spectral_signature_from_string(shapecorr::to_string(s)) == s);
  CHECK_THROWS_AS(shapecorr::spectral_signature_from_string("HKS"), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::spectral_signature_from_string(""), shapecorr::Invalid_argument);
}
