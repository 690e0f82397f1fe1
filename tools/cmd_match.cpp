// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr match: nearest-descriptor matching of source points to target vertices.
#include "descriptor_sets.h"

#include <shapecorr/io/write_correspondences.h>
#include <shapecorr/sampling/furthest_point_sampling.h>

#include <chrono>

namespace cli {
namespace {

namespace SP = shapecorr::parameters;

std::vector<std::size_t> source_points(const Mesh& source, const Args& a) {
  std::vector<std::size_t> ids;
  if(a.has("source-points")) {
    if(a.has("points") || a.has("seed")) throw Usage_error("match: --source-points excludes --points and --seed");
    std::ifstream in(a.get("source-points"));
    if(!in) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, a.get("source-points") + ": cannot read");
    std::string tok;
    while(in >> tok) {
      const std::size_t v = to_count(tok, a.get("source-points") + ": source point", 0, std::numeric_limits<std::size_t>::max());
      if(v >= source.number_of_vertices()) throw shapecorr::Invalid_argument("source point " + tok + " out of range");
      ids.push_back(v);
    }
    if(ids.empty()) throw Usage_error(a.get("source-points") + ": no vertex ids");
    return ids;
  }
  const std::size_t n = std::min<std::size_t>(to_count(a.get("points", "100"), "--points", 1, max_count), source.number_of_vertices());
  std::vector<vertex_descriptor> samples;
  shapecorr::furthest_point_sampling(source, n, std::back_inserter(samples), SP::random_seed(static_cast<unsigned>(to_count(a.get("seed", "0"), "--seed", 0, max_seed))));
  for(auto v : samples) ids.push_back(v.idx());
  return ids;
}

int run_match(const Args& a) {
  const std::string type = a.require("descriptor"), output = a.require("output");
  check_descriptor_type(type, "--descriptor");
  if(a.has("exact-area") && type != "face-spin-image") throw Usage_error("--exact-area applies to --descriptor face-spin-image");
  if(a.has("comparison") && !is_contour(type)) throw Usage_error("--comparison applies to --descriptor spin-contour or gsc");
  const shapecorr::Contour_comparison comparison = shapecorr::contour_comparison_from_string(a.get("comparison", "automatic"));
  const std::size_t k = to_count(a.get("candidates", "1"), "--candidates", 1, 1000000);
  const Mesh source = read_mesh(a, 0), target = read_mesh(a, 1);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<std::size_t> ids = source_points(source, a);
  shapecorr::Geodesic_spin_normalization norm; // the target's, imposed on the source
  const Descriptor_set t = compute_descriptor_set(target, all_ids(target.number_of_vertices()), type, a, target, "target descriptors", &norm);
  const Descriptor_set s = compute_descriptor_set(source, ids, type, a, target, "source descriptors", &norm);
  const auto t1 = std::chrono::steady_clock::now();
  const auto nearest = nearest_descriptors(s, t, k, comparison);
  std::ofstream out = open_output(output);
  out.precision(9);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::size_t unmatched = 0;
  for(std::size_t i = 0; i < nearest.size(); ++i) {
    unmatched += nearest[i].empty();
    for(const auto& n : nearest[i]) out << ids[i] << " " << n.target << " " << n.distance << "\n";
    if(!nearest[i].empty()) pairs.emplace_back(ids[i], nearest[i][0].target);
  }
  if(a.has("lines")) shapecorr::write_correspondences(a.get("lines"), source, target, pairs);
  if(a.has("distance-view")) { // the descriptor distance to one source vertex on both shapes
    const std::size_t v = parse_ids(a.get("distance-view"), source.number_of_vertices())[0];
    const std::string prefix = a.get("distance-view-prefix", output);
    const Descriptor_set all_source = compute_descriptor_set(source, all_ids(source.number_of_vertices()), type, a, target, "distance view (source)", &norm);
    write_values(prefix + "_source.ply", source, distances_from(all_source, all_source, v), {v});
    const std::vector<double> dt = distances_from(all_source, t, v);
    std::size_t best = 0; // the nearest target with a distance (an empty descriptor has none)
    for(std::size_t j = 0; j < dt.size(); ++j)
      if(std::isfinite(dt[j]) && (!std::isfinite(dt[best]) || dt[j] < dt[best])) best = j;
    write_values(prefix + "_target.ply", target, dt, {best});
    if(verbose(a))
      std::cerr << "match: distance to source vertex " << v << " -> " << prefix << "_source.ply, " << prefix << "_target.ply (marked: the nearest target vertex "
                << best << ")\n";
  } else if(a.has("distance-view-prefix")) {
    throw Usage_error("--distance-view-prefix applies with --distance-view");
  }
  if(verbose(a))
    std::cerr << "match: " << type << ", " << ids.size() << " source points against " << target.number_of_vertices() << " target vertices (descriptors "
              << std::chrono::duration<double>(t1 - t0).count() << " s, matching "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count() << " s) -> " << output
              << (a.has("lines") ? " and " + a.get("lines") : std::string()) << "\n";
  if(verbose(a) && is_contour(type)) {
    auto empties = [](const Descriptor_set& d) {
      return static_cast<std::size_t>(std::count_if(d.contours.begin(), d.contours.end(), [](const shapecorr::Spin_contour& c) { return c.empty(); }));
    };
    if(const std::size_t e = empties(t)) std::cerr << "note: " << e << " target vertices have an empty contour (no descriptor: a flat neighbourhood): never matched\n";
    if(unmatched) std::cerr << "note: " << unmatched << " source points have no match (an empty contour, or only empty target contours): no line in " << output << "\n";
  }
  return 0;
}

std::vector<Option> options() {
  std::vector<Option> o = {
      {"descriptor", "NAME", "hks, wks, sihks, spin-image, face-spin-image, spin-contour, improved-spin-image, gsc, geodesic-spin-image"},
      {"output", "FILE", "'source_id target_id distance' lines (0-based), up to --candidates lines per source, nearest first; none for a source without a descriptor (an empty contour)"},
      {"points", "N", "match N furthest-point samples of SOURCE (default 100)"},
      {"seed", "S", "seed of the sampling's start vertex (default 0)"},
      {"source-points", "FILE", "match these SOURCE vertex ids (whitespace-separated) instead"},
      {"candidates", "K", "the K nearest target vertices of each source point (default 1)"},
      {"comparison", "automatic|exact|index|fields",
       "spin-contour, gsc: how contours are compared: automatic (default: exact below 32 sources, else nearest-point indices, the "
       "same distances), exact, index, or fields (distance fields: approximate, at most 1/240 off, faster)"},
      {"lines", "FILE.obj|.ply", "both meshes side by side with a line per match"},
      {"distance-view", "V", "PREFIX_source.ply and PREFIX_target.ply: both shapes coloured by the descriptor distance to source vertex V"},
      {"distance-view-prefix", "PREFIX", "prefix of the --distance-view files (default: FILE)"}};
  for(const Option& x : descriptor_options()) o.push_back(x);
  return with_mesh_reading_options(o);
}

} // namespace

const Command& match_command() {
  static const Command c{
      "match", "match SOURCE TARGET --descriptor NAME [--points N | --source-points FILE] [options] --output FILE",
      "Matches points of SOURCE (N furthest-point samples, or the ids in a file) to the TARGET vertices of nearest "
      "descriptor. Support fractions refer to the TARGET's extent (gsc: the TARGET's geodesic diameter and agd range, "
      "so that a part of a shape matches the whole).",
      options(), 2, 2, run_match};
  return c;
}

} // namespace cli
