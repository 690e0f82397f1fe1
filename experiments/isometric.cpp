// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The chapter 5 evaluation: fully automatic near-isometric correspondence (ours, with the GSC, WKS
// and ISC trims) against pyFM's functional maps with WKS + ZoomOut (a separate Python process,
// experiments/pyfm_map.py), on the same pairs with the same metric: the Princeton protocol's
// geodesic error at ground-truth pairs divided by sqrt(target area), direct and symmetry-aware
// (the map judged against the truth or its left-right mirror, whichever it is nearer on average).
// Cases: the pairs of tosca5k/test_pairs.txt, camel_gallop frames (pyFM's maps as truth), lion ->
// cat (non-isometric), and cut sources (a tosca pair per class, the source's extremity of largest
// agd removed). One JSON file per case in OUTPUT/cases; a case file done before keeps its methods
// and gets only those it lacks (runs resume; another trim can be added later);
// experiments/isometric_summary.py makes the tables and figures.
// usage: evaluate_isometric [--data DIR] [--output DIR] [--cases tosca,camel,lion,cut] [--trims gsc,wks,isc]
//        [--extra-trims-every N] [--part I/N] [--limit N] [--every N] [--truth-points 1000] [--pyfm SCRIPT|none]
//        [--pyfm-variants plain,oriented] [--peers DIR] [--python PY] [--threads T]
// pyFM runs twice: "pyfm" without its orientation term, "pyfm-oriented" with w_orient = 1 (what
// its authors recommend for direct maps).
#include "program.h"
#include "shapes.h"

#include <shapecorr/evaluation.h>
#include <shapecorr/registration/isometric_correspondence.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace {
using eval::split;
using eval::Mesh;
using eval::none;
namespace SP = shapecorr::parameters;
using nlohmann::json;

struct Case {
  std::string name, kind;        // kind: tosca, camel, lion, cut
  std::string source_file, target_file;
  eval::Shape source;
  Mesh target;
  std::vector<std::size_t> truth_of, mirror_of; // per source vertex: its true target vertex / that of its mirror image (none: unknown)
  std::size_t file_vertices = none;              // vertices of the source file (before a repair's duplicates)
};

std::vector<std::size_t> read_map(const std::string& path, std::size_t n_source) {
  std::ifstream in(path);
  if(!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::size_t> m;
  std::string line;
  while(std::getline(in, line)) {
    if(line.empty() || line[0] == '#') continue;
    m.push_back(std::stoul(line));
  }
  if(m.size() < n_source) throw std::runtime_error(path + ": " + std::to_string(m.size()) + " entries for " + std::to_string(n_source) + " vertices");
  return m;
}

// TOSCA: the .vts files name corresponding points of the template in each shape
void tosca_truth(const std::string& tosca, const std::string& a, const std::string& b, Case& c, const std::vector<std::size_t>& original) {
  const auto va = shapecorr::read_vts(tosca + "corres/" + a + ".vts"), vb = shapecorr::read_vts(tosca + "corres/" + b + ".vts");
  const auto vs = shapecorr::read_vts(tosca + "corres/" + a + ".sym.vts");
  std::vector<std::size_t> t(original.empty() ? c.source.mesh.number_of_vertices() : 0, none), s = t;
  if(!original.empty()) { // on the original shape, then carried to the kept vertices
    std::size_t n0 = 0;
    for(std::size_t o : original) n0 = std::max(n0, o + 1);
    for(std::size_t v : va) n0 = std::max(n0, v + 1);
    t.assign(n0, none);
    s.assign(n0, none);
  }
  for(std::size_t k = 0; k < va.size() && k < vb.size() && k < vs.size(); ++k) {
    if(va[k] < t.size() && t[va[k]] == none) t[va[k]] = vb[k];
    if(vs[k] < s.size() && s[vs[k]] == none) s[vs[k]] = vb[k];
  }
  c.truth_of.assign(c.source.mesh.number_of_vertices(), none);
  c.mirror_of = c.truth_of;
  for(std::size_t v = 0; v < c.truth_of.size(); ++v) {
    const std::size_t o = c.source.original[v];
    if(o < t.size()) {
      c.truth_of[v] = t[o];
      c.mirror_of[v] = s[o];
    }
  }
}

// The largest connected component of a mesh (by faces) as a shape of its own, and for every vertex
// of the mesh the vertex of that shape it goes to: itself, or the nearest one (a vertex off the
// component: the duplicates of a non-manifold split lie where a component vertex lies).
struct Main_component {
  eval::Shape shape;
  std::vector<std::size_t> main_of;
  std::size_t components = 1;
  explicit Main_component(const Mesh& m) {
    Mesh copy = m;
    auto cc = copy.add_property_map<Mesh::Face_index, std::size_t>("f:eval_cc", 0).first;
    components = CGAL::Polygon_mesh_processing::connected_components(copy, cc);
    std::vector<std::size_t> faces(components, 0), of_vertex(m.number_of_vertices(), none);
    for(auto f : copy.faces()) ++faces[cc[f]];
    const std::size_t largest = std::size_t(std::max_element(faces.begin(), faces.end()) - faces.begin());
    for(auto f : copy.faces())
      for(auto v : CGAL::vertices_around_face(copy.halfedge(f), copy)) of_vertex[v.idx()] = cc[f];
    if(components == 1 && std::find(of_vertex.begin(), of_vertex.end(), none) == of_vertex.end()) { // the mesh itself, same numbering
      shape = eval::whole(m);
      main_of = shape.original;
      return;
    }
    shape = eval::keep_faces(m, [&](std::size_t v) { return of_vertex[v] == largest; });
    std::vector<std::size_t> back(m.number_of_vertices(), none);
    for(std::size_t i = 0; i < shape.original.size(); ++i) back[shape.original[i]] = i;
    main_of.assign(m.number_of_vertices(), 0);
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
      if(back[v] != none) {
        main_of[v] = back[v];
        continue;
      }
      const auto p = m.point(eval::Vertex(static_cast<Mesh::size_type>(v)));
      double best = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < shape.original.size(); ++i) {
        const double d = CGAL::squared_distance(p, m.point(eval::Vertex(static_cast<Mesh::size_type>(shape.original[i]))));
        if(d < best) {
          best = d;
          main_of[v] = i;
        }
      }
    }
  }
};

// The errors of one method's dense map and sparse matches on a case.
struct Method_result {
  double seconds = 0;
  std::vector<double> dense, dense_mirror;                 // at the sampled truth pairs
  std::vector<std::vector<double>> sparse, sparse_mirror;  // per level, at matches with truth
  std::vector<std::vector<double>> sweeps, sweeps_mirror;  // per level: mean error of all matches before / after each sweep
  json levels = json::array();
};

json errors_json(const Method_result& r) {
  const double md = shapecorr::summarize_map_errors(r.dense).mean, mm = shapecorr::summarize_map_errors(r.dense_mirror).mean;
  const bool mirrored = !r.dense_mirror.empty() && mm < md;
  const auto& chosen = mirrored ? r.dense_mirror : r.dense;
  auto summary = [](const std::vector<double>& e) {
    const auto s = shapecorr::summarize_map_errors(e);
    return json{{"mean", s.mean}, {"within_0.25", s.fraction_within}, {"largest", s.largest}};
  };
  json j{{"seconds", r.seconds},
         {"dense_direct", summary(r.dense)},
         {"dense_symmetric", summary(chosen)},
         {"mirrored", mirrored},
         {"curve_direct", shapecorr::cumulative_error_curve(r.dense)},
         {"curve_symmetric", shapecorr::cumulative_error_curve(chosen)}};
  if(!r.sparse.empty()) {
    j["sparse_direct"] = r.sparse;
    j["sparse_symmetric"] = mirrored ? r.sparse_mirror : r.sparse;
    j["sweeps_direct"] = r.sweeps;
    j["sweeps_symmetric"] = mirrored ? r.sweeps_mirror : r.sweeps;
    j["levels"] = r.levels;
  }
  return j;
}

struct Options {
  std::string data = SHAPECORR_EVAL_DATA_DIR, out = "experiments/results/isometric", cases = "tosca,camel,lion,cut", trims = "gsc,wks,isc";
  std::string pyfm = SHAPECORR_EXPERIMENTS_DIR "/pyfm_map.py", peers, python = "/usr/bin/python3";
  std::string pyfm_variants = "plain,oriented"; // plain: w_orient 0 ("pyfm"); oriented: w_orient 1 ("pyfm-oriented")
  std::size_t extra_every = 1, every = 1, part = 0, parts = 1, limit = 0, truth_points = 1000, eigenpairs = 60;
  unsigned threads = 0;
};

void run_case(const Case& c, const Options& o) {
  // a case file done before keeps its methods; only the methods it lacks run (e.g. another trim)
  const std::string path = o.out + "/cases/" + c.name + ".json";
  json before;
  if(std::ifstream in{path}) in >> before;
  auto missing = [&](const std::string& method) { return !before.contains("methods") || !before["methods"].contains(method); };
  std::vector<std::string> trims;
  for(const std::string& t : split(o.trims, ','))
    if(missing("ours-" + t)) trims.push_back(t);
  std::vector<std::string> pyfm_runs; // the pyFM variants this case lacks
  if(o.pyfm != "none")
    for(const std::string& v : split(o.pyfm_variants, ','))
      if(missing(v == "oriented" ? "pyfm-oriented" : "pyfm")) pyfm_runs.push_back(v);
  if(trims.empty() && pyfm_runs.empty()) {
    std::cerr << c.name << ": done before (" << path << ")\n";
    return;
  }
  const std::size_t ns = c.source.mesh.number_of_vertices();
  // the sampled truth pairs of the dense maps: every stride-th source vertex with truth (and,
  // where there is one, a mirror truth)
  std::vector<std::size_t> with_truth;
  for(std::size_t v = 0; v < ns; ++v)
    if(c.truth_of[v] != none && (c.mirror_of.empty() || c.mirror_of[v] != none)) with_truth.push_back(v);
  const std::size_t stride = std::max<std::size_t>(1, with_truth.size() / o.truth_points);
  // a true vertex off the target's largest component (a vertex a non-manifold repair left alone,
  // its faces moved to duplicates) is unreachable: its place on that component stands for it
  const Main_component target_main(c.target);
  auto snap = [&](std::size_t t) { return target_main.shape.original[target_main.main_of[t]]; };
  std::vector<std::size_t> pair_source, pair_truth;
  for(std::size_t i = 0; i < with_truth.size(); i += stride) {
    pair_source.push_back(with_truth[i]);
    pair_truth.push_back(snap(c.truth_of[with_truth[i]]));
  }
  const bool symmetric = !c.mirror_of.empty();
  json j = before.is_object() ? before : json{{"name", c.name}, {"kind", c.kind}, {"source_vertices", ns},
                                              {"target_vertices", c.target.number_of_vertices()}, {"truth_pairs", pair_source.size()}};
  auto dense_errors = [&](const std::vector<std::size_t>& map, Method_result& r) {
    // the mirror list: the map at the mirror images' true target vertices, i.e. for pair (s, t)
    // the source vertex whose mirror truth is t: found by the mirror truth of s's counterpart
    std::vector<std::vector<std::size_t>> found(1);
    for(std::size_t s : pair_source) found[0].push_back(map[s]);
    auto e = shapecorr::map_geodesic_errors(c.target, pair_truth, found, SP::number_of_threads(o.threads));
    r.dense = e[0];
    if(symmetric) { // the mirror truth of s: map[s] should be mirror_of[s]
      std::vector<std::size_t> mt;
      for(std::size_t s : pair_source) mt.push_back(snap(c.mirror_of[s]));
      r.dense_mirror = shapecorr::map_geodesic_errors(c.target, mt, found, SP::number_of_threads(o.threads))[0];
    }
  };
  // ours, with each trim
  for(const std::string& trim : trims) {
    const auto t = trim == "gsc" ? shapecorr::Trim_descriptor::GEODESIC_SPIN_CONTOUR
                                 : trim == "wks" ? shapecorr::Trim_descriptor::WAVE_KERNEL_SIGNATURE : shapecorr::Trim_descriptor::INTRINSIC_SHAPE_CONTEXT;
    Method_result r;
    const auto t0 = std::chrono::steady_clock::now();
    // the method wants one connected component: on a mesh with several (camel frames 1 and 5 after
    // their non-manifold edges are split) it runs on the largest, and the map is carried back
    const Main_component src(c.source.mesh);
    const Main_component& tgt = target_main;
    shapecorr::Isometric_correspondence<Mesh> method(src.shape.mesh, tgt.shape.mesh,
                                                     SP::trim_descriptor(t).number_of_threads(o.threads).number_of_eigenpairs(c.kind == "cut" ? 0 : o.eigenpairs));
    shapecorr::Isometric_correspondence_report report = method.run();
    std::vector<std::size_t> dense(ns);
    for(std::size_t v = 0; v < ns; ++v) dense[v] = tgt.shape.original[method.dense_map()[src.main_of[v]]];
    for(auto& m : report.matches) m = {src.shape.original[m.source], tgt.shape.original[m.target], m.level};
    for(auto& l : report.levels)
      for(auto& snapshot : l.snapshots)
        for(auto& m : snapshot) m = {src.shape.original[m.source], tgt.shape.original[m.target], m.level};
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    j["methods"]["ours-" + trim]["components"] = {src.components, tgt.components};
    const json orientation = {{"score", report.orientation_score},
                              {"met", report.levels.empty() ? false : report.levels[0].orientation_met}};
    dense_errors(dense, r);
    // sparse matches and the snapshots of local optimization: one list of (truth, found) pairs
    std::vector<std::size_t> truth, mirror, found;
    struct Slot {
      std::size_t level, snapshot; // snapshot == none: the level's final matches
    };
    std::vector<Slot> slots;
    auto add = [&](const shapecorr::Vertex_match& m, Slot s) {
      if(c.truth_of[m.source] == none || (symmetric && c.mirror_of[m.source] == none)) return;
      truth.push_back(snap(c.truth_of[m.source]));
      mirror.push_back(snap(symmetric ? c.mirror_of[m.source] : c.truth_of[m.source]));
      found.push_back(m.target);
      slots.push_back(s);
    };
    const std::size_t L = report.levels.size();
    for(const auto& m : report.matches) add(m, {m.level, none});
    for(std::size_t l = 0; l < L; ++l)
      for(std::size_t k = 0; k < report.levels[l].snapshots.size(); ++k)
        for(const auto& m : report.levels[l].snapshots[k]) add(m, {l, k});
    const auto ed = shapecorr::map_geodesic_errors(c.target, truth, {found}, SP::number_of_threads(o.threads))[0];
    const auto em = shapecorr::map_geodesic_errors(c.target, mirror, {found}, SP::number_of_threads(o.threads))[0];
    r.sparse.assign(L, {});
    r.sparse_mirror.assign(L, {});
    r.sweeps.assign(L, {});
    r.sweeps_mirror.assign(L, {});
    std::vector<std::vector<std::size_t>> count(L);
    for(std::size_t l = 0; l < L; ++l) {
      r.sweeps[l].assign(report.levels[l].snapshots.size(), 0.0);
      r.sweeps_mirror[l].assign(report.levels[l].snapshots.size(), 0.0);
      count[l].assign(report.levels[l].snapshots.size(), 0);
    }
    for(std::size_t i = 0; i < slots.size(); ++i) {
      const Slot& s = slots[i];
      if(s.snapshot == none) {
        r.sparse[s.level].push_back(ed[i]);
        r.sparse_mirror[s.level].push_back(em[i]);
      } else {
        r.sweeps[s.level][s.snapshot] += ed[i];
        r.sweeps_mirror[s.level][s.snapshot] += em[i];
        ++count[s.level][s.snapshot];
      }
    }
    for(std::size_t l = 0; l < L; ++l)
      for(std::size_t k = 0; k < count[l].size(); ++k)
        if(count[l][k] > 0) {
          r.sweeps[l][k] /= double(count[l][k]);
          r.sweeps_mirror[l][k] /= double(count[l][k]);
        }
    for(const auto& l : report.levels)
      r.levels.push_back({{"new_matches", l.new_matches}, {"matching_seconds", l.matching_seconds}, {"local_seconds", l.local_seconds},
                          {"sweeps", l.energies.empty() ? 0 : l.energies.size() - 1}, {"energy", l.energies.empty() ? 0.0 : l.energies.back()}});
    const json components = j["methods"]["ours-" + trim]["components"];
    j["methods"]["ours-" + trim] = errors_json(r);
    j["methods"]["ours-" + trim]["components"] = components;
    j["methods"]["ours-" + trim]["dense_seconds"] = report.dense_seconds;
    j["methods"]["ours-" + trim]["orientation"] = orientation;
    const auto& d = j["methods"]["ours-" + trim];
    std::cerr << c.name << " ours-" << trim << ": dense mean " << d["dense_direct"]["mean"].get<double>() << " direct, "
              << d["dense_symmetric"]["mean"].get<double>() << " symmetric (" << 100 * d["dense_symmetric"]["within_0.25"].get<double>()
              << " % < 0.25), " << r.seconds << " s, orientation " << report.orientation_score << "\n";
  }
  // pyFM, as a separate process on the same files: without and with its orientation term
  for(const std::string& variant : pyfm_runs) {
    const std::string method = variant == "oriented" ? "pyfm-oriented" : "pyfm", w_orient = variant == "oriented" ? "1" : "0";
    std::string source_file = c.source_file;
    if(source_file.empty()) { // a cut source: written for pyFM
      source_file = o.out + "/work/" + c.name + "_source.off";
      // plain OFF: "OFF", the counts, the points, the triangles (pyFM's reader wants exactly that)
      std::ofstream off(source_file);
      off.precision(17);
      off << "OFF\n" << c.source.mesh.number_of_vertices() << " " << c.source.mesh.number_of_faces() << " 0\n";
      for(auto v : c.source.mesh.vertices()) off << c.source.mesh.point(v) << "\n";
      for(auto f : c.source.mesh.faces()) {
        off << "3";
        for(auto v : CGAL::vertices_around_face(c.source.mesh.halfedge(f), c.source.mesh)) off << " " << v.idx();
        off << "\n";
      }
      if(!off) throw std::runtime_error("cannot write " + source_file);
    }
    const std::string map_file = o.out + "/work/" + c.name + "_" + method + ".txt", log = o.out + "/work/" + c.name + "_" + method + ".log";
    const std::string cmd = "'" + o.python + "' '" + o.pyfm + "' '" + o.peers + "' '" + source_file + "' '" + c.target_file + "' '" + map_file + "' " +
                            w_orient + " > '" + log + "' 2>&1";
    Method_result r;
    if(std::system(cmd.c_str()) != 0) {
      std::cerr << c.name << " " << method << " failed (see " << log << ")\n";
      j["methods"][method] = {{"failed", true}};
    } else {
      std::ifstream in(log);
      std::string word;
      while(in >> word)
        if(word == "seconds") in >> r.seconds;
      // (pyFM maps the file's vertices; the duplicates a non-manifold repair appends have no
      // truth, are never evaluated, and get vertex 0)
      std::vector<std::size_t> map = read_map(map_file, std::min(ns, c.file_vertices));
      map.resize(ns, 0);
      for(std::size_t s = 0; s < ns; ++s)
        if(map[s] >= c.target.number_of_vertices()) throw std::runtime_error(map_file + ": a target vertex out of range");
      dense_errors(map, r);
      j["methods"][method] = errors_json(r);
      j["methods"][method]["w_orient"] = std::stod(w_orient);
      const auto& d = j["methods"][method];
      std::cerr << c.name << " " << method << ": dense mean " << d["dense_direct"]["mean"].get<double>() << " direct, " << d["dense_symmetric"]["mean"].get<double>()
                << " symmetric (" << 100 * d["dense_symmetric"]["within_0.25"].get<double>() << " % < 0.25), " << r.seconds << " s\n";
    }
  }
  std::ofstream out(path + ".part");
  out << j.dump(1) << "\n";
  out.close();
  std::rename((path + ".part").c_str(), path.c_str());
}

} // namespace

int main(int argc, char** argv) {
  Options o;
  o.peers = o.data + "/../peers";
  const int code = eval::parse_options(argc, argv, "evaluate_isometric",
      "[--data DIR] [--output DIR] [--cases tosca,camel,lion,cut] [--trims gsc,wks,isc] [--extra-trims-every N]\n"
      "       [--part I/N] [--limit N] [--every N] [--truth-points N] [--pyfm SCRIPT|none] [--pyfm-variants plain,oriented] [--eigenpairs K]\n"
      "       [--peers DIR] [--python PY] [--threads T]",
      [&](const std::string& k, const std::string& v) {
        if(k == "--data") o.data = v;
        else if(k == "--output") o.out = v;
        else if(k == "--cases") o.cases = v;
        else if(k == "--trims") o.trims = v;
        else if(k == "--extra-trims-every") o.extra_every = std::stoul(v);
        else if(k == "--part") {
          const auto p = split(v, '/');
          if(p.size() != 2) return false;
          o.part = std::stoul(p[0]);
          o.parts = std::stoul(p[1]);
        } else if(k == "--limit") o.limit = std::stoul(v);
        else if(k == "--truth-points") o.truth_points = std::stoul(v);
        else if(k == "--pyfm") o.pyfm = v;
        else if(k == "--pyfm-variants") o.pyfm_variants = v;
        else if(k == "--every") o.every = std::stoul(v);
        else if(k == "--eigenpairs") o.eigenpairs = std::stoul(v);
        else if(k == "--peers") o.peers = v;
        else if(k == "--python") o.python = v;
        else if(k == "--threads") o.threads = static_cast<unsigned>(std::stoul(v));
        else return false;
        return true;
      });
  if(code >= 0) return code;
  try {
    if(!eval::has_evaluation_data("evaluate_isometric", o.data)) return 1;
    if(o.parts == 0 || o.part >= o.parts || o.truth_points == 0 || o.extra_every == 0 || o.every == 0)
      throw std::runtime_error("bad --part, --truth-points, --every or --extra-trims-every");
    std::system(("mkdir -p '" + o.out + "/cases' '" + o.out + "/work'").c_str());
    const std::string tosca = o.data + "/tosca5k/", camel = o.data + "/camel_gallop/";
    // the list of cases (built lazily: a case's meshes are read when it runs)
    struct Entry {
      std::string kind, a, b;
      std::size_t order;
    };
    std::vector<Entry> entries;
    const auto kinds = split(o.cases, ',');
    auto wanted = [&](const std::string& k) { return std::find(kinds.begin(), kinds.end(), k) != kinds.end(); };
    std::vector<std::pair<std::string, std::string>> pairs;
    {
      std::ifstream in(tosca + "test_pairs.txt");
      std::string a, b;
      while(in >> a >> b) pairs.emplace_back(a, b);
    }
    if(wanted("tosca"))
      for(std::size_t i = 0; i < pairs.size() && (o.limit == 0 || i < o.limit); ++i)
        if(i % o.every == 0) entries.push_back({"tosca", pairs[i].first, pairs[i].second, i});
    if(wanted("camel"))
      for(const char* m : {"1_to_3", "1_to_5", "1_to_7", "2_to_4", "2_to_10", "3_to_1", "10_to_8"}) {
        const auto ij = split(std::string(m), '_');
        entries.push_back({"camel", ij[0], ij[2], 0});
      }
    if(wanted("lion")) entries.push_back({"lion", "lion", "cat", 0});
    if(wanted("cut")) {
      std::set<std::string> classes;
      for(const auto& p : pairs) {
        const std::string cls = p.first.substr(0, p.first.find_first_of("0123456789"));
        if(classes.insert(cls).second) entries.push_back({"cut", p.first, p.second, 0});
      }
    }
    for(std::size_t e = 0; e < entries.size(); ++e) {
      if(e % o.parts != o.part) continue;
      const Entry& en = entries[e];
      Case c;
      c.kind = en.kind;
      if(en.kind == "tosca" || en.kind == "cut") {
        c.name = (en.kind == "cut" ? "cut-" : "") + en.a + "-" + en.b;
        const Mesh A = eval::read(tosca + "meshes/" + en.a + ".off");
        c.target = eval::read(tosca + "meshes/" + en.b + ".off");
        c.target_file = tosca + "meshes/" + en.b + ".off";
        if(en.kind == "cut") c.source = eval::cut_extremity(A);
        else {
          c.source = eval::whole(A);
          c.source_file = tosca + "meshes/" + en.a + ".off";
        }
        tosca_truth(tosca, en.a, en.b, c, en.kind == "cut" ? c.source.original : std::vector<std::size_t>());
      } else if(en.kind == "camel") {
        c.name = "camel" + en.a + "-camel" + en.b;
        auto frame = [&](const std::string& k) { return camel + "camel_gallop/camel-gallop-" + (k.size() < 2 ? "0" : "") + k + ".off"; };
        c.source = eval::whole(eval::read(frame(en.a)));
        c.target = eval::read(frame(en.b));
        c.source_file = frame(en.a);
        c.target_file = frame(en.b);
        c.truth_of = read_map(camel + "camel_gallop/maps/" + en.a + "_to_" + en.b, 0);
        c.file_vertices = c.truth_of.size();
        c.truth_of.resize(c.source.mesh.number_of_vertices(), none); // repaired duplicates: no truth
      } else {
        c.name = "lion-cat";
        c.source = eval::whole(eval::read(camel + "lion-00.off"));
        c.target = eval::read(camel + "cat-00.off");
        c.source_file = camel + "lion-00.off";
        c.target_file = camel + "cat-00.off";
        c.truth_of = read_map(camel + "lion2cat", 0);
        c.truth_of.resize(c.source.mesh.number_of_vertices(), none);
      }
      for(auto& t : c.truth_of)
        if(t >= c.target.number_of_vertices()) t = none;
      if(!(o.extra_every > 1 && en.kind == "tosca" && en.order % o.extra_every != 0)) run_case(c, o);
      else {
        Options gsc_only = o;
        gsc_only.trims = "gsc";
        run_case(c, gsc_only);
      }
    }
  } catch(const std::exception& e) {
    std::cerr << "evaluate_isometric: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
