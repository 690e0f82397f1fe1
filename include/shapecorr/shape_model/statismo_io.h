// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file statismo_io.h
/// A statistical shape model in the Statismo HDF5 layout (file format 0.9, mesh representer), so
/// that models open in Statismo and Scalismo tools and theirs open here. Needs HDF5 (Debian
/// `libhdf5-dev`; link `HDF5::HDF5`, or the CMake target `ShapeCorr::HDF5` when the project found
/// it); `shapecorr/shape_model.h` does not include this header.
#ifndef SHAPECORR_SHAPE_MODEL_STATISMO_IO_H
#define SHAPECORR_SHAPE_MODEL_STATISMO_IO_H

#include <shapecorr/exceptions.h>
#include <shapecorr/shape_model/Statistical_shape_model.h>

#include <hdf5.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

namespace shapecorr {
namespace internal {

/// An HDF5 identifier closed by `close` when the handle goes (files, groups, datasets, spaces, types).
class H5_handle {
public:
  H5_handle(hid_t id, herr_t (*close)(hid_t)) : m_id(id), m_close(close) {}
  H5_handle(const H5_handle&) = delete;
  H5_handle& operator=(const H5_handle&) = delete;
  ~H5_handle() {
    if(m_id >= 0) m_close(m_id);
  }
  operator hid_t() const { return m_id; }
  bool valid() const { return m_id >= 0; }

private:
  hid_t m_id;
  herr_t (*m_close)(hid_t);
};

/// Silences HDF5's own error printing while it lives (errors become our exceptions).
class H5_quiet {
public:
  H5_quiet() {
    H5Eget_auto2(H5E_DEFAULT, &m_func, &m_data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~H5_quiet() { H5Eset_auto2(H5E_DEFAULT, m_func, m_data); }

private:
  H5E_auto2_t m_func = nullptr;
  void* m_data = nullptr;
};

struct Statismo_writer {
  std::string path;
  void check(herr_t status, const std::string& what) const {
    if(status < 0) throw Output_error("statismo: writing '" + path + "' failed (" + what + ")");
  }
  hid_t group(hid_t parent, const char* name) const {
    const hid_t g = H5Gcreate2(parent, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if(g < 0) throw Output_error("statismo: writing '" + path + "' failed (group " + name + ")");
    return g;
  }
  // a dataset of `rank` dimensions `dims`, stored as `file_type`, from memory of `memory_type`
  void dataset(hid_t parent, const char* name, int rank, const hsize_t* dims, hid_t file_type, hid_t memory_type, const void* data) const {
    H5_handle space(rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims, nullptr), H5Sclose);
    H5_handle set(H5Dcreate2(parent, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    if(!space.valid() || !set.valid()) throw Output_error("statismo: writing '" + path + "' failed (dataset " + name + ")");
    check(H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), name);
  }
  // floats, as Statismo stores them (row-major: a rows × cols matrix is rows × cols in the file)
  void floats(hid_t parent, const char* name, const Eigen::MatrixXd& m, bool vector) const {
    const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> f = m.cast<float>();
    const hsize_t dims[2] = {static_cast<hsize_t>(m.rows()), static_cast<hsize_t>(m.cols())};
    dataset(parent, name, vector ? 1 : 2, dims, H5T_NATIVE_FLOAT, H5T_NATIVE_FLOAT, f.data());
  }
  void integer(hid_t parent, const char* name, int value) const { dataset(parent, name, 0, nullptr, H5T_NATIVE_INT32, H5T_NATIVE_INT32, &value); }
  void text(hid_t parent, const char* name, const std::string& s) const {
    H5_handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    check(H5Tset_size(type, s.size() + 1), name);
    dataset(parent, name, 0, nullptr, type, type, s.c_str());
  }
  void text_attribute(hid_t object, const char* name, const std::string& s) const {
    H5_handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    check(H5Tset_size(type, s.size() + 1), name);
    H5_handle space(H5Screate(H5S_SCALAR), H5Sclose);
    H5_handle attribute(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if(!attribute.valid()) throw Output_error("statismo: writing '" + path + "' failed (attribute " + name + ")");
    check(H5Awrite(attribute, type, s.c_str()), name);
  }
};

struct Statismo_reader {
  std::string path;
  hsize_t budget; // elements a dataset may hold: bounded by the file's size (see read_statismo_model)
  [[noreturn]] void fail(const std::string& why) const { throw Invalid_input(Mesh_defect::unreadable_file, "statismo: '" + path + "': " + why); }
  bool exists(hid_t parent, const char* name) const { return H5Lexists(parent, name, H5P_DEFAULT) > 0; }
  // the dimensions of a dataset (checked against `rank` and the budget)
  std::vector<hsize_t> dims(hid_t set, const char* name, int rank) const {
    H5_handle space(H5Dget_space(set), H5Sclose);
    const int r = space.valid() ? H5Sget_simple_extent_ndims(space) : -1;
    if(r != rank) fail(std::string(name) + " has " + std::to_string(r) + " dimensions, " + std::to_string(rank) + " expected");
    std::vector<hsize_t> d(static_cast<std::size_t>(std::max(rank, 1)), 1);
    if(rank > 0) H5Sget_simple_extent_dims(space, d.data(), nullptr);
    hsize_t count = 1;
    for(hsize_t x : d) {
      if(x != 0 && count > budget / x) fail(std::string(name) + " claims more elements than the file can hold");
      count *= x;
    }
    return d;
  }
  // a float or double dataset of rank 1 or 2, read as doubles (row-major in the file)
  Eigen::MatrixXd matrix(hid_t parent, const char* name, int rank) const {
    H5_handle set(H5Dopen2(parent, name, H5P_DEFAULT), H5Dclose);
    if(!set.valid()) fail(std::string("no dataset ") + name);
    const std::vector<hsize_t> d = dims(set, name, rank);
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m(static_cast<Eigen::Index>(d[0]), static_cast<Eigen::Index>(rank == 2 ? d[1] : 1));
    if(m.size() > 0 && H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, m.data()) < 0) fail(std::string("cannot read ") + name + " as numbers");
    return m;
  }
  std::vector<std::uint32_t> cells(hid_t parent, const char* name, hsize_t& rows, hsize_t& cols) const {
    H5_handle set(H5Dopen2(parent, name, H5P_DEFAULT), H5Dclose);
    if(!set.valid()) fail(std::string("no dataset ") + name);
    const std::vector<hsize_t> d = dims(set, name, 2);
    rows = d[0], cols = d[1];
    std::vector<std::uint32_t> c(static_cast<std::size_t>(rows * cols));
    if(!c.empty() && H5Dread(set, H5T_NATIVE_UINT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, c.data()) < 0) fail(std::string("cannot read ") + name + " as indices");
    return c;
  }
  std::string text(hid_t parent, const char* name) const {
    H5_handle set(H5Dopen2(parent, name, H5P_DEFAULT), H5Dclose);
    if(!set.valid()) fail(std::string("no dataset ") + name);
    H5_handle type(H5Dget_type(set), H5Tclose);
    if(H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0) fail(std::string(name) + " is not a fixed-length string");
    const std::size_t size = H5Tget_size(type);
    if(size > budget) fail(std::string(name) + " is longer than the file");
    std::string s(size, '\0');
    if(size > 0 && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &s[0]) < 0) fail(std::string("cannot read ") + name);
    return s.substr(0, s.find('\0'));
  }
  int integer(hid_t parent, const char* name) const {
    H5_handle set(H5Dopen2(parent, name, H5P_DEFAULT), H5Dclose);
    if(!set.valid()) fail(std::string("no dataset ") + name);
    dims(set, name, 0);
    int v = 0;
    if(H5Dread(set, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, &v) < 0) fail(std::string("cannot read ") + name);
    return v;
  }
};

} // namespace internal

/// \ingroup PkgShapeCorrShapeModel
/// Writes `model` in the Statismo HDF5 layout, format 0.9: `/version` (majorVersion 0,
/// minorVersion 9); `/representer` (attributes name "vtkStandardMeshRepresenter", datasetType
/// "POLYGON_MESH"; `points` 3 × n, the mean shape as reference; `cells` 3 × m); `/model` (`mean`
/// 3n, `pcaBasis` 3n × k orthonormal, `pcaVariance` k, `noiseVariance` 0); `/modelinfo`
/// (`build-time`, `scores` k × N, and `modelBuilder-0` with the builder name, the training shapes'
/// names as `dataInfo` and ShapeCorr's `totalVariance` and `withScale` as `parameters`). Numbers
/// are single precision, as Statismo stores them (a round trip keeps about 7 digits).
/// \throws Output_error when the file cannot be written
inline void write_statismo_model(const Statistical_shape_model& model, const std::string& path) {
  using namespace internal;
  if(model.number_of_modes() == 0) throw Output_error("statismo: '" + path + "': a model without modes cannot be written (Statismo stores at least one)");
  H5_quiet quiet;
  const Statismo_writer w{path};
  H5_handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if(!file.valid()) throw Output_error("statismo: cannot write '" + path + "'");
  {
    H5_handle version(w.group(file, "version"), H5Gclose);
    w.integer(version, "majorVersion", 0);
    w.integer(version, "minorVersion", 9);
  }
  const Eigen::Index n = static_cast<Eigen::Index>(model.number_of_vertices());
  {
    H5_handle representer(w.group(file, "representer"), H5Gclose);
    w.text_attribute(representer, "name", "vtkStandardMeshRepresenter");
    w.text_attribute(representer, "version", "1.0");
    w.text_attribute(representer, "datasetType", "POLYGON_MESH");
    w.floats(representer, "points", Eigen::Map<const Eigen::MatrixXd>(model.mean().data(), 3, n), false);
    Eigen::Matrix<std::uint32_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> cells(3, static_cast<Eigen::Index>(model.triangles().size()));
    for(std::size_t f = 0; f < model.triangles().size(); ++f)
      for(int c = 0; c < 3; ++c) cells(c, static_cast<Eigen::Index>(f)) = static_cast<std::uint32_t>(model.triangles()[f][static_cast<std::size_t>(c)]);
    const hsize_t dims[2] = {3, static_cast<hsize_t>(cells.cols())};
    w.dataset(representer, "cells", 2, dims, H5T_NATIVE_UINT32, H5T_NATIVE_UINT32, cells.data());
    H5_handle point_data(w.group(representer, "pointData"), H5Gclose), cell_data(w.group(representer, "cellData"), H5Gclose);
  }
  {
    H5_handle m(w.group(file, "model"), H5Gclose);
    w.floats(m, "mean", model.mean(), true);
    w.floats(m, "pcaBasis", model.modes(), false);
    w.floats(m, "pcaVariance", model.variances(), true);
    const float noise = 0;
    w.dataset(m, "noiseVariance", 0, nullptr, H5T_NATIVE_FLOAT, H5T_NATIVE_FLOAT, &noise);
  }
  {
    const std::time_t now = std::time(nullptr);
    char when[64] = {0};
    std::strftime(when, sizeof when, "%a %b %d %H:%M:%S %Y\n", std::gmtime(&now));
    H5_handle info(w.group(file, "modelinfo"), H5Gclose);
    w.text(info, "build-time", when);
    // Statismo cannot store an empty matrix: without scores it writes one zero
    w.floats(info, "scores", model.number_of_training_shapes() ? model.training_scores() : Eigen::MatrixXd::Zero(1, 1), false);
    H5_handle builder(w.group(info, "modelBuilder-0"), H5Gclose);
    w.text(builder, "builderName", "ShapeCorr build_statistical_shape_model (Procrustes + PCA)");
    w.text(builder, "buildTime", when);
    H5_handle data(w.group(builder, "dataInfo"), H5Gclose), parameters(w.group(builder, "parameters"), H5Gclose);
    for(std::size_t i = 0; i < model.training_names().size(); ++i) w.text(data, ("URI-" + std::to_string(i)).c_str(), model.training_names()[i]);
    char total[64];
    std::snprintf(total, sizeof total, "%.17g", model.total_variance());
    w.text(parameters, "totalVariance", total);
    w.text(parameters, "withScale", model.with_scale() ? "1" : "0");
  }
  if(H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) throw Output_error("statismo: writing '" + path + "' failed");
}

/// \ingroup PkgShapeCorrShapeModel
/// Reads a model in the Statismo HDF5 layout (format 0.9, or 0.8 whose basis is stored scaled by
/// the standard deviations; a mesh representer with `points` and triangle `cells`): the mean, the
/// modes, their variances, the scores when present (k × N), the triangles. The total variance is
/// ShapeCorr's `totalVariance` parameter when the file has it, else the sum of the variances
/// (Statismo does not keep the variance of dropped modes); `withScale` likewise, else false.
/// Every dataset's size is checked against the file's size before anything is allocated.
/// \throws Invalid_input (`unreadable_file`) naming the file and what is missing or wrong
inline Statistical_shape_model read_statismo_model(const std::string& path) {
  using namespace internal;
  std::ifstream probe(path, std::ios::binary | std::ios::ate);
  if(!probe) throw Invalid_input(Mesh_defect::unreadable_file, "statismo: cannot open '" + path + "'");
  const hsize_t file_bytes = static_cast<hsize_t>(std::max<std::streamoff>(probe.tellg(), 0));
  // elements of at least one byte each, compressed at most 1000-fold: a generous, finite bound
  const Statismo_reader r{path, 1000 * (file_bytes + 1)};
  H5_quiet quiet;
  if(H5Fis_hdf5(path.c_str()) <= 0) r.fail("not an HDF5 file");
  H5_handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if(!file.valid()) r.fail("cannot open the HDF5 file");
  int major = 0, minor = 8; // files without /version are Statismo 0.8
  if(r.exists(file, "version")) {
    H5_handle version(H5Gopen2(file, "version", H5P_DEFAULT), H5Gclose);
    major = r.integer(version, "majorVersion");
    minor = r.integer(version, "minorVersion");
  }
  if(major != 0 || (minor != 8 && minor != 9)) r.fail("Statismo format " + std::to_string(major) + "." + std::to_string(minor) + " (this build reads 0.8 and 0.9)");
  if(!r.exists(file, "model") || !r.exists(file, "representer")) r.fail("no /model or /representer group: not a Statismo model");
  H5_handle m(H5Gopen2(file, "model", H5P_DEFAULT), H5Gclose);
  const Eigen::VectorXd mean = r.matrix(m, "mean", 1);
  Eigen::MatrixXd basis = r.matrix(m, "pcaBasis", 2);
  const Eigen::VectorXd variances = r.matrix(m, "pcaVariance", 1);
  if(mean.size() == 0 || mean.size() % 3 != 0) r.fail("the mean has " + std::to_string(mean.size()) + " entries, not 3 per point");
  if(basis.rows() != mean.size() || basis.cols() != variances.size())
    r.fail("pcaBasis is " + std::to_string(basis.rows()) + " x " + std::to_string(basis.cols()) + ", the mean has " + std::to_string(mean.size()) +
           " entries and pcaVariance " + std::to_string(variances.size()));
  if(minor == 8)
    for(Eigen::Index j = 0; j < basis.cols(); ++j)
      if(variances[j] > 0) basis.col(j) /= std::sqrt(variances[j]);
  H5_handle representer(H5Gopen2(file, "representer", H5P_DEFAULT), H5Gclose);
  if(!r.exists(representer, "cells")) r.fail("the representer has no cells (a legacy or image representer: not read)");
  hsize_t rows = 0, cols = 0;
  const std::vector<std::uint32_t> cells = r.cells(representer, "cells", rows, cols);
  if(rows != 3) r.fail("cells of " + std::to_string(rows) + " points (triangles are read)");
  std::vector<std::array<std::size_t, 3>> triangles(static_cast<std::size_t>(cols));
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(std::size_t c = 0; c < 3; ++c) triangles[f][c] = cells[c * static_cast<std::size_t>(cols) + f];
  Eigen::MatrixXd scores;
  double total = variances.sum();
  bool with_scale = false;
  std::vector<std::string> names;
  if(r.exists(file, "modelinfo")) {
    H5_handle info(H5Gopen2(file, "modelinfo", H5P_DEFAULT), H5Gclose);
    if(r.exists(info, "scores")) {
      scores = r.matrix(info, "scores", 2);
      if(scores.rows() != variances.size()) scores.resize(0, 0); // Statismo's 1 x 1 stand-in for none, or foreign
    }
    if(r.exists(info, "modelBuilder-0")) {
      H5_handle builder(H5Gopen2(info, "modelBuilder-0", H5P_DEFAULT), H5Gclose);
      if(r.exists(builder, "parameters")) {
        H5_handle parameters(H5Gopen2(builder, "parameters", H5P_DEFAULT), H5Gclose);
        if(r.exists(parameters, "totalVariance")) {
          try {
            total = std::max(total, std::stod(r.text(parameters, "totalVariance")));
          } catch(const std::logic_error&) {
            r.fail("totalVariance is not a number");
          }
        }
        if(r.exists(parameters, "withScale")) with_scale = r.text(parameters, "withScale") == "1";
      }
      if(r.exists(builder, "dataInfo")) {
        H5_handle data(H5Gopen2(builder, "dataInfo", H5P_DEFAULT), H5Gclose);
        for(Eigen::Index i = 0; i < scores.cols(); ++i) {
          const std::string key = "URI-" + std::to_string(i);
          if(!r.exists(data, key.c_str())) break;
          names.push_back(r.text(data, key.c_str()));
        }
      }
    }
  }
  try {
    Statistical_shape_model model(mean, basis, variances, total, std::move(triangles), std::move(scores), with_scale);
    if(names.size() == model.number_of_training_shapes() && !names.empty()) model.set_training_names(std::move(names));
    return model;
  } catch(const Invalid_argument& e) {
    r.fail(e.what());
  }
}

} // namespace shapecorr

#endif
