// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Building a statistical shape model of 14 fitted femurs (thesis chapter 6): the PCA through the
// N x N Gram matrix (the library's route) against the thin dense SVD of the same 3n x N data
// matrix (Eigen's BDCSVD), in the same run, and the whole build (Procrustes alignment + PCA).
// Reported: the time ratio (goal: the Gram route >= 10x faster) and the largest relative
// difference of the variances (goal: <= 1e-9).
// The shapes: the fits of the femur workflow (results/femurs/fits/*.ply, or the folder in
// $SHAPECORR_BENCH_FITS); without them, femur_01 of the data under 14 smooth random deformations
// (the same size); without the data, a sphere of 40962 vertices under them.
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/shape_model.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

Eigen::Matrix3Xd points_of(const Mesh& m) {
  Eigen::Matrix3Xd X(3, static_cast<Eigen::Index>(m.number_of_vertices()));
  for(auto v : m.vertices()) X.col(static_cast<Eigen::Index>(v.idx())) << m.point(v).x(), m.point(v).y(), m.point(v).z();
  return X;
}

struct Data {
  std::vector<Eigen::Matrix3Xd> shapes;
  std::vector<std::array<std::size_t, 3>> triangles;
  Eigen::MatrixXd centered; // the aligned shapes minus their mean, 3n x N
  std::string source;
  Data() {
    const char* env = std::getenv("SHAPECORR_BENCH_FITS");
    const std::filesystem::path fits = env ? env : std::filesystem::path(SHAPECORR_BENCH_SOURCE_DIR) / "results/femurs/fits";
    std::vector<std::filesystem::path> files;
    if(std::filesystem::is_directory(fits))
      for(const auto& e : std::filesystem::directory_iterator(fits))
        if(e.path().extension() == ".ply") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    Mesh first;
    if(files.size() >= 2) {
      for(const auto& f : files) {
        Mesh m;
        shapecorr::read_triangle_mesh(f.string(), m);
        if(shapes.empty()) first = m;
        shapes.push_back(points_of(m));
      }
      source = std::to_string(files.size()) + " fits in " + fits.string();
    } else {
      try {
        shapecorr::read_triangle_mesh(std::string(SHAPECORR_BENCH_DATA_DIR) + "/femurs/femur_01.ply", first);
        source = "femur_01 under 14 smooth random deformations";
      } catch(const std::exception&) {
        first.clear();
        shapecorr::make_icosphere(first, 6);
        source = "a sphere of 40962 vertices under 14 smooth random deformations";
      }
      const Eigen::Matrix3Xd X = points_of(first);
      const double size = (X.rowwise().maxCoeff() - X.rowwise().minCoeff()).norm();
      std::mt19937 rng(1);
      std::normal_distribution<double> g;
      for(int s = 0; s < 14; ++s) {
        Eigen::Matrix3Xd Y = X;
        for(int bump = 0; bump < 6; ++bump) { // Gaussian bumps of random centre, width and direction
          const Eigen::Vector3d c = X.col(static_cast<Eigen::Index>(rng() % X.cols())), d(g(rng), g(rng), g(rng));
          const double width = size * (0.1 + 0.2 * std::abs(g(rng)));
          for(Eigen::Index i = 0; i < X.cols(); ++i) Y.col(i) += 0.02 * size * d * std::exp(-(X.col(i) - c).squaredNorm() / (width * width));
        }
        shapes.push_back(Y);
      }
    }
    for(auto f : first.faces()) {
      std::array<std::size_t, 3> t;
      int k = 0;
      for(auto v : vertices_around_face(first.halfedge(f), first)) t[static_cast<std::size_t>(k++)] = v.idx();
      triangles.push_back(t);
    }
    const shapecorr::Procrustes_alignment gpa = shapecorr::generalized_procrustes_alignment(shapes, false);
    const Eigen::Index n3 = 3 * gpa.mean.cols(), N = static_cast<Eigen::Index>(shapes.size());
    centered.resize(n3, N);
    for(Eigen::Index i = 0; i < N; ++i) centered.col(i) = Eigen::Map<const Eigen::VectorXd>(gpa.aligned[static_cast<std::size_t>(i)].data(), n3);
    centered.colwise() -= Eigen::VectorXd(centered.rowwise().mean());
    std::cerr << "shapes: " << source << " (" << shapes[0].cols() << " vertices each)\n";
  }
};

const Data& data() {
  static const Data d;
  return d;
}

// the largest relative difference of the two routes' variances (computed once)
double variance_agreement() {
  static const double worst = [] {
    const auto a = shapecorr::principal_components(data().centered, shapecorr::Pca_method::GRAM_MATRIX);
    const auto b = shapecorr::principal_components(data().centered, shapecorr::Pca_method::DENSE_SVD);
    if(a.variances.size() != b.variances.size()) return 1.0;
    return ((a.variances - b.variances).cwiseAbs().array() / b.variances.array()).maxCoeff();
  }();
  return worst;
}

void BM_Pca_GramMatrix(benchmark::State& state) {
  const Data& d = data();
  for(auto _ : state) benchmark::DoNotOptimize(shapecorr::principal_components(d.centered, shapecorr::Pca_method::GRAM_MATRIX).variances.sum());
  state.counters["vertices"] = static_cast<double>(d.shapes[0].cols());
  state.counters["shapes"] = static_cast<double>(d.shapes.size());
  state.counters["variance_rel_diff"] = variance_agreement();
}
BENCHMARK(BM_Pca_GramMatrix)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Reference_Pca_DenseSvd(benchmark::State& state) {
  const Data& d = data();
  for(auto _ : state) benchmark::DoNotOptimize(shapecorr::principal_components(d.centered, shapecorr::Pca_method::DENSE_SVD).variances.sum());
}
BENCHMARK(BM_Reference_Pca_DenseSvd)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_BuildModel(benchmark::State& state) {
  const Data& d = data();
  for(auto _ : state) benchmark::DoNotOptimize(shapecorr::build_statistical_shape_model(d.shapes, d.triangles).number_of_modes());
}
BENCHMARK(BM_BuildModel)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
