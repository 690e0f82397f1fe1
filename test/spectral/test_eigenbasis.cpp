// The Laplace-Beltrami eigenbasis: sphere eigenvalues l(l+1) with multiplicity 2l+1, M-orthonormal
// eigenvectors, one zero eigenvalue per component, Spectra and dense paths agree, save/load, errors,
// a user-supplied eigensolver through the named parameter.
#include "spectral_test_helpers.h"

#include <shapecorr/spectral/Laplace_beltrami_eigenbasis.h>

#include <CGAL/Polygon_mesh_processing/transform.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <fstream>

namespace SP = shapecorr::parameters;

namespace {
// A minimal model of LaplaceBeltramiEigensolver: dense, for small meshes.
struct Dense_eigensolver {
  int* calls = nullptr;
  void solve(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& mass, std::size_t k, Eigen::VectorXd& values,
             Eigen::MatrixXd& vectors) const {
    ++*calls;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(L), Eigen::MatrixXd(mass.asDiagonal()));
    values = es.eigenvalues().head(static_cast<Eigen::Index>(k));
    vectors = es.eigenvectors().leftCols(static_cast<Eigen::Index>(k));
  }
};
} // namespace

TEMPLATE_LIST_TEST_CASE("unit sphere: eigenvalues l(l+1) with multiplicity 2l+1", "[spectral][eigenbasis]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 3); // 642 vertices: Spectra's shift-invert Lanczos (above dense_size)
  const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(m, 36);
  const Eigen::VectorXd& lambda = b.eigenvalues();
  CHECK(std::abs(lambda[0]) < 1e-9);
  CHECK(b.number_of_zero_eigenvalues() == 1);
  std::size_t i = 1;
  for(int l = 1; l <= 5; ++l)
    for(int j = 0; j < 2 * l + 1; ++j, ++i) {
      INFO("l = " << l << ", eigenvalue " << i << " = " << lambda[static_cast<Eigen::Index>(i)]);
      // measured on 642 vertices: 0.2% (l = 1) to 4% (l = 5) below l(l+1)
      CHECK(std::abs(lambda[static_cast<Eigen::Index>(i)] - l * (l + 1)) <= 0.05 * l * (l + 1));
    }
  // the gap between consecutive l is far larger than the spread inside one l
  CHECK(lambda[4] - lambda[3] > 10 * (lambda[3] - lambda[1]));
  // M-orthonormal
  const Eigen::MatrixXd G = b.eigenvectors().transpose() * b.mass().asDiagonal() * b.eigenvectors();
  CHECK((G - Eigen::MatrixXd::Identity(36, 36)).cwiseAbs().maxCoeff() < 1e-9);
  // eigen-equation residuals
  const Eigen::SparseMatrix<double> L = shapecorr::cotangent_laplacian(m);
  const Eigen::MatrixXd R = L * b.eigenvectors() - b.mass().asDiagonal() * b.eigenvectors() * lambda.asDiagonal();
  CHECK(R.cwiseAbs().maxCoeff() < 1e-8 * (1 + lambda.maxCoeff()) * b.mass().maxCoeff() * b.eigenvectors().cwiseAbs().maxCoeff());
}

TEST_CASE("Spectra and the dense path agree; a user eigensolver is used when given", "[spectral][eigenbasis]") {
  test::Surface_mesh m;
  test::make_ellipsoid(m, 3);
  const auto lanczos = shapecorr::compute_laplace_beltrami_eigenbasis(m, 20);
  shapecorr::Spectra_eigensolver<> dense_cfg;
  dense_cfg.dense_size = 100000;
  const auto dense = shapecorr::compute_laplace_beltrami_eigenbasis(m, 20, SP::eigensolver(dense_cfg));
  CHECK((lanczos.eigenvalues() - dense.eigenvalues()).cwiseAbs().maxCoeff() < 1e-9 * dense.eigenvalues().maxCoeff());
  // simple spectrum: eigenvectors agree up to sign
  for(Eigen::Index j = 1; j < 20; ++j) {
    const double c = std::abs(lanczos.eigenvectors().col(j).dot(lanczos.mass().asDiagonal() * dense.eigenvectors().col(j)));
    CHECK(c == Approx(1.0).epsilon(1e-6));
  }
  int calls = 0;
  Dense_eigensolver user{&calls};
  const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(m, 20, SP::eigensolver(user));
  CHECK(calls == 1);
  CHECK((b.eigenvalues() - dense.eigenvalues()).cwiseAbs().maxCoeff() < 1e-9 * dense.eigenvalues().maxCoeff());
}

TEST_CASE("spectrum slicing returns the same pairs as one dense solve, clusters included", "[spectral][eigenbasis]") {
  for(int shape = 0; shape < 2; ++shape) {
    test::Surface_mesh m;
    if(shape == 0) test::make_ellipsoid(m, 3); // simple spectrum
    else shapecorr::make_icosphere(m, 3);      // clusters of 2l+1 nearly equal values
    shapecorr::Spectra_eigensolver<> sliced;
    sliced.slice_size = 15; // 64 pairs in five slices or more
    shapecorr::Spectra_eigensolver<> dense_cfg;
    dense_cfg.dense_size = 100000;
    const auto a = shapecorr::compute_laplace_beltrami_eigenbasis(m, 64, SP::eigensolver(sliced));
    const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(m, 64, SP::eigensolver(dense_cfg));
    INFO("shape " << shape << ": largest eigenvalue " << b.eigenvalues()[63]);
    CHECK((a.eigenvalues() - b.eigenvalues()).cwiseAbs().maxCoeff() < 1e-8 * b.eigenvalues().maxCoeff());
    const Eigen::MatrixXd G = a.eigenvectors().transpose() * a.mass().asDiagonal() * a.eigenvectors();
    CHECK((G - Eigen::MatrixXd::Identity(64, 64)).cwiseAbs().maxCoeff() < 1e-8);
  }
}

TEMPLATE_LIST_TEST_CASE("each connected component contributes a zero eigenvalue", "[spectral][eigenbasis]", test::Mesh_types) {
  TestType a, b;
  shapecorr::make_icosphere(a, 3);
  shapecorr::make_icosphere(b, 2);
  test::transform_points(b, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p + Eigen::Vector3d(5, 0, 0)); });
  CGAL::copy_face_graph(b, a);
  const auto basis = shapecorr::compute_laplace_beltrami_eigenbasis(a, 10);
  CHECK(basis.number_of_zero_eigenvalues() == 2);
  CHECK(basis.eigenvalues()[2] == Approx(2.0).epsilon(0.02)); // the unit sphere's l = 1 (the other has radius 1 too)
}

TEST_CASE("eigenbasis save and load round-trip; bad files are typed errors", "[spectral][eigenbasis][io]") {
  test::Surface_mesh m;
  test::make_ellipsoid(m, 2);
  const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(m, 12);
  const std::string path = test::temp_path("test_eigenbasis_roundtrip.bin");
  b.save(path);
  const auto c = shapecorr::Laplace_beltrami_eigenbasis::load(path);
  CHECK(c.eigenvalues() == b.eigenvalues());
  CHECK(c.eigenvectors() == b.eigenvectors());
  CHECK(c.mass() == b.mass());
  { // truncate it
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  }
  CHECK_THROWS_AS(shapecorr::Laplace_beltrami_eigenbasis::load(path), shapecorr::Invalid_input);
  { std::ofstream out(path, std::ios::trunc); out << "OFF\n3 1 0\n"; }
  CHECK_THROWS_AS(shapecorr::Laplace_beltrami_eigenbasis::load(path), shapecorr::Invalid_input);
  std::remove(path.c_str());
  CHECK_THROWS_AS(shapecorr::Laplace_beltrami_eigenbasis::load("no/such/file.bin"), shapecorr::Invalid_input);
}

TEST_CASE("eigenbasis errors: k out of range, isolated vertex, solver failure", "[spectral][eigenbasis][errors]") {
  test::Surface_mesh m;
  shapecorr::make_icosphere(m, 1);
  CHECK_THROWS_AS(shapecorr::compute_laplace_beltrami_eigenbasis(m, 0), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::compute_laplace_beltrami_eigenbasis(m, 43), shapecorr::Invalid_argument);
  CHECK(shapecorr::compute_laplace_beltrami_eigenbasis(m, 42).number_of_eigenpairs() == 42); // all of them
  test::Surface_mesh iso;
  shapecorr::make_icosphere(iso, 1);
  iso.add_vertex(test::Point(3, 3, 3));
  try {
    shapecorr::compute_laplace_beltrami_eigenbasis(iso, 5);
    FAIL("no exception");
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(e.defect() == shapecorr::Mesh_defect::isolated_vertex);
  }
  test::Surface_mesh big;
  shapecorr::make_icosphere(big, 3);
  shapecorr::Spectra_eigensolver<> hopeless;
  hopeless.tolerance = 0;   // nothing ever converges to a zero tolerance
  hopeless.max_iterations = 2;
  CHECK_THROWS_AS(shapecorr::compute_laplace_beltrami_eigenbasis(big, 30, SP::eigensolver(hopeless)), shapecorr::Solver_failure);
}

namespace {
std::string eigenbasis_load_error(const std::string& path) {
  try {
    shapecorr::Laplace_beltrami_eigenbasis::load(path);
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(std::string(e.what()).find(path) != std::string::npos);
    return e.what();
  }
  return "";
}
std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
void put_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes; }
} // namespace

TEST_CASE("regression 31.1: hostile eigenbasis files are typed errors, never a crash or NaN descriptors", "[spectral][eigenbasis][io][regression]") {
  const std::string path = test::temp_path("test_eigenbasis_hostile.bin");
  Eigen::VectorXd values(2), mass(3);
  values << 0.0, 1.5;
  mass << 0.5, 0.25, 0.25;
  Eigen::MatrixXd vectors = Eigen::MatrixXd::Ones(3, 2);
  const shapecorr::Laplace_beltrami_eigenbasis good(values, vectors, mass, 2.0);
  good.save(path);
  const std::string bytes = file_bytes(path);
  CHECK(eigenbasis_load_error(path).empty());
  // sizes that overflow 64-bit products (n k * 8 wraps) or exceed the file: no allocation, an error
  for(std::uint64_t n : {std::uint64_t(1) << 61, std::uint64_t(0x2000000000000001ull), std::uint64_t(4), std::uint64_t(0)}) {
    std::string b = bytes;
    std::memcpy(&b[12], &n, 8);
    put_bytes(path, b);
    INFO("n = " << n);
    CHECK_THAT(eigenbasis_load_error(path), Catch::Contains(n == 0 ? "1 <= k <= n" : "disagree with the file size"));
  }
  // a flipped bit anywhere in the payload: checksum
  for(std::size_t at : {std::size_t(36), bytes.size() / 2, bytes.size() - 9}) {
    std::string b = bytes;
    b[at] = static_cast<char>(b[at] ^ 0x10);
    put_bytes(path, b);
    CHECK_THAT(eigenbasis_load_error(path), Catch::Contains("checksum mismatch"));
  }
  // every truncation
  for(std::size_t cut = 0; cut < bytes.size(); ++cut) {
    put_bytes(path, bytes.substr(0, cut));
    CHECK_FALSE(eigenbasis_load_error(path).empty());
  }
  // version 1 and foreign files
  put_bytes(path, "SCLBEIG1" + bytes.substr(8));
  CHECK_THAT(eigenbasis_load_error(path), Catch::Contains("version 1"));
  put_bytes(path, "OFF\n3 1 0\n");
  CHECK_THAT(eigenbasis_load_error(path), Catch::Contains("not a ShapeCorr eigenbasis file"));
  // valid checksums over invalid contents (written through save): NaN/inf eigenvalues, negative or
  // unsorted ones, NaN masses, non-finite vectors
  auto check_content = [&](Eigen::VectorXd v, Eigen::MatrixXd u, Eigen::VectorXd m, const char* expected) {
    shapecorr::Laplace_beltrami_eigenbasis(v, u, m, 2.0).save(path);
    CHECK_THAT(eigenbasis_load_error(path), Catch::Contains(expected));
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  check_content((Eigen::VectorXd(2) << 0.0, nan).finished(), vectors, mass, "eigenvalue 1 is not finite");
  check_content((Eigen::VectorXd(2) << 0.0, inf).finished(), vectors, mass, "eigenvalue 1 is not finite");
  check_content((Eigen::VectorXd(2) << -0.5, 1.0).finished(), vectors, mass, "eigenvalue 0 = -0.500000 is negative");
  check_content((Eigen::VectorXd(2) << 1.0, 0.5).finished(), vectors, mass, "not ascending at 1");
  check_content(values, vectors, (Eigen::VectorXd(3) << 0.5, nan, 0.25).finished(), "mass of vertex 1 is not a positive number");
  Eigen::MatrixXd bad = vectors;
  bad(2, 1) = nan;
  check_content(values, bad, mass, "an eigenvector has a non-finite entry");
  // a round-off negative zero eigenvalue is accepted
  shapecorr::Laplace_beltrami_eigenbasis((Eigen::VectorXd(2) << -1e-12, 1.0).finished(), vectors, mass, 2.0).save(path);
  CHECK(eigenbasis_load_error(path).empty());
  std::remove(path.c_str());
}
