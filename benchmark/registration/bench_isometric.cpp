// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Automatic near-isometric correspondence (thesis chapter 5) on the TOSCA pair cat0 -> cat1
// (5000 vertices each); without the data the generated creature and its bent copy stand in.
// Reported, each against a reference measured in the same run:
//  - the coarse program with 10 features (the problem `trim()` builds): the dedicated branch and
//    bound against GLPK through CGAL's MixedIntegerProgramTraits (goal: both proven optimal, the
//    branch and bound >= 10x faster);
//  - the whole pipeline (three starts, three levels, the dense map) against one all-pairs
//    geodesic computation (fast marching) of both shapes.
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/GLPK_mixed_integer_program_traits.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <iostream>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

struct Pair {
  Mesh source, target;
  shapecorr::Coarse_matching_problem problem;
  Pair() {
    const std::string dir = std::string(SHAPECORR_BENCH_DATA_DIR) + "/tosca5k/meshes/";
    try {
      shapecorr::read_triangle_mesh(dir + "cat0.off", source);
      shapecorr::read_triangle_mesh(dir + "cat1.off", target);
    } catch(const std::exception& e) {
      std::cerr << "TOSCA unavailable (" << e.what() << "): the creature and its bent copy stand in\n";
      source.clear();
      target.clear();
      shapecorr::make_creature(source, 5);
      shapecorr::make_creature(target, 5, 40.0);
    }
    shapecorr::Isometric_correspondence<Mesh> method(source, target);
    method.sample_features();
    method.trim();
    problem = method.coarse_problem();
  }
};

const Pair& pair() {
  static const Pair p;
  return p;
}

void BM_CoarseProgram_BranchAndBound(benchmark::State& state) {
  const Pair& p = pair();
  shapecorr::Feature_matching r;
  for(auto _ : state) r = shapecorr::solve_coarse_matching_branch_and_bound(p.problem);
  state.counters["features"] = static_cast<double>(p.problem.source_distances.rows());
  state.counters["candidates"] = static_cast<double>(p.problem.candidates.size());
  state.counters["objective"] = r.objective;
  state.counters["optimal"] = r.optimal ? 1 : 0;
  state.counters["nodes"] = static_cast<double>(r.nodes);
}
BENCHMARK(BM_CoarseProgram_BranchAndBound)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Reference_CoarseProgram_Glpk(benchmark::State& state) {
  const Pair& p = pair();
  shapecorr::Feature_matching r;
  for(auto _ : state) {
    CGAL::GLPK_mixed_integer_program_traits<double> solver;
    r = shapecorr::solve_coarse_matching_mip(p.problem, solver);
  }
  state.counters["objective"] = r.objective;
  state.counters["optimal"] = r.optimal ? 1 : 0;
}
BENCHMARK(BM_Reference_CoarseProgram_Glpk)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Pipeline(benchmark::State& state) {
  const Pair& p = pair();
  for(auto _ : state) {
    shapecorr::Isometric_correspondence<Mesh> method(p.source, p.target);
    benchmark::DoNotOptimize(method.run().matches.size());
  }
  state.counters["vertices"] = static_cast<double>(p.source.number_of_vertices());
}
BENCHMARK(BM_Pipeline)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_Reference_AllPairsGeodesics_BothShapes(benchmark::State& state) {
  const Pair& p = pair();
  for(auto _ : state) {
    benchmark::DoNotOptimize(shapecorr::compute_all_pairs_geodesic_distances(p.source));
    benchmark::DoNotOptimize(shapecorr::compute_all_pairs_geodesic_distances(p.target));
  }
}
BENCHMARK(BM_Reference_AllPairsGeodesics_BothShapes)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
