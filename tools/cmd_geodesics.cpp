// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr geodesics, sample and agd: distances, furthest point samples, average geodesic distance.
#include "cli_common.h"

#include <shapecorr/geodesics.h>
#include <shapecorr/sampling.h>

#include <chrono>

namespace cli {
namespace {

// The heat method's intrinsic Delaunay option (Heat_method_geodesics, use_intrinsic_delaunay).
Option intrinsic_delaunay_option() {
  return {"intrinsic-delaunay", "",
          "heat method on the intrinsic Delaunay triangulation: more accurate on poor triangles "
          "(mean error about 0.8-1.0% of the diameter instead of 2% on TOSCA, doc/geodesics.md)"};
}

int run_geodesics(const Args& a) {
  Mesh m = read_mesh(a);
  const std::vector<std::size_t> ids = parse_ids(a.require("source"), m.number_of_vertices());
  const std::string output = a.require("output");
  const auto method = shapecorr::geodesic_method_from_string(a.get("method", "heat"));
  const bool intrinsic = a.has("intrinsic-delaunay");
  if(intrinsic && method != shapecorr::Geodesic_method::HEAT)
    throw Usage_error("geodesics: --intrinsic-delaunay applies to the heat method (--method heat)");
  std::vector<vertex_descriptor> sources;
  for(std::size_t i : ids) sources.push_back(vertex_descriptor(static_cast<Mesh::size_type>(i)));
  auto dist = m.add_property_map<vertex_descriptor, double>("v:dist", 0.0).first;
  const auto t0 = std::chrono::steady_clock::now();
  shapecorr::compute_geodesic_distances(m, sources, dist, shapecorr::parameters::geodesic_method(method).use_intrinsic_delaunay(intrinsic));
  const double secs = seconds_since(t0);
  std::vector<double> values(m.number_of_vertices());
  double dmax = 0;
  std::size_t unreachable = 0;
  for(vertex_descriptor v : vertices(m)) {
    values[v.idx()] = dist[v];
    if(std::isfinite(dist[v])) dmax = std::max(dmax, dist[v]);
    else ++unreachable;
  }
  write_values(output, m, values, ids);
  if(verbose(a)) {
    std::cerr << "geodesics: " << ids.size() << " source(s), method " << a.get("method", "heat") << (intrinsic ? " (intrinsic Delaunay)" : "") << ", max distance " << dmax << ", "
              << secs << " s -> " << output << "\n";
    if(unreachable)
      std::cerr << "note: " << unreachable << " vertices lie in components without a source: no distance (an empty line in .csv, grey in .ply)\n";
  }
  return 0;
}

int run_sample(const Args& a) {
  const Mesh m = read_mesh(a);
  const std::size_t count = to_count(a.require("count"), "--count", 1, max_count);
  const unsigned seed = static_cast<unsigned>(to_count(a.get("seed", "0"), "--seed", 0, max_seed));
  const std::string metric = a.get("metric", "geodesic");
  if(metric != "geodesic" && metric != "euclidean") throw Usage_error("sample: --metric must be geodesic or euclidean");
  const bool intrinsic = a.has("intrinsic-delaunay");
  if(intrinsic && metric != "geodesic") throw Usage_error("sample: --intrinsic-delaunay applies to the geodesic metric");
  std::vector<vertex_descriptor> samples;
  shapecorr::furthest_point_sampling(m, count, std::back_inserter(samples),
                                     shapecorr::parameters::distance_metric(metric == "geodesic" ? shapecorr::Distance_metric::GEODESIC
                                                                                                 : shapecorr::Distance_metric::EUCLIDEAN)
                                         .random_seed(seed)
                                         .use_intrinsic_delaunay(intrinsic));
  std::ostringstream o;
  for(vertex_descriptor v : samples) o << v.idx() << "\n";
  if(a.has("output")) {
    std::ofstream out = open_output(a.get("output"));
    out << o.str();
  } else {
    std::cout << o.str();
  }
  return 0;
}

int run_agd(const Args& a) {
  Mesh m = read_mesh(a);
  const std::string output = a.require("output");
  auto agd = m.add_property_map<vertex_descriptor, double>("v:agd", 0.0).first;
  const auto t0 = std::chrono::steady_clock::now();
  std::string what;
  const bool intrinsic = a.has("intrinsic-delaunay");
  if(a.has("radius")) {
    if(a.has("sources")) throw Usage_error("agd: --sources applies to the global agd, not with --radius");
    if(intrinsic) throw Usage_error("agd: --intrinsic-delaunay applies to the global agd (heat method), not with --radius (fast marching)");
    const double fraction = to_double(a.get("radius"), "--radius", 0, 2, true);
    const double D = shapecorr::geodesic_diameter(m);
    shapecorr::compute_local_average_geodesic_distance(m, fraction * D, agd);
    what = "local agd, r = " + a.get("radius") + " D (D = " + std::to_string(D) + ")";
  } else {
    const std::size_t k = to_count(a.get("sources", "100"), "--sources", 0, max_count);
    shapecorr::compute_average_geodesic_distance(m, agd, shapecorr::parameters::number_of_sources(k).use_intrinsic_delaunay(intrinsic));
    what = "global agd from " + (k == 0 ? std::string("all") : std::to_string(k)) + " sources";
  }
  const double secs = seconds_since(t0);
  std::vector<double> values(m.number_of_vertices());
  for(vertex_descriptor v : vertices(m)) values[v.idx()] = agd[v];
  const std::size_t undefined = write_values(output, m, values);
  if(verbose(a)) {
    std::cerr << "agd: " << what << ", " << secs << " s -> " << output << "\n";
    if(undefined) std::cerr << "note: " << undefined << " vertices have no average geodesic distance (an empty line in .csv, grey in .ply)\n";
  }
  return 0;
}

} // namespace

const Command& geodesics_command() {
  static const Command c{"geodesics", "geodesics MESH --source V[,V...] [--method heat|exact|fmm] [--intrinsic-delaunay] --output FILE",
                         "Geodesic distance of every vertex to the nearest source (0-based vertex ids): heat method "
                         "(default, fast), exact (CGAL's shortest paths) or fast marching. FILE.csv: one distance per "
                         "line in vertex order; FILE.ply: the mesh coloured by distance, sources marked. Vertices of "
                         "components without a source have no distance: an empty line in FILE.csv, grey in FILE.ply, "
                         "counted in a note on stderr.",
                         with_mesh_reading_options({{"source", "V[,V...]", "source vertex ids"},
                                            {"method", "heat|exact|fmm", "distance backend (default heat)"},
                                            intrinsic_delaunay_option(),
                                            {"output", "FILE", ".csv (values) or .ply (coloured mesh)"}}),
                         1, 1, run_geodesics};
  return c;
}

const Command& sample_command() {
  static const Command c{"sample", "sample MESH --count N [--metric geodesic|euclidean] [--intrinsic-delaunay] [--seed S] [--output FILE]",
                         "Furthest point sampling (thesis chapter 5): N vertex ids in selection order, one per line, on "
                         "stdout or in FILE. The arbitrary start vertex, drawn with the seed, is not among them.",
                         with_mesh_reading_options({{"count", "N", "number of samples"},
                                            {"metric", "geodesic|euclidean", "distance between samples (default geodesic, heat method)"},
                                            intrinsic_delaunay_option(),
                                            {"seed", "S", "seed of the start vertex (default 0)"},
                                            {"output", "FILE", "write the ids here instead of stdout"}}),
                         1, 1, run_sample};
  return c;
}

const Command& agd_command() {
  static const Command c{"agd", "agd MESH [--radius FRACTION | --sources K [--intrinsic-delaunay]] --output FILE",
                         "Average geodesic distance of every vertex (thesis chapter 4): global, from K furthest-point "
                         "sources weighted by their Voronoi areas (default 100; 0 = every vertex), or local, within "
                         "FRACTION x the geodesic diameter. FILE.csv: one value per line; FILE.ply: coloured mesh.",
                         with_mesh_reading_options({{"radius", "FRACTION", "local agd within FRACTION x D"},
                                            {"sources", "K", "global agd from K sources (default 100, 0 = all)"},
                                            intrinsic_delaunay_option(),
                                            {"output", "FILE", ".csv (values) or .ply (coloured mesh)"}}),
                         1, 1, run_agd};
  return c;
}

} // namespace cli
