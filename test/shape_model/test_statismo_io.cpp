// The Statismo HDF5 layout (built only where HDF5 is installed): a model written and read back
// (single precision, as Statismo stores it), the layout's groups, datasets and attributes as
// Statismo 0.9 and Scalismo read them, a Statismo 0.8 file (basis scaled by the standard
// deviations), and files that are not models.
#include "test_meshes.h"

#include <shapecorr/mesh/primitives.h>
#include <shapecorr/shape_model.h>
#include <shapecorr/shape_model/statismo_io.h>

#include <catch2/catch.hpp>

#include <fstream>

namespace {
shapecorr::Statistical_shape_model stretched_spheres() {
  std::vector<test::Surface_mesh> meshes;
  for(double a : {0.8, 1.0, 1.2, 1.1})
    for(double b : {0.9, 1.1}) {
      test::Surface_mesh m;
      shapecorr::make_icosphere(m, 1);
      for(auto v : vertices(m)) m.point(v) = test::Point(a * m.point(v).x(), b * m.point(v).y(), m.point(v).z() + 0.1 * a * b);
      meshes.push_back(m);
    }
  shapecorr::Statistical_shape_model model = shapecorr::build_statistical_shape_model(meshes, CGAL::parameters::default_values());
  std::vector<std::string> names;
  for(std::size_t i = 0; i < meshes.size(); ++i) names.push_back("fit_" + std::to_string(i) + ".ply");
  model.set_training_names(names);
  return model;
}

std::string text_attribute(hid_t object, const char* name) {
  shapecorr::internal::H5_handle a(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  shapecorr::internal::H5_handle type(H5Aget_type(a), H5Tclose);
  std::string s(H5Tget_size(type), '\0');
  H5Aread(a, type, &s[0]);
  return s.substr(0, s.find('\0'));
}
} // namespace

TEST_CASE("statismo: round trip and layout", "[shape_model][statismo]") {
  const shapecorr::Statistical_shape_model model = stretched_spheres();
  const std::string path = test::temp_path("model.h5");
  shapecorr::write_statismo_model(model, path);
  const shapecorr::Statistical_shape_model back = shapecorr::read_statismo_model(path);
  REQUIRE(back.number_of_modes() == model.number_of_modes());
  REQUIRE(back.number_of_training_shapes() == model.number_of_training_shapes());
  CHECK((back.mean() - model.mean()).cwiseAbs().maxCoeff() < 1e-6);
  CHECK((back.modes() - model.modes()).cwiseAbs().maxCoeff() < 1e-6);
  CHECK(((back.variances() - model.variances()).cwiseQuotient(model.variances())).cwiseAbs().maxCoeff() < 1e-6);
  CHECK((back.training_scores() - model.training_scores()).cwiseAbs().maxCoeff() < 1e-5);
  CHECK(back.triangles() == model.triangles());
  CHECK(back.training_names() == model.training_names());
  CHECK(back.total_variance() == Approx(model.total_variance()).epsilon(1e-12));
  CHECK(!back.with_scale());
  // an instance drawn from both agrees to single precision
  Eigen::VectorXd c(2);
  c << 1.5, -0.5;
  CHECK((back.instance(c) - model.instance(c)).cwiseAbs().maxCoeff() < 1e-5);

  // the layout Statismo's StatisticalModel::Load and Scalismo's reader look for
  shapecorr::internal::H5_handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  REQUIRE(file.valid());
  for(const char* name : {"/version/majorVersion", "/version/minorVersion", "/model/mean", "/model/pcaBasis", "/model/pcaVariance",
                          "/model/noiseVariance", "/representer/points", "/representer/cells", "/modelinfo/scores", "/modelinfo/build-time",
                          "/modelinfo/modelBuilder-0/builderName", "/modelinfo/modelBuilder-0/dataInfo/URI-0"})
    CHECK(H5Lexists(file, name, H5P_DEFAULT) > 0);
  shapecorr::internal::H5_handle representer(H5Gopen2(file, "representer", H5P_DEFAULT), H5Gclose);
  CHECK(text_attribute(representer, "datasetType") == "POLYGON_MESH");
  CHECK(text_attribute(representer, "name") == "vtkStandardMeshRepresenter");
  shapecorr::internal::H5_handle points(H5Dopen2(file, "/representer/points", H5P_DEFAULT), H5Dclose);
  shapecorr::internal::H5_handle space(H5Dget_space(points), H5Sclose);
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  CHECK(dims[0] == 3);
  CHECK(dims[1] == model.number_of_vertices());
  shapecorr::internal::H5_handle basis(H5Dopen2(file, "/model/pcaBasis", H5P_DEFAULT), H5Dclose);
  shapecorr::internal::H5_handle type(H5Dget_type(basis), H5Tclose);
  CHECK(H5Tget_class(type) == H5T_FLOAT);
  CHECK(H5Tget_size(type) == 4); // single precision, as Statismo writes
}

TEST_CASE("statismo: a 0.8 file and files that are not models", "[shape_model][statismo]") {
  const shapecorr::Statistical_shape_model model = stretched_spheres();
  const std::string path = test::temp_path("old.h5");
  shapecorr::write_statismo_model(model, path);
  {
    // Statismo 0.8: no /version, the basis stored times the standard deviations
    shapecorr::internal::H5_handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
    REQUIRE(H5Ldelete(file, "/version", H5P_DEFAULT) >= 0);
    REQUIRE(H5Ldelete(file, "/model/pcaBasis", H5P_DEFAULT) >= 0);
    shapecorr::internal::Statismo_writer w{path};
    shapecorr::internal::H5_handle m(H5Gopen2(file, "model", H5P_DEFAULT), H5Gclose);
    w.floats(m, "pcaBasis", model.modes() * model.variances().cwiseSqrt().asDiagonal(), false);
  }
  const shapecorr::Statistical_shape_model old = shapecorr::read_statismo_model(path);
  CHECK((old.modes() - model.modes()).cwiseAbs().maxCoeff() < 1e-6);

  const std::string other = test::temp_path("other.h5");
  { std::ofstream(other) << "not HDF5 at all"; }
  CHECK_THROWS_WITH(shapecorr::read_statismo_model(other), Catch::Contains("not an HDF5 file"));
  CHECK_THROWS_AS(shapecorr::read_statismo_model(other + ".missing"), shapecorr::Invalid_input);
  {
    shapecorr::internal::H5_handle file(H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  }
  CHECK_THROWS_WITH(shapecorr::read_statismo_model(other), Catch::Contains("not a Statismo model"));
  // a model without modes cannot be written (Statismo keeps at least one)
  const shapecorr::Statistical_shape_model empty(model.mean(), Eigen::MatrixXd(model.mean().size(), 0), Eigen::VectorXd(0), 0.0, model.triangles());
  CHECK_THROWS_AS(shapecorr::write_statismo_model(empty, other), shapecorr::Output_error);
}
