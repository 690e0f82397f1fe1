// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr correspond: fully automatic near-isometric correspondence (thesis chapter 5) of SOURCE
// and TARGET; the dense map, the sparse matches, a JSON report, coloured meshes and, with ground
// truth, the geodesic error.
#include "cli_common.h"

#include <shapecorr/evaluation/descriptor_ranking.h>
#include <shapecorr/evaluation/map_geodesic_error.h>
#include <shapecorr/registration/isometric_correspondence.h>


#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <boost/tuple/tuple.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>

namespace cli {
namespace {

K::Point_3 point_of(const Mesh& m, std::size_t i) { return m.point(vertex_descriptor(static_cast<Mesh::size_type>(i))); }

nlohmann::json to_json(const shapecorr::Map_error_summary& e) {
  return {{"pairs", e.pairs}, {"mean_error", e.mean}, {"largest_error", e.largest}, {"fraction_within_0.25", e.fraction_within}};
}

// The ground-truth pairs must pair up and name vertices of the meshes.
void check_truth(const Mesh& source, const Mesh& target, const std::vector<std::size_t>& source_ids, const std::vector<std::size_t>& target_ids) {
  if(source_ids.size() != target_ids.size())
    throw shapecorr::Invalid_argument("correspond: the two --truth files have " + std::to_string(source_ids.size()) + " and " +
                                      std::to_string(target_ids.size()) + " ids (they must pair up)");
  for(std::size_t k = 0; k < source_ids.size(); ++k)
    if(source_ids[k] >= source.number_of_vertices() || target_ids[k] >= target.number_of_vertices())
      throw shapecorr::Invalid_argument("correspond: --truth pair " + std::to_string(k + 1) + " names a vertex the mesh does not have");
}

// For each vertex of `from`, the nearest vertex of `to` (a k-d tree of `to`'s points).
std::vector<std::size_t> nearest_vertices(const Mesh& from, const Mesh& to) {
  typedef boost::tuple<K::Point_3, std::size_t> Indexed;
  typedef CGAL::Search_traits_adapter<Indexed, CGAL::Nth_of_tuple_property_map<0, Indexed>, CGAL::Search_traits_3<K>> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  std::vector<Indexed> points;
  for(auto v : to.vertices()) points.emplace_back(to.point(v), std::size_t(v.idx()));
  typename Search::Tree tree(points.begin(), points.end());
  std::vector<std::size_t> out;
  for(auto v : from.vertices()) {
    Search search(tree, from.point(v), 1);
    out.push_back(boost::get<1>(search.begin()->first));
  }
  return out;
}

int run_correspond(const Args& a) {
  const Mesh source = read_mesh(a, 0);
  const Mesh target = read_mesh(a, 1);
  const std::string output = a.require("output");
  const std::string solver = a.get("solver", "bb"), trim = a.get("trim", "gsc");
  if(solver != "bb" && solver != "mip") throw Usage_error("correspond: --solver must be bb (branch and bound) or mip (GLPK)");
  if(trim != "gsc" && trim != "wks" && trim != "isc") throw Usage_error("correspond: --trim must be gsc, wks or isc");
  const std::string orientation = a.get("orientation", "preserving");
  if(orientation != "preserving" && orientation != "reversing" && orientation != "any")
    throw Usage_error("correspond: --orientation must be preserving, reversing or any");
  if(a.has("colors") && a.get("colors").empty()) throw Usage_error("correspond: --colors needs a file prefix");
  if(a.has("lines") && extension(a.get("lines")) != "obj" && extension(a.get("lines")) != "ply")
    throw Usage_error("correspond: --lines must end in .obj or .ply");
  namespace SP = shapecorr::parameters;
  const bool show = verbose(a);
  const std::function<void(std::size_t, std::size_t)> progress = [&](std::size_t done, std::size_t total) {
    if(show) std::cerr << "correspond: stage " << done << "/" << total << "\n";
  };
  const auto np = SP::number_of_features(to_count(a.get("features", "10"), "--features", 2, 1000))
                      .number_of_levels(to_count(a.get("levels", "3"), "--levels", 0, 1000))
                      .features_per_level(to_count(a.get("per-level", "20"), "--per-level", 1, 100000))
                      .number_of_starts(to_count(a.get("starts", "3"), "--starts", 1, 1000))
                      .number_of_candidates(to_count(a.get("candidates", "3"), "--candidates", 1, 1000))
                      .number_of_eigenpairs(to_count(a.get("eigenpairs", "60"), "--eigenpairs", 0, 1000))
                      .random_seed(static_cast<unsigned>(to_count(a.get("seed", "0"), "--seed", 0, max_seed)))
                      .coarse_solver(solver == "bb" ? shapecorr::Coarse_solver::BRANCH_AND_BOUND : shapecorr::Coarse_solver::MIXED_INTEGER_PROGRAM)
                      .trim_descriptor(trim == "gsc"   ? shapecorr::Trim_descriptor::GEODESIC_SPIN_CONTOUR
                                       : trim == "wks" ? shapecorr::Trim_descriptor::WAVE_KERNEL_SIGNATURE
                                                       : shapecorr::Trim_descriptor::INTRINSIC_SHAPE_CONTEXT)
                      .orientation(orientation == "preserving"  ? shapecorr::Map_orientation::PRESERVING
                                   : orientation == "reversing" ? shapecorr::Map_orientation::REVERSING
                                                                : shapecorr::Map_orientation::ANY)
                      .progress_callback(progress);
  std::vector<std::size_t> truth_source, truth_target;
  if(a.has("truth") && a.has("truth-nearest")) throw Usage_error("correspond: --truth and --truth-nearest exclude each other");
  if(a.has("truth-nearest")) { // the same surface in the same place: each source vertex's truth is the nearest target vertex
    const std::vector<std::size_t> near = nearest_vertices(source, target);
    for(std::size_t s = 0; s < near.size(); ++s) {
      truth_source.push_back(s);
      truth_target.push_back(near[s]);
    }
  }
  if(a.has("truth")) { // read before the work: a bad file fails at once
    truth_source = shapecorr::read_vts(a.values("truth")[0]);
    truth_target = shapecorr::read_vts(a.values("truth")[1]);
    check_truth(source, target, truth_source, truth_target);
  }
  std::vector<std::size_t> mirror_source; // --symmetric: the mirror images of the truth's source vertices
  if(a.has("symmetric")) {
    if(!a.has("truth")) throw Usage_error("correspond: --symmetric needs --truth");
    mirror_source = shapecorr::read_vts(a.get("symmetric"));
    check_truth(source, target, mirror_source, truth_target);
  }
  const auto t0 = std::chrono::steady_clock::now();
  shapecorr::Isometric_correspondence<Mesh> method(source, target, np);
  const shapecorr::Isometric_correspondence_report& report = method.run();
  const double secs = seconds_since(t0);
  const std::vector<std::size_t>& dense = method.dense_map();
  {
    std::ofstream out = open_output(output);
    out << "# shapecorr correspond: line i (after the comments) is the target vertex (0-based) of source vertex i\n";
    for(std::size_t t : dense) out << t << "\n";
    if(!out) throw shapecorr::Output_error(output + ": write failed");
  }
  if(a.has("sparse")) {
    std::ofstream out = open_output(a.get("sparse"));
    out << "# source target level (0-based vertex ids; level 0: the coarse program)\n";
    for(const auto& m : report.matches) out << m.source << " " << m.target << " " << m.level << "\n";
  }
  if(a.has("lines")) {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for(const auto& m : report.matches) pairs.emplace_back(m.source, m.target);
    shapecorr::write_correspondences(a.get("lines"), source, target, pairs);
  }
  if(a.has("colors")) {
    // the target coloured by the distance from the target vertex of the first match, and the
    // source by the same values pulled back through the dense map: a right map gives the same
    // picture on both; the matched features in red
    const K::Point_3 origin = point_of(target, report.matches.front().target);
    std::vector<double> on_target(target.number_of_vertices()), on_source(source.number_of_vertices());
    for(std::size_t t = 0; t < on_target.size(); ++t) on_target[t] = std::sqrt(CGAL::squared_distance(point_of(target, t), origin));
    for(std::size_t s = 0; s < on_source.size(); ++s) on_source[s] = on_target[dense[s]];
    std::vector<std::size_t> hs, ht;
    for(const auto& m : report.matches) hs.push_back(m.source), ht.push_back(m.target);
    write_values(a.get("colors") + "_source.ply", source, on_source, hs);
    write_values(a.get("colors") + "_target.ply", target, on_target, ht);
  }
  // the geodesic error at the truth's pairs, divided by sqrt(area); with --symmetric also of the
  // mirror images of the truth's source points (the flipped map)
  shapecorr::Map_error_summary te, mirrored;
  if(!truth_source.empty()) {
    std::vector<std::vector<std::size_t>> found(a.has("symmetric") ? 2 : 1);
    for(std::size_t k = 0; k < truth_source.size(); ++k) {
      found[0].push_back(dense[truth_source[k]]);
      if(a.has("symmetric")) found[1].push_back(dense[mirror_source[k]]);
    }
    const auto e = shapecorr::map_geodesic_errors(target, truth_target, found);
    te = shapecorr::summarize_map_errors(e[0]);
    if(a.has("symmetric")) mirrored = shapecorr::summarize_map_errors(e[1]);
  }
  if(a.has("report")) {
    nlohmann::json j;
    j["source"] = a.positional[0];
    j["target"] = a.positional[1];
    j["starts"] = report.starts;
    j["chosen_seed"] = report.chosen_seed;
    j["sparse_matches"] = report.matches.size();
    j["orientation"] = {{"requested", orientation},
                        {"returned", report.orientation == shapecorr::Map_orientation::PRESERVING ? "preserving" : "reversing"},
                        {"score", report.orientation_score},
                        {"coarse_met", report.levels.empty() ? false : report.levels[0].orientation_met}};
    nlohmann::json levels = nlohmann::json::array();
    for(const auto& l : report.levels)
      levels.push_back({{"level", l.level},
                        {"source_features", l.source_features},
                        {"target_features", l.target_features},
                        {"candidates", l.candidates},
                        {"new_matches", l.new_matches},
                        {"objective", l.objective},
                        {"optimal", l.optimal},
                        {"nodes", l.nodes},
                        {"energies", l.energies},
                        {"matching_seconds", l.matching_seconds},
                        {"local_seconds", l.local_seconds}});
    j["levels"] = levels;
    j["descriptor_seconds"] = report.descriptor_seconds;
    j["dense_seconds"] = report.dense_seconds;
    j["seconds"] = secs;
    if(!truth_source.empty()) j["truth"] = to_json(te);
    if(a.has("symmetric")) j["truth_symmetric"] = to_json(mirrored);
    std::ofstream out = open_output(a.get("report"));
    out << j.dump(2) << "\n";
  }
  if(show) {
    std::cerr << "correspond: " << report.matches.size() << " sparse matches over " << report.levels.size() << " levels (start " << report.chosen_seed
              << " of " << report.starts << " tried), dense map of " << dense.size() << " vertices, orientation-"
              << (report.orientation == shapecorr::Map_orientation::PRESERVING ? "preserving" : "reversing") << " (agreement " << report.orientation_score << ")";
    if(!truth_source.empty())
      std::cerr << "; geodesic error / sqrt(area) over " << te.pairs << " pairs: mean " << te.mean << ", largest " << te.largest << ", "
                << 100 * te.fraction_within << " % within 0.25";
    if(a.has("symmetric"))
      std::cerr << "; against the mirrored truth: mean " << mirrored.mean << ", largest " << mirrored.largest << ", " << 100 * mirrored.fraction_within
                << " % within 0.25 (the map is " << (mirrored.mean < te.mean ? "the mirrored one" : "the direct one") << ")";
    std::cerr << "; " << secs << " s -> " << output << "\n";
  }
  return 0;
}

} // namespace

const Command& correspond_command() {
  static const Command c{
      "correspond",
      "correspond SOURCE TARGET --output MAP.txt [--features N] [--levels L] [--sparse FILE] [--lines FILE] [--colors PREFIX] [--orientation preserving|reversing|any] [--truth S.vts T.vts [--symmetric S.sym.vts] | --truth-nearest] [--report FILE.json]",
      "Fully automatic correspondence of two near-isometric shapes (thesis chapter 5): furthest-point features, "
      "candidate pairs by Geodesic Spin Contour (or WKS), the coarse program that keeps geodesic distances (branch and "
      "bound, or GLPK) among matchings of the orientation asked for (direct by default), local optimization, refinement "
      "levels, then a dense map; the summary line says the map's orientation and its agreement in [-1, 1]. SOURCE and TARGET must be one connected "
      "component each. Writes MAP.txt: after '#' comments, line i is the target vertex (0-based) of source vertex i. "
      "With --truth (TOSCA .vts files of SOURCE and TARGET, 1-based, paired by line), prints the geodesic error on TARGET "
      "divided by sqrt(area) (with --symmetric also against the mirrored truth: a symmetric shape has two right maps). "
      "Progress on stderr.",
      with_mesh_reading_options({{"output", "MAP.txt", "the dense map, one target vertex per source vertex"},
                                 {"features", "N", "coarse features per shape (default 10)"},
                                 {"levels", "L", "refinement levels (default 3)"},
                                 {"per-level", "N", "new features per shape and level (default 20)"},
                                 {"starts", "S", "first vertices tried for the coarse level; the lowest energy is kept (default 3)"},
                                 {"candidates", "K", "candidate targets per feature, widened until the program is feasible (default 3)"},
                                 {"solver", "bb|mip", "the coarse program's solver: branch and bound (default) or GLPK"},
                                 {"trim", "gsc|wks|isc", "descriptor of the candidate pairs (default gsc)"},
                                 {"eigenpairs", "K", "largest spectral basis of the dense map's upsampling; 0: geodesic coordinates only (default 60)"},
                                 {"seed", "S", "seed of the first sampled vertex (default 0)"},
                                 {"orientation", "preserving|reversing|any", "the map's orientation: direct (default), the mirror map, or whichever distorts least"},
                                 {"sparse", "FILE", "the sparse matches: 'source target level' per line"},
                                 {"lines", "FILE.obj|.ply", "both shapes side by side with a line per sparse match (MeshLab)"},
                                 {"colors", "PREFIX", "PREFIX_target.ply coloured by the distance from a matched feature, PREFIX_source.ply by the same values through the map (matched features red)"},
                                 {"truth", "S.vts T.vts", "ground-truth vertex lists of SOURCE and TARGET (1-based, paired by line): report the geodesic error"},
                                 {"truth-nearest", "", "SOURCE and TARGET are the same surface in the same place (another triangulation): the truth of a source vertex is the nearest target vertex"},
                                 {"symmetric", "S.sym.vts", "with --truth: the mirror image of each truth source vertex (TOSCA .sym.vts): also the error against the mirrored truth"},
                                 {"report", "FILE.json", "levels (features, candidates, objective, energies, times), starts, the truth error"}}),
      2, 2, run_correspond};
  return c;
}

} // namespace cli
