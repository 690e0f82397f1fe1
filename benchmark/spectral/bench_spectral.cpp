// Spectral benchmarks on the TOSCA wolf (../shared/data/tosca5k/meshes/wolf0.off, 4344 vertices;
// SHAPECORR_BENCH_MESH overrides; a generated ellipsoid stands in without data):
//  - 300 Laplace-Beltrami eigenpairs by spectrum slicing (the default) against one Spectra
//    shift-invert run for all 300 pairs (the plain use of Spectra), same operators, same run;
//  - HKS, WKS (100 scales) and SI-HKS for every vertex from the basis (descriptor time only);
//  - the whole job: eigenbasis + HKS + WKS.
#include "../bench_mesh.h"

#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/spectral.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>

namespace {
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

struct Fixture {
  Mesh mesh;
  shapecorr::Laplace_operators op;
  shapecorr::Laplace_beltrami_eigenbasis basis;
  Fixture() {
    bench::load_mesh<Mesh>(mesh, "tosca5k/meshes/wolf0.off", [](Mesh& m) { shapecorr::make_icosphere(m, 5); }, "icosphere(5)");
    op = shapecorr::laplace_operators(mesh);
    basis = shapecorr::compute_laplace_beltrami_eigenbasis(mesh, 300);
  }
};
Fixture& fixture() {
  static Fixture f;
  return f;
}

void solve(benchmark::State& state, const shapecorr::Spectra_eigensolver<>& s) {
  Fixture& f = fixture();
  Eigen::VectorXd v;
  Eigen::MatrixXd V;
  for(auto _ : state) {
    s.solve(f.op.L, f.op.mass, 300, v, V);
    benchmark::DoNotOptimize(V.data());
  }
  state.counters["vertices"] = static_cast<double>(f.mesh.number_of_vertices());
  state.counters["max_abs_eigenvalue_diff"] = (v - f.basis.eigenvalues()).cwiseAbs().maxCoeff();
}

void BM_Eigenbasis300_Sliced(benchmark::State& state) { solve(state, shapecorr::Spectra_eigensolver<>()); }
BENCHMARK(BM_Eigenbasis300_Sliced)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Reference_Eigenbasis300_OneSpectraRun(benchmark::State& state) {
  shapecorr::Spectra_eigensolver<> s;
  s.slice_size = 100000; // one shift-invert run for all 300 + margin pairs
  solve(state, s);
}
BENCHMARK(BM_Reference_Eigenbasis300_OneSpectraRun)->Unit(benchmark::kMillisecond)->Iterations(3);

template <typename F>
void descriptor(benchmark::State& state, F&& f) {
  Fixture& fx = fixture();
  for(auto _ : state) benchmark::DoNotOptimize(f(fx.basis).data());
  state.counters["vertices"] = static_cast<double>(fx.mesh.number_of_vertices());
  state.counters["seconds_per_vertex"] = benchmark::Counter(static_cast<double>(fx.mesh.number_of_vertices()),
                                                       benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
void BM_HKS_AllVertices(benchmark::State& state) { descriptor(state, [](const auto& b) { return shapecorr::heat_kernel_signature_matrix(b); }); }
void BM_WKS_AllVertices(benchmark::State& state) { descriptor(state, [](const auto& b) { return shapecorr::wave_kernel_signature_matrix(b); }); }
void BM_SIHKS_AllVertices(benchmark::State& state) {
  descriptor(state, [](const auto& b) { return shapecorr::scale_invariant_heat_kernel_signature_matrix(b); });
}
BENCHMARK(BM_HKS_AllVertices)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WKS_AllVertices)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SIHKS_AllVertices)->Unit(benchmark::kMillisecond);

void BM_Total_EigenbasisHksWks(benchmark::State& state) {
  Fixture& f = fixture();
  for(auto _ : state) {
    const auto b = shapecorr::compute_laplace_beltrami_eigenbasis(f.mesh, 300);
    benchmark::DoNotOptimize(shapecorr::heat_kernel_signature_matrix(b).data());
    benchmark::DoNotOptimize(shapecorr::wave_kernel_signature_matrix(b).data());
  }
  state.counters["vertices"] = static_cast<double>(f.mesh.number_of_vertices());
}
BENCHMARK(BM_Total_EigenbasisHksWks)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace

BENCHMARK_MAIN();
