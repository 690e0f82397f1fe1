// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// NICPS on a vertebra (the thesis's setting): the template ../shared/data/vertebrae/ref_20.ply
// (5000 vertices) onto the raw vertebra sub-verse010 (about 20k vertices), pre-aligned by their
// 10 landmarks; without the data a sphere onto an ellipsoid stands in. Reported:
//  - the time per NICPS iteration and, measured inside the same iterations, its numeric sparse
//    Cholesky factorization (the floor: every iteration needs one) and its correspondence search;
//    the ratio iteration / factorization is the figure (goal 2x);
//  - iterations, total time and the process's peak resident memory;
//  - the rigid alignment (landmarks + ICP) before it, for scale.
#include "../bench_mesh.h"

#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <fstream>
#include <iostream>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

std::vector<K::Point_3> read_landmarks(const std::string& path) {
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  std::vector<K::Point_3> out;
  for(const auto& e : j) out.emplace_back(e["coordinates"][0].get<double>(), e["coordinates"][1].get<double>(), e["coordinates"][2].get<double>());
  return out;
}

struct Fixture {
  Mesh tmpl, target;
  std::vector<K::Point_3> tmpl_landmarks, target_landmarks;
  bool real = false;
  Fixture() {
    const std::string dir = std::string(SHAPECORR_BENCH_DATA_DIR) + "/vertebrae/";
    try {
      shapecorr::read_triangle_mesh(dir + "ref_20.ply", tmpl);
      shapecorr::read_triangle_mesh(dir + "raw/sub-verse010_segment_20.ply", target);
      tmpl_landmarks = read_landmarks(dir + "ref_20.json");
      target_landmarks = read_landmarks(dir + "raw/sub-verse010_segment_20.json");
      real = true;
    } catch(const std::exception& e) {
      std::cerr << "vertebrae unavailable (" << e.what() << "): a sphere onto an ellipsoid stands in\n";
      tmpl.clear();
      target.clear();
      shapecorr::make_icosphere(tmpl, 4);
      shapecorr::make_icosphere(target, 5);
      for(auto v : vertices(target)) target.point(v) = K::Point_3(1.3 * target.point(v).x(), 0.9 * target.point(v).y(), 0.75 * target.point(v).z());
    }
    namespace SP = shapecorr::parameters;
    const auto r = real ? shapecorr::align_rigidly(tmpl, target, SP::rigid_initialization(shapecorr::Rigid_initialization::LANDMARKS).landmark_points(tmpl_landmarks),
                                                   SP::landmark_points(target_landmarks))
                        : shapecorr::align_rigidly(tmpl, target);
    shapecorr::apply_transform(tmpl, r.transform);
  }
};
Fixture& fixture() {
  static Fixture f;
  return f;
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0; // Linux: kilobytes
}

void BM_Nicps_Vertebra(benchmark::State& state) {
  Fixture& f = fixture();
  shapecorr::Nicps_report r;
  for(auto _ : state) {
    auto out = get(CGAL::dynamic_vertex_property_t<K::Point_3>(), f.tmpl);
    r = shapecorr::nicps(f.tmpl, f.target, out);
    benchmark::DoNotOptimize(r.final_rms);
  }
  double it = 0, fact = 0, search = 0;
  for(const auto& rec : r.iterations) it += rec.seconds, fact += rec.factorization_seconds, search += rec.search_seconds;
  const double n = static_cast<double>(r.iterations.size());
  state.counters["template_vertices"] = static_cast<double>(f.tmpl.number_of_vertices());
  state.counters["target_vertices"] = static_cast<double>(f.target.number_of_vertices());
  state.counters["iterations"] = n;
  state.counters["iteration_ms"] = 1e3 * it / n;
  state.counters["factorization_ms"] = 1e3 * fact / n;
  state.counters["search_ms"] = 1e3 * search / n;
  state.counters["iteration_over_factorization"] = it / fact;
  state.counters["final_rms"] = r.final_rms;
  state.counters["peak_rss_mb"] = peak_rss_mb();
}
BENCHMARK(BM_Nicps_Vertebra)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_RigidAlignment_Vertebra(benchmark::State& state) {
  Fixture& f = fixture();
  namespace SP = shapecorr::parameters;
  for(auto _ : state) {
    const auto r = shapecorr::align_rigidly(f.tmpl, f.target, SP::rigid_initialization(shapecorr::Rigid_initialization::NONE));
    benchmark::DoNotOptimize(r.final_rms);
  }
}
BENCHMARK(BM_RigidAlignment_Vertebra)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
