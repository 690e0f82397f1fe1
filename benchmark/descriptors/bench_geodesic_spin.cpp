// Geodesic Spin Contour benchmarks on the TOSCA wolf (../shared/data/tosca5k/meshes/wolf0.off, 4344
// vertices; SHAPECORR_BENCH_MESH overrides), L = 0.4 D, r = 0.15 D (the thesis's wolf parameters),
// each against a reference measured in the same run:
//  - one GSC once the distances exist (the geodesic ball of the point precomputed) vs the
//    geodesic spin image from the same ball;
//  - the GSCs of all vertices from their precomputed balls on every core (throughput per contour);
//  - the GSC of every vertex including every geodesic computation (diameter, local agd, one
//    radius-limited march per vertex) vs all-pairs fast-marching distances (what the thesis computed
//    first, in about 15 minutes, before any descriptor);
//  - the core's clock (a chain of dependent additions), to state the one-contour time in cycles.
// Run through benchmark/run, which writes JSON and the ratios.
#include "../bench_clock.h"
#include "../bench_mesh.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <numeric>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SP = shapecorr::parameters;
typedef shapecorr::Geodesic_spin_descriptors<Mesh> GSD;

struct Fixture {
  Mesh mesh;
  std::string name;
  std::unique_ptr<GSD> gsd;
  std::vector<GSD::Ball> balls; // of 64 vertices spread over the mesh
  Fixture() {
    name = bench::load_mesh<Mesh>(mesh, "tosca5k/meshes/wolf0.off", [](Mesh& m) { shapecorr::make_icosphere(m, 5); }, "icosphere(5)");
    gsd.reset(new GSD(mesh, SP::support_fraction(0.4).agd_radius_fraction(0.15)));
    const std::size_t n = gsd->number_of_vertices();
    for(std::size_t k = 0; k < 64; ++k) {
      balls.emplace_back();
      gsd->support_ball(k * n / 64, balls.back());
    }
  }
};
Fixture& fixture() {
  static Fixture f;
  return f;
}

void BM_GSC_FromDistances(benchmark::State& state) {
  Fixture& fx = fixture();
  GSD::Workspace ws(*fx.gsd);
  std::size_t i = 0, points = 0, count = 0;
  for(auto _ : state) {
    const shapecorr::Spin_contour c = fx.gsd->geodesic_spin_contour(fx.balls[i++ % 64], ws);
    points += c.size();
    ++count;
    benchmark::DoNotOptimize(c.size());
  }
  state.counters["vertices"] = static_cast<double>(fx.gsd->number_of_vertices());
  state.counters["mean_points"] = static_cast<double>(points) / static_cast<double>(count);
  state.counters["mean_ball"] = [&] {
    double s = 0;
    for(const auto& b : fx.balls) s += static_cast<double>(b.size());
    return s / 64.0;
  }();
}
BENCHMARK(BM_GSC_FromDistances)->Unit(benchmark::kMicrosecond);

void BM_Reference_GeodesicSpinImage_FromDistances(benchmark::State& state) {
  Fixture& fx = fixture();
  std::size_t i = 0;
  for(auto _ : state) benchmark::DoNotOptimize(fx.gsd->geodesic_spin_image(fx.balls[i++ % 64]).values().data());
}
BENCHMARK(BM_Reference_GeodesicSpinImage_FromDistances)->Unit(benchmark::kMicrosecond);

// The clock the core ran at, in the same run (interleave the repetitions with
// --benchmark_enable_random_interleaving=true to follow the machine's swings).
BENCHMARK(bench::BM_Reference_ClockCycles)->Name("BM_Reference_ClockCycles")->Unit(benchmark::kMicrosecond);

// Throughput once the distances exist: the GSCs of all vertices from their precomputed balls, on
// every core (each thread with its own workspace); the counter is the wall time per contour.
void BM_GSC_AllVertices_FromDistances(benchmark::State& state) {
  Fixture& fx = fixture();
  const std::size_t n = fx.gsd->number_of_vertices();
  const unsigned threads = shapecorr::resolve_thread_count(0);
  std::vector<GSD::Workspace> ws;
  for(unsigned t = 0; t < threads; ++t) ws.emplace_back(*fx.gsd);
  static std::vector<GSD::Ball> all; // every vertex's ball (about 150 MB on the wolf)
  if(all.empty()) {
    all.resize(n);
    shapecorr::parallel_for(n, threads, [&](std::size_t i, unsigned tid) { fx.gsd->support_ball(i, all[i], ws[tid]); });
  }
  std::vector<std::size_t> points(n);
  for(auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    shapecorr::parallel_for(n, threads, [&](std::size_t i, unsigned tid) { points[i] = fx.gsd->geodesic_spin_contour(all[i], ws[tid]).size(); });
    const auto t1 = std::chrono::steady_clock::now();
    state.SetIterationTime(std::chrono::duration<double>(t1 - t0).count());
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["vertices"] = static_cast<double>(n);
  state.counters["threads"] = static_cast<double>(threads);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_GSC_AllVertices_FromDistances)->Unit(benchmark::kMillisecond)->Iterations(3)->UseManualTime();

// One radius-limited march to L + the longest edge (the distances one GSC needs).
void BM_GSC_SupportBall(benchmark::State& state) {
  Fixture& fx = fixture();
  GSD::Workspace ws(*fx.gsd);
  GSD::Ball ball;
  std::size_t i = 0;
  const std::size_t n = fx.gsd->number_of_vertices();
  for(auto _ : state) {
    fx.gsd->support_ball((i++ * 67) % n, ball, ws);
    benchmark::DoNotOptimize(ball.data());
  }
}
BENCHMARK(BM_GSC_SupportBall)->Unit(benchmark::kMicrosecond);

// Everything for every vertex: the diameter, the local agd, one march and one contour per vertex.
void BM_GSC_AllVertices(benchmark::State& state) {
  Fixture& fx = fixture();
  for(auto _ : state) {
    const GSD g(fx.mesh, SP::support_fraction(0.4).agd_radius_fraction(0.15));
    std::vector<std::size_t> all(g.number_of_vertices());
    std::iota(all.begin(), all.end(), std::size_t(0));
    benchmark::DoNotOptimize(g.geodesic_spin_contours(all).data());
  }
  state.counters["vertices"] = static_cast<double>(num_vertices(fx.mesh));
}
BENCHMARK(BM_GSC_AllVertices)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void BM_Reference_AllPairsFastMarching(benchmark::State& state) {
  Fixture& fx = fixture();
  for(auto _ : state)
    benchmark::DoNotOptimize(shapecorr::compute_all_pairs_geodesic_distances(fx.mesh, SP::geodesic_method(shapecorr::Geodesic_method::FAST_MARCHING)).diameter());
}
BENCHMARK(BM_Reference_AllPairsFastMarching)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
