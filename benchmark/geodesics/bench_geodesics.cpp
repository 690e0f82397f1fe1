// Geodesics benchmarks on the TOSCA wolf (../shared/data/tosca5k/meshes/wolf0.off, 4344 vertices;
// SHAPECORR_BENCH_MESH overrides), each against a reference measured in the same run:
//  - all-pairs distances (heat method, fast marching) vs looping CGAL's Heat_method_3 over sources;
//  - radius-limited distances (r = 0.15 D) per source, local agd for every vertex;
//  - exact single source (CGAL Surface_mesh_shortest_path) vs one heat query.
// Accuracy against exact distances on 50 furthest-point sources is reported as counters
// (mean_abs_err_pct_D). Run through benchmark/run, which writes JSON and the ratios.
#include "../bench_mesh.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/sampling.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>
#include <memory>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
namespace SP = shapecorr::parameters;

struct Fixture {
  Mesh mesh;
  std::string name;
  double D = 0;                            // exact geodesic diameter (sweeps)
  std::vector<std::size_t> sources50;      // 50 furthest-point sources
  std::vector<Eigen::VectorXd> exact50;    // exact distances from them
  Fixture() {
    name = bench::load_mesh<Mesh>(mesh, "tosca5k/meshes/wolf0.off", [](Mesh& m) { shapecorr::make_icosphere(m, 5); }, "icosphere(5)");
    shapecorr::Exact_geodesics<Mesh> exact(mesh);
    D = shapecorr::geodesic_diameter(mesh, SP::geodesic_engine(&exact).number_of_iterations(4));
    std::vector<vertex_descriptor> s;
    shapecorr::furthest_point_sampling(mesh, 50, std::back_inserter(s), SP::random_seed(1u).geodesic_engine(&exact));
    std::vector<Eigen::VectorXd> ex(s.size());
    for(vertex_descriptor v : s) sources50.push_back(v.idx());
    shapecorr::parallel_for(s.size(), 0, [&](std::size_t i, unsigned) { ex[i] = exact.distances_from(sources50[i]); });
    exact50 = std::move(ex);
  }
  template <typename Row>
  double mean_error_pct(Row&& row_of_source) const {
    double err = 0, count = 0;
    for(std::size_t k = 0; k < sources50.size(); ++k) {
      const Eigen::VectorXd d = row_of_source(sources50[k]);
      err += (d - exact50[k]).cwiseAbs().sum();
      count += static_cast<double>(d.size());
    }
    return 100.0 * err / count / D;
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void set_counters(benchmark::State& state, std::size_t n) {
  state.counters["vertices"] = static_cast<double>(n);
  state.SetComplexityN(static_cast<benchmark::IterationCount>(n));
}

void BM_AllPairs_Heat(benchmark::State& state) {
  Fixture& f = fixture();
  const bool idt = state.range(0) != 0;
  shapecorr::Geodesic_distance_matrix M;
  for(auto _ : state) {
    shapecorr::Heat_method_geodesics<Mesh> heat(f.mesh, SP::use_intrinsic_delaunay(idt));
    M = shapecorr::compute_all_pairs_geodesic_distances(f.mesh, SP::geodesic_engine(&heat));
    benchmark::DoNotOptimize(M.matrix().data());
  }
  set_counters(state, f.mesh.number_of_vertices());
  state.counters["mean_abs_err_pct_D"] = f.mean_error_pct([&](std::size_t s) { return Eigen::VectorXd(M.row(s).transpose().cast<double>()); });
  state.counters["memory_MB"] = M.memory_bytes() / 1e6;
}
BENCHMARK(BM_AllPairs_Heat)->Arg(0)->Arg(1)->ArgName("intrinsic_delaunay")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

void BM_AllPairs_FastMarching(benchmark::State& state) {
  Fixture& f = fixture();
  shapecorr::Geodesic_distance_matrix M;
  for(auto _ : state) {
    M = shapecorr::compute_all_pairs_geodesic_distances(f.mesh, SP::geodesic_method(shapecorr::Geodesic_method::FAST_MARCHING));
    benchmark::DoNotOptimize(M.matrix().data());
  }
  set_counters(state, f.mesh.number_of_vertices());
  state.counters["mean_abs_err_pct_D"] = f.mean_error_pct([&](std::size_t s) { return Eigen::VectorXd(M.row(s).transpose().cast<double>()); });
}
BENCHMARK(BM_AllPairs_FastMarching)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// Reference: CGAL's heat method, precomputed once, one source at a time. Timed on 200 sources and
// reported per source; benchmark/run scales it to all n sources (2 threads, one CGAL object each).
void BM_Reference_CGAL_HeatMethod_PerSource(benchmark::State& state) {
  Fixture& f = fixture();
  CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh> hm(f.mesh);
  auto dist = f.mesh.add_property_map<vertex_descriptor, double>("v:bench_cgal", 0).first;
  const std::size_t sources = 200, n = f.mesh.number_of_vertices();
  for(auto _ : state) {
    for(std::size_t s = 0; s < sources; ++s) {
      hm.clear_sources();
      hm.add_source(vertex_descriptor(static_cast<Mesh::size_type>((s * 97) % n)));
      hm.estimate_geodesic_distances(dist);
    }
  }
  state.counters["sources"] = sources;
  state.counters["mean_abs_err_pct_D"] = f.mean_error_pct([&](std::size_t s) {
    hm.clear_sources();
    hm.add_source(vertex_descriptor(static_cast<Mesh::size_type>(s)));
    hm.estimate_geodesic_distances(dist);
    Eigen::VectorXd d(static_cast<Eigen::Index>(n));
    for(vertex_descriptor v : vertices(f.mesh)) d[v.idx()] = dist[v];
    return d;
  });
  f.mesh.remove_property_map(dist);
  set_counters(state, n);
}
BENCHMARK(BM_Reference_CGAL_HeatMethod_PerSource)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

void BM_RadiusLimited_PerSource(benchmark::State& state) {
  Fixture& f = fixture();
  shapecorr::Fast_marching_geodesics<Mesh> fmm(f.mesh);
  const double R = 0.15 * f.D;
  shapecorr::Fast_marching_geodesics<Mesh>::Ball ball;
  shapecorr::Fast_marching_geodesics<Mesh>::Workspace ws;
  const std::size_t n = f.mesh.number_of_vertices();
  std::size_t s = 0, touched = 0, queries = 0;
  for(auto _ : state) {
    fmm.distances_within(s, R, ball, ws);
    touched += ball.size();
    ++queries;
    s = (s + 97) % n;
  }
  state.counters["mean_ball_vertices"] = static_cast<double>(touched) / static_cast<double>(queries);
  set_counters(state, n);
}
BENCHMARK(BM_RadiusLimited_PerSource)->Unit(benchmark::kMicrosecond);

void BM_LocalAgd_AllVertices(benchmark::State& state) {
  Fixture& f = fixture();
  auto agd = f.mesh.add_property_map<vertex_descriptor, double>("v:bench_agd", 0).first;
  for(auto _ : state) shapecorr::compute_local_average_geodesic_distance(f.mesh, 0.15 * f.D, agd);
  f.mesh.remove_property_map(agd);
  set_counters(state, f.mesh.number_of_vertices());
}
BENCHMARK(BM_LocalAgd_AllVertices)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

void BM_Exact_SingleSource(benchmark::State& state) {
  Fixture& f = fixture();
  shapecorr::Exact_geodesics<Mesh> exact(f.mesh);
  std::size_t s = 0;
  for(auto _ : state) {
    benchmark::DoNotOptimize(exact.distances_from(s).data());
    s = (s + 97) % f.mesh.number_of_vertices();
  }
  set_counters(state, f.mesh.number_of_vertices());
}
BENCHMARK(BM_Exact_SingleSource)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_Heat_SingleSource(benchmark::State& state) {
  Fixture& f = fixture();
  shapecorr::Heat_method_geodesics<Mesh> heat(f.mesh);
  heat.distances_from(0); // factor outside the timing
  std::size_t s = 0;
  for(auto _ : state) {
    benchmark::DoNotOptimize(heat.distances_from(s).data());
    s = (s + 97) % f.mesh.number_of_vertices();
  }
  set_counters(state, f.mesh.number_of_vertices());
}
BENCHMARK(BM_Heat_SingleSource)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
