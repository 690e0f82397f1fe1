// Statistical shape models: a family of ellipsoids whose x and y semi-axes vary independently on a
// 3 × 3 grid (one connectivity): exactly two modes, along the x and y stretches, with the
// variances of the design; random rigid motions of the specimens change nothing (Procrustes);
// a training shape is reconstructed exactly with all modes, the leave-one-out generalization with
// both modes is 0; the Gram and SVD routes agree; save/load round trip and corrupt files; the
// meshes of instances; bad input. Generic parts over the three mesh types.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/mesh/primitives.h>
#include <shapecorr/shape_model.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <random>

namespace SP = shapecorr::parameters;

namespace {

// the grid of semi-axes: a in {0.7, 1, 1.3}, b in {0.9, 1, 1.1}, c = 1 (a's variance 0.0675 and
// b's 0.0075 over the nine shapes, divided by N − 1 = 8; uncorrelated by design)
const double grid_a[3] = {0.7, 1.0, 1.3}, grid_b[3] = {0.9, 1.0, 1.1};

template <typename Mesh>
std::vector<Mesh> ellipsoid_family(int subdivisions, unsigned motion_seed) {
  std::vector<Mesh> meshes;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      Mesh m;
      shapecorr::make_icosphere(m, subdivisions);
      const Eigen::Isometry3d T = motion_seed ? test::representable_rigid_motion<Mesh>(motion_seed + unsigned(3 * i + j)) : Eigen::Isometry3d::Identity();
      test::transform_points(m, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(T * Eigen::Vector3d(grid_a[i] * p.x(), grid_b[j] * p.y(), p.z())); });
      meshes.push_back(std::move(m));
    }
  return meshes;
}

// The unit sphere's coordinate `axis` at every vertex, as a 3n vector with zeros elsewhere,
// normalized: the direction in which stretching that axis moves the shape.
Eigen::VectorXd stretch_direction(int subdivisions, int axis) {
  test::Surface_mesh m;
  shapecorr::make_icosphere(m, subdivisions);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(num_vertices(m)));
  for(auto v : vertices(m)) d[3 * static_cast<Eigen::Index>(v.idx()) + axis] = m.point(v)[axis];
  return d.normalized();
}

double sum_of_squares(int subdivisions, int axis) {
  test::Surface_mesh m;
  shapecorr::make_icosphere(m, subdivisions);
  double s = 0;
  for(auto v : vertices(m)) s += m.point(v)[axis] * m.point(v)[axis];
  return s;
}

template <typename Mesh>
Eigen::VectorXd shape_of(const Mesh& m) {
  Eigen::VectorXd x(3 * static_cast<Eigen::Index>(num_vertices(m)));
  Eigen::Index i = 0; // point i: the i-th vertex in iteration order (the default vertex index of the three types)
  for(auto v : vertices(m)) {
    const auto& p = get(CGAL::vertex_point, m, v);
    x[i] = p[0], x[i + 1] = p[1], x[i + 2] = p[2];
    i += 3;
  }
  return x;
}

} // namespace

TEMPLATE_LIST_TEST_CASE("shape model: ellipsoids with two independent axes give two modes along them", "[shape_model]", test::Mesh_types) {
  const int level = 2;
  const double tol = std::is_same<TestType, test::OpenMesh_mesh>::value ? 1e-5 : 1e-9;
  for(unsigned motion : {0u, 17u}) {
    INFO("random rigid motions of the specimens: " << (motion ? "yes" : "no"));
    const std::vector<TestType> meshes = ellipsoid_family<TestType>(level, motion);
    const shapecorr::Statistical_shape_model model = shapecorr::build_statistical_shape_model(meshes);
    REQUIRE(model.number_of_training_shapes() == 9);
    // two modes hold the variance; the analytic variances var(a) Σx², var(b) Σy²
    REQUIRE(model.number_of_modes() >= 2);
    const Eigen::VectorXd ratios = model.explained_variance_ratios();
    CHECK(ratios[0] + ratios[1] > 1 - tol);
    CHECK(model.variances()[0] == Approx(0.0675 * sum_of_squares(level, 0)).epsilon(tol));
    CHECK(model.variances()[1] == Approx(0.0075 * sum_of_squares(level, 1)).epsilon(tol));
    // along the right directions (motion: the frame is the first specimen's, the directions turn with it)
    if(motion == 0) {
      CHECK(std::abs(model.modes().col(0).dot(stretch_direction(level, 0))) > 1 - tol);
      CHECK(std::abs(model.modes().col(1).dot(stretch_direction(level, 1))) > 1 - tol);
    }
    // a training shape, in its own pose, comes back with all modes; with one mode it does not
    const Eigen::VectorXd x = shape_of(meshes[8]); // a = 1.3, b = 1.1 (not the mean)
    CHECK(shapecorr::internal::mean_vertex_distance(model.reconstruct(x, model.number_of_modes()), x) < 1e-6);
    CHECK(shapecorr::internal::mean_vertex_distance(model.reconstruct(x, 1), x) > 1e-3);
  }
}

TEST_CASE("shape model: Procrustes alignment removes a random rigid motion", "[shape_model]") {
  test::Surface_mesh m;
  shapecorr::make_creature(m, 2);
  const Eigen::VectorXd x = shape_of(m);
  const Eigen::Index n = x.size() / 3;
  const Eigen::Matrix3Xd X = Eigen::Map<const Eigen::Matrix3Xd>(x.data(), 3, n);
  for(unsigned seed = 1; seed <= 5; ++seed) {
    const Eigen::Isometry3d T = test::random_rigid_motion(seed);
    const Eigen::Matrix3Xd Y = T * X;
    for(bool scale : {false, true}) {
      const double s = scale ? 1.7 : 1.0;
      const shapecorr::Procrustes_alignment gpa = shapecorr::generalized_procrustes_alignment({X, s * Y}, scale);
      CHECK(gpa.converged);
      // both land on the first shape, where it was (with scale: at the mean centroid size, (1 + s)/2 of it)
      const double m = scale ? (1 + s) / 2 : 1.0;
      const Eigen::Vector3d c = X.rowwise().mean();
      const Eigen::Matrix3Xd expected = ((m * (X.colwise() - c)).colwise() + c);
      CHECK((gpa.aligned[0] - expected).norm() / X.norm() < 1e-9);
      CHECK((gpa.aligned[1] - expected).norm() / X.norm() < 1e-9);
      CHECK((gpa.mean - expected).norm() / X.norm() < 1e-9);
      CHECK(gpa.transforms[1].scale == Approx(m / s).epsilon(1e-9));
    }
  }
  // a family in size only: one mode without scale, none with it
  std::vector<Eigen::Matrix3Xd> sizes;
  for(double s : {0.8, 1.0, 1.3}) sizes.push_back(s * X);
  const std::vector<std::array<std::size_t, 3>> no_faces = {{0, 1, 2}};
  CHECK(shapecorr::build_statistical_shape_model(sizes, no_faces, false).number_of_modes() == 1);
  CHECK(shapecorr::build_statistical_shape_model(sizes, no_faces, true).number_of_modes() == 0);
}

TEST_CASE("shape model: the Gram route and the dense SVD agree", "[shape_model]") {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  Eigen::MatrixXd D(600, 7);
  for(Eigen::Index i = 0; i < D.size(); ++i) D.data()[i] = g(rng) * (1 + static_cast<double>(i % 7));
  D.colwise() -= D.rowwise().mean();
  const auto a = shapecorr::principal_components(D, shapecorr::Pca_method::GRAM_MATRIX);
  const auto b = shapecorr::principal_components(D, shapecorr::Pca_method::DENSE_SVD);
  REQUIRE(a.variances.size() == 6); // N − 1 after centring
  REQUIRE(b.variances.size() == 6);
  CHECK((a.variances - b.variances).cwiseAbs().maxCoeff() < 1e-9 * a.variances[0]);
  CHECK((a.modes - b.modes).cwiseAbs().maxCoeff() < 1e-7);
  CHECK(a.total_variance == Approx(a.variances.sum()).epsilon(1e-12));
  CHECK((a.modes.transpose() * a.modes).isIdentity(1e-10));
  CHECK_THROWS_AS(shapecorr::principal_components(D.leftCols(1)), shapecorr::Invalid_argument);
}

TEST_CASE("shape model: generalization, specificity, compactness", "[shape_model]") {
  const std::vector<test::Surface_mesh> meshes = ellipsoid_family<test::Surface_mesh>(1, 3);
  const shapecorr::Statistical_shape_model model = shapecorr::build_statistical_shape_model(meshes);
  // leave-one-out: any eight of the nine grid shapes still span both stretches
  const shapecorr::Shape_model_curve G = shapecorr::shape_model_generalization(model, SP::number_of_threads(2));
  REQUIRE(G.value.size() == 7);
  CHECK(G.value[0] > 1e-3);
  CHECK(G.value[1] < 1e-9);
  const shapecorr::Shape_model_curve C = shapecorr::shape_model_compactness(model);
  CHECK(C.value.back() == Approx(model.total_variance()).epsilon(1e-9));
  CHECK(C.value[1] / model.total_variance() > 1 - 1e-9);
  // specificity: deterministic with the seed; with one mode an instance is the ellipsoid
  // a = 1 + c sd(a), b = 1 (c the sample's first coefficient), whose nearest training shape is the
  // grid's nearest a with b = 1, at the mean vertex distance |Δa| mean|x|: the same draws give S(1)
  const auto S1 = shapecorr::shape_model_specificity(model, SP::number_of_samples(200).random_seed(3));
  const auto S2 = shapecorr::shape_model_specificity(model, SP::number_of_samples(200).random_seed(3).number_of_threads(1));
  REQUIRE(S1.value.size() == model.number_of_modes());
  CHECK(S1.value == S2.value);
  std::mt19937_64 random(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  test::Surface_mesh sphere;
  shapecorr::make_icosphere(sphere, 1);
  double mean_abs_x = 0;
  for(auto v : vertices(sphere)) mean_abs_x += std::abs(sphere.point(v).x()) / static_cast<double>(num_vertices(sphere));
  double expected = 0;
  for(int sample = 0; sample < 200; ++sample) {
    const double a = 1 + normal(random) * std::sqrt(0.0675);
    for(std::size_t i = 1; i < model.number_of_modes(); ++i) normal(random); // the other modes' draws
    double nearest = 1e300;
    for(double g : grid_a) nearest = std::min(nearest, std::abs(a - g));
    expected += nearest * mean_abs_x / 200;
  }
  CHECK(S1.value[0] == Approx(expected).epsilon(1e-6));
  CHECK(S1.value[1] > S1.value[0]); // two modes stray further from the nine shapes
  // a truncated model cannot give back its training shapes
  shapecorr::Statistical_shape_model truncated(model.mean(), model.modes().leftCols(1), model.variances().head(1), model.total_variance(),
                                               model.triangles(), model.training_scores().topRows(1));
  CHECK_THROWS_AS(shapecorr::shape_model_generalization(truncated), shapecorr::Invalid_argument);
}

TEMPLATE_LIST_TEST_CASE("shape model: save and load, instances as meshes", "[shape_model]", test::Mesh_types) {
  const std::vector<TestType> meshes = ellipsoid_family<TestType>(1, 0);
  shapecorr::Statistical_shape_model model = shapecorr::build_statistical_shape_model(meshes, SP::allow_scaling(true));
  std::vector<std::string> names;
  for(int i = 0; i < 9; ++i) names.push_back("specimen_" + std::to_string(i) + (i == 3 ? " (with spaces, ü)" : ""));
  model.set_training_names(names);
  const std::string path = test::temp_path("model.ssm");
  model.save(path);
  const shapecorr::Statistical_shape_model back = shapecorr::Statistical_shape_model::load(path);
  CHECK(back.mean() == model.mean());
  CHECK(back.modes() == model.modes());
  CHECK(back.variances() == model.variances());
  CHECK(back.training_scores() == model.training_scores());
  CHECK(back.triangles() == model.triangles());
  CHECK(back.training_names() == names);
  CHECK(back.with_scale());
  CHECK(back.total_variance() == model.total_variance());

  // an instance as a mesh: the model's connectivity, point i at vertex i
  Eigen::VectorXd c(2);
  c << 2.0, -1.0;
  const Eigen::VectorXd x = model.instance(c);
  TestType out;
  shapecorr::make_shape_mesh(model, x, out);
  CHECK(num_vertices(out) == model.number_of_vertices());
  CHECK(num_faces(out) == model.triangles().size());
  CHECK((shape_of(out) - x).cwiseAbs().maxCoeff() < 1e-6);
  // its coefficients come back by projection (the rigid model: with scale, projection also rescales the instance)
  const auto rigid = shapecorr::build_statistical_shape_model(meshes);
  CHECK((rigid.project(rigid.instance(c)).coefficients.head(2) - c).cwiseAbs().maxCoeff() < 1e-5);

  // corrupt, truncated, foreign files: typed errors
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  auto write = [&](const std::string& b) {
    std::ofstream out(path, std::ios::binary);
    out << b;
  };
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 1;
  write(flipped);
  CHECK_THROWS_WITH(shapecorr::Statistical_shape_model::load(path), Catch::Contains("checksum"));
  write(bytes.substr(0, bytes.size() / 3));
  CHECK_THROWS_AS(shapecorr::Statistical_shape_model::load(path), shapecorr::Invalid_input);
  std::string huge = bytes;
  huge[12] = char(0xff), huge[13] = char(0xff), huge[17] = char(0x7f); // n: an absurd vertex count
  write(huge);
  CHECK_THROWS_WITH(shapecorr::Statistical_shape_model::load(path), Catch::Contains("disagree"));
  write("SCLBEIG2 something else");
  CHECK_THROWS_WITH(shapecorr::Statistical_shape_model::load(path), Catch::Contains("not a ShapeCorr shape model"));
  CHECK_THROWS_AS(shapecorr::Statistical_shape_model::load(path + ".missing"), shapecorr::Invalid_input);
}

TEST_CASE("shape model: bad input", "[shape_model]") {
  std::vector<test::Surface_mesh> meshes = ellipsoid_family<test::Surface_mesh>(1, 0);
  CHECK_THROWS_AS(shapecorr::build_statistical_shape_model(std::vector<test::Surface_mesh>(meshes.begin(), meshes.begin() + 1)), shapecorr::Invalid_argument);
  test::Surface_mesh other;
  shapecorr::make_icosphere(other, 2);
  meshes.push_back(other);
  CHECK_THROWS_WITH(shapecorr::build_statistical_shape_model(meshes), Catch::Contains("fit one template"));
  meshes.pop_back();
  meshes[2].point(*vertices(meshes[2]).begin()) = test::Point(std::nan(""), 0, 0);
  CHECK_THROWS_AS(shapecorr::build_statistical_shape_model(meshes), shapecorr::Invalid_input);
  meshes = ellipsoid_family<test::Surface_mesh>(1, 0);
  const auto model = shapecorr::build_statistical_shape_model(meshes);
  CHECK_THROWS_AS(model.instance(Eigen::VectorXd::Ones(50)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(model.project(Eigen::VectorXd::Zero(6)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::shape_model_specificity(model, SP::number_of_samples(0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Statistical_shape_model(Eigen::VectorXd::Zero(6), Eigen::MatrixXd::Zero(6, 1), Eigen::VectorXd::Ones(1), 1.0, {}),
                  shapecorr::Invalid_argument); // modes not orthonormal
}
