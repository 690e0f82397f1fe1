// Discrete Laplace operators: L 1 = 0, symmetry, positive semi-definiteness, the Dirichlet energy of
// a linear function on a flat patch (= area), vertex areas summing to the surface area, the graph
// Laplacian's degrees.
#include "spectral_test_helpers.h"

#include <shapecorr/operators/laplacian.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <catch2/catch.hpp>

namespace SP = shapecorr::parameters;

TEMPLATE_LIST_TEST_CASE("cotangent Laplacian: L 1 = 0, symmetric, positive semi-definite", "[spectral][laplacian]", test::Mesh_types) {
  TestType m;
  test::make_ellipsoid(m, 3);
  for(bool idt : {false, true}) {
    const Eigen::SparseMatrix<double> L = shapecorr::cotangent_laplacian(m, SP::use_intrinsic_delaunay(idt));
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(L.rows());
    CHECK((L * ones).cwiseAbs().maxCoeff() < 1e-12 * L.diagonal().maxCoeff());
    CHECK((Eigen::SparseMatrix<double>(L.transpose()) - L).norm() < 1e-12 * L.norm());
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    for(int trial = 0; trial < 5; ++trial) {
      Eigen::VectorXd x(L.rows());
      for(Eigen::Index i = 0; i < x.size(); ++i) x[i] = g(rng);
      CHECK(x.dot(L * x) >= 0);
    }
  }
}

TEMPLATE_LIST_TEST_CASE("cotangent Laplacian: Dirichlet energy of a linear function on a flat patch is the area", "[spectral][laplacian]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 9, 6, 2.0, 1.5); // area 3
  // move interior vertices off the regular lattice so that some triangles are obtuse
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  test::transform_points(m, [&](const Eigen::Vector3d& p) {
    const bool interior = p.x() > 1e-9 && p.x() < 2 - 1e-9 && p.y() > 1e-9 && p.y() < 1.5 - 1e-9;
    return interior ? Eigen::Vector3d(p.x() + u(rng), p.y() + u(rng), 0) : p;
  });
  const auto vs = test::vertices_in_index_order(m);
  auto vpm = get(CGAL::vertex_point, m);
  Eigen::VectorXd f(static_cast<Eigen::Index>(vs.size()));
  for(std::size_t i = 0; i < vs.size(); ++i) f[static_cast<Eigen::Index>(i)] = 0.6 * get(vpm, vs[i]).x() + 0.8 * get(vpm, vs[i]).y(); // |grad f| = 1
  for(bool idt : {false, true}) {
    const Eigen::SparseMatrix<double> L = shapecorr::cotangent_laplacian(m, SP::use_intrinsic_delaunay(idt));
    CHECK(f.dot(L * f) == Approx(3.0).epsilon(1e-10));
  }
}

TEMPLATE_LIST_TEST_CASE("lumped mass matrices sum to the surface area", "[spectral][laplacian]", test::Mesh_types) {
  TestType m;
  test::make_ellipsoid(m, 2);
  const double area = CGAL::Polygon_mesh_processing::area(m);
  const Eigen::VectorXd b = shapecorr::lumped_mass_matrix(m);
  const Eigen::VectorXd v = shapecorr::lumped_mass_matrix(m, SP::mass_matrix_type(shapecorr::Mass_matrix_type::MIXED_VORONOI));
  CHECK(b.sum() == Approx(area).epsilon(1e-12));
  CHECK(v.sum() == Approx(area).epsilon(1e-12));
  CHECK(b.minCoeff() > 0);
  CHECK(v.minCoeff() > 0);
  CHECK((b - v).cwiseAbs().maxCoeff() > 0); // different rules
}

TEST_CASE("mixed Voronoi areas on a regular flat grid: interior vertices own one cell", "[spectral][laplacian]") {
  test::Surface_mesh m;
  shapecorr::make_grid(m, 4, 4, 4.0, 4.0); // unit cells, right triangles: the circumcentre is on the hypotenuse
  const Eigen::VectorXd v = shapecorr::lumped_mass_matrix(m, SP::mass_matrix_type(shapecorr::Mass_matrix_type::MIXED_VORONOI));
  const std::size_t centre = 2 * 5 + 2; // vertex (2, 2)
  CHECK(v[static_cast<Eigen::Index>(centre)] == Approx(1.0).epsilon(1e-12));
}

TEMPLATE_LIST_TEST_CASE("combinatorial Laplacian: degrees on the diagonal, L 1 = 0", "[spectral][laplacian]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 1); // icosahedron vertices have degree 5, the new ones 6
  const Eigen::SparseMatrix<double> L = shapecorr::combinatorial_laplacian(m);
  CHECK((L * Eigen::VectorXd::Ones(L.rows())).cwiseAbs().maxCoeff() == 0);
  for(Eigen::Index i = 0; i < 12; ++i) CHECK(L.coeff(i, i) == 5);
  for(Eigen::Index i = 12; i < L.rows(); ++i) CHECK(L.coeff(i, i) == 6);
}

TEST_CASE("Laplace operators reject empty meshes and NaN coordinates", "[spectral][laplacian][errors]") {
  test::Surface_mesh empty;
  CHECK_THROWS_AS(shapecorr::cotangent_laplacian(empty), shapecorr::Invalid_input);
  test::Surface_mesh m;
  shapecorr::make_icosphere(m, 1);
  m.point(test::Surface_mesh::Vertex_index(3)) = test::Point(std::nan(""), 0, 0);
  try {
    shapecorr::cotangent_laplacian(m);
    FAIL("no exception");
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(e.defect() == shapecorr::Mesh_defect::non_finite_coordinate);
  }
}
