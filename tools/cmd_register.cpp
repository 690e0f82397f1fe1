// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr register: rigid alignment of SOURCE to TARGET, optionally followed by NICPS; the
// registered source, its distance map and a JSON report with the distances before and after.
#include "cli_common.h"
#include "landmarks.h"

#include <shapecorr/evaluation.h>
#include <shapecorr/registration.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

namespace cli {
namespace {

// `mesh` coloured by the distance of each of its vertices to `target`: a coloured PLY (.ply), or
// a picture of it from both sides with a colour bar (.png).
void write_distance_map(const std::string& path, Mesh& mesh, const Mesh& target, const std::string& title) {
  auto d = mesh.add_property_map<vertex_descriptor, double>("v:distance", 0.0).first;
  shapecorr::compute_distances_to_surface(mesh, target, d);
  std::vector<double> values;
  for(vertex_descriptor v : vertices(mesh)) values.push_back(d[v]);
  mesh.remove_property_map(d);
  if(extension(path) == "png") {
    shapecorr::Mesh_picture_options o;
    o.title = title;
    shapecorr::write_colored_mesh_png(path, mesh, values, o);
  } else {
    shapecorr::write_colored_ply(path, mesh, values);
  }
}

nlohmann::json distances_json(const shapecorr::Surface_distance& d) {
  return {{"l1", d.l1}, {"l2", d.l2}, {"lmax", d.lmax}, {"error_bound", d.error_bound}};
}

int run_register(const Args& a) {
  Mesh source = read_mesh(a, 0);
  const Mesh target = read_mesh(a, 1);
  const std::string output = a.require("output");
  const std::string pre = a.get("pre-align", a.has("landmarks") ? "landmarks" : "pca");
  shapecorr::Rigid_initialization init;
  if(pre == "pca") init = shapecorr::Rigid_initialization::PRINCIPAL_AXES;
  else if(pre == "landmarks") init = shapecorr::Rigid_initialization::LANDMARKS;
  else if(pre == "none") init = shapecorr::Rigid_initialization::NONE;
  else throw Usage_error("register: --pre-align must be pca, landmarks or none");
  if(init == shapecorr::Rigid_initialization::LANDMARKS && !a.has("landmarks"))
    throw Usage_error("register: --pre-align landmarks needs --landmarks SOURCE_LANDMARKS TARGET_LANDMARKS");
  const std::string method = a.get("method", "rigid");
  if(method != "rigid" && method != "nicps" && method != "andresen" && method != "pauly" && method != "cpd" && method != "gmm-l2")
    throw Usage_error("register: --method must be rigid, nicps, andresen, pauly, cpd or gmm-l2");
  const bool nonrigid = method != "rigid";
  const std::string regularizer = a.get("regularizer", "combinatorial");
  shapecorr::Nicps_regularizer reg;
  if(regularizer == "combinatorial") reg = shapecorr::Nicps_regularizer::COMBINATORIAL_LAPLACIAN;
  else if(regularizer == "cotangent") reg = shapecorr::Nicps_regularizer::COTANGENT_LAPLACIAN;
  else if(regularizer == "edge") reg = shapecorr::Nicps_regularizer::EDGE;
  else throw Usage_error("register: --regularizer must be combinatorial, cotangent or edge");
  if(method != "nicps" && a.has("regularizer")) throw Usage_error("register: --regularizer applies to --method nicps");
  const std::string metric = a.get("metric", "point-to-plane");
  if(metric != "point-to-plane" && metric != "point-to-point") throw Usage_error("register: --metric must be point-to-plane or point-to-point");
  double max_pair = std::numeric_limits<double>::infinity();
  if(a.has("max-pair-distance")) {
    if(method != "nicps") throw Usage_error("register: --max-pair-distance applies to --method nicps");
    max_pair = to_double(a.get("max-pair-distance"), "register: --max-pair-distance", 0, 1e300, true);
  }
  // each method's own default bound (andresen: diffusion steps; gmm-l2: L-BFGS iterations per level)
  const std::string default_iterations = method == "andresen" ? "500" : method == "cpd" ? "150" : "50";
  const std::size_t iterations = to_count(a.get("iterations", default_iterations), "--iterations", 0, method == "rigid" || method == "andresen" ? 100000 : 10000);
  for(const char* map : {"distance-map", "distance-map-before"})
    if(a.has(map) && extension(a.get(map)) != "ply" && extension(a.get(map)) != "png")
      throw Usage_error(std::string("register: --") + map + " must end in .ply (coloured mesh) or .png (picture)");
  const std::string ext = extension(output);
  if(ext != "ply" && ext != "off" && ext != "obj" && ext != "stl") throw Usage_error("register: --output must end in .ply, .off, .obj or .stl");

  Landmarks ls, lt;
  if(a.has("landmarks")) {
    ls = read_landmarks(a.values("landmarks")[0]);
    lt = read_landmarks(a.values("landmarks")[1]);
    pair_landmarks(ls, lt);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const shapecorr::Surface_distance before = shapecorr::surface_distance(source, target);
  if(a.has("distance-map-before")) write_distance_map(a.get("distance-map-before"), source, target, "distance to the target before");
  namespace SP = shapecorr::parameters;
  const auto np = SP::rigid_initialization(init)
                      .allow_scaling(a.has("scale"))
                      .icp_metric(metric == "point-to-plane" ? shapecorr::Icp_metric::POINT_TO_PLANE : shapecorr::Icp_metric::POINT_TO_POINT)
                      .number_of_iterations(method == "rigid" ? iterations : std::size_t(50));
  const shapecorr::Rigid_alignment_report r = init == shapecorr::Rigid_initialization::LANDMARKS
                                                  ? shapecorr::align_rigidly(source, target, np.landmark_points(ls.points), SP::landmark_points(lt.points))
                                                  : shapecorr::align_rigidly(source, target, np);
  shapecorr::apply_transform(source, r.transform);
  const shapecorr::Surface_distance after_rigid = shapecorr::surface_distance(source, target);
  std::string stop;                                    // non-rigid: why the method stopped
  std::vector<nlohmann::json> per_iteration;            // non-rigid: one record per iteration
  std::vector<std::size_t> steer_vertex; // non-rigid: the source vertex that carries each landmark (NICPS: steered by it)
  if(nonrigid) {
    std::vector<std::pair<std::size_t, Eigen::Vector3d>> steer;
    for(std::size_t i = 0; i < ls.points.size(); ++i) {
      const Eigen::Vector3d p = r.transform(Eigen::Vector3d(ls.points[i].x(), ls.points[i].y(), ls.points[i].z()));
      std::size_t best = 0;
      double bd = std::numeric_limits<double>::infinity();
      for(vertex_descriptor v : vertices(source)) {
        const double d = (Eigen::Vector3d(source.point(v).x(), source.point(v).y(), source.point(v).z()) - p).squaredNorm();
        if(d < bd) bd = d, best = v.idx();
      }
      steer.emplace_back(best, Eigen::Vector3d(lt.points[i].x(), lt.points[i].y(), lt.points[i].z()));
      steer_vertex.push_back(best);
    }
    const bool show = verbose(a);
    auto fitted = source.add_property_map<vertex_descriptor, K::Point_3>("v:fitted").first;
    if(method == "nicps") {
      // landmarks steer the fit: each source landmark's nearest vertex of the (moved) source
      const std::function<bool(const shapecorr::Nicps_iteration_record&)> progress = [&](const shapecorr::Nicps_iteration_record& it) {
        if(show)
          std::cerr << "nicps: iteration " << it.iteration + 1 << "/" << iterations << ", alpha " << it.alpha << ", pairs " << it.forward_pairs << " + "
                    << it.inverse_pairs << ", rms distance " << it.rms_distance << "\n";
        per_iteration.push_back({{"iteration", it.iteration}, {"alpha", it.alpha}, {"forward_pairs", it.forward_pairs}, {"inverse_pairs", it.inverse_pairs},
                                 {"energy", it.energy}, {"rms_distance", it.rms_distance}, {"step", it.step}});
        return true;
      };
      stop = shapecorr::to_string(shapecorr::nicps(source, target, fitted,
                                                   SP::nicps_regularizer(reg)
                                                       .number_of_iterations(iterations)
                                                       .landmark_correspondences(steer)
                                                       .maximum_pair_distance(max_pair)
                                                       .iteration_callback(progress))
                                      .stop);
    } else {
      const std::function<bool(const shapecorr::Iteration_record&)> progress = [&](const shapecorr::Iteration_record& it) {
        // andresen's steps are many and cheap: a line every 50
        if(show && (method != "andresen" || it.iteration % 50 == 49))
          std::cerr << method << ": iteration " << it.iteration + 1 << ", energy " << it.energy << ", rms distance " << it.rms_distance << "\n";
        per_iteration.push_back({{"iteration", it.iteration}, {"pairs", it.pairs}, {"energy", it.energy}, {"rms_distance", it.rms_distance}, {"step", it.step}});
        return true;
      };
      const auto np_fit = SP::number_of_iterations(iterations).iteration_callback(progress);
      shapecorr::Registration_report br;
      if(method == "andresen") br = shapecorr::andresen_registration(source, target, fitted, np_fit);
      else if(method == "pauly") br = shapecorr::pauly_registration(source, target, fitted, np_fit);
      else if(method == "cpd") br = shapecorr::cpd_registration(source, target, fitted, np_fit);
      else br = shapecorr::gmm_l2_registration(source, target, fitted, np_fit);
      stop = shapecorr::to_string(br.stop);
    }
    for(vertex_descriptor v : vertices(source)) source.point(v) = fitted[v];
    source.remove_property_map(fitted);
  }
  const shapecorr::Surface_distance after = shapecorr::surface_distance(source, target);
  const double secs = seconds_since(t0);
  if(!CGAL::IO::write_polygon_mesh(output, source, CGAL::parameters::stream_precision(17)))
    throw shapecorr::Output_error("register: cannot write '" + output + "'");

  std::vector<double> lm_before, lm_after, lm_after_rigid;
  if(!ls.points.empty()) {
    lm_before = shapecorr::landmark_distances(ls.points, lt.points);
    std::vector<K::Point_3> rigid;
    for(const auto& p : ls.points) {
      const Eigen::Vector3d q = r.transform(Eigen::Vector3d(p.x(), p.y(), p.z()));
      rigid.emplace_back(q.x(), q.y(), q.z());
    }
    lm_after_rigid = shapecorr::landmark_distances(rigid, lt.points);
    std::vector<K::Point_3> moved; // rigid: the landmarks moved; non-rigid: their vertices after the fit
    for(std::size_t i = 0; i < ls.points.size(); ++i) {
      const auto& p = ls.points[i];
      const Eigen::Vector3d q = r.transform(Eigen::Vector3d(p.x(), p.y(), p.z()));
      moved.push_back(nonrigid ? source.point(vertex_descriptor(static_cast<Mesh::size_type>(steer_vertex[i]))) : K::Point_3(q.x(), q.y(), q.z()));
    }
    lm_after = shapecorr::landmark_distances(moved, lt.points);
  }
  if(a.has("distance-map")) write_distance_map(a.get("distance-map"), source, target, "distance to the target after " + method);
  if(a.has("report")) {
    nlohmann::json j;
    j["source"] = a.positional[0];
    j["target"] = a.positional[1];
    j["method"] = method;
    if(method == "nicps") j["regularizer"] = regularizer;
    if(nonrigid) {
      j["nonrigid_stop"] = stop;
      j["nonrigid_per_iteration"] = per_iteration;
    }
    j["pre_align"] = pre;
    j["metric"] = metric;
    j["scale_allowed"] = a.has("scale");
    std::vector<std::vector<double>> m(4, std::vector<double>(4));
    const Eigen::Matrix4d M = r.transform.matrix();
    for(int i = 0; i < 4; ++i)
      for(int k = 0; k < 4; ++k) m[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = M(i, k);
    j["transform"] = m;
    j["scale"] = r.transform.scale;
    j["starts_tried"] = r.starts_tried;
    j["winning_start"] = r.winning_start;
    j["stop"] = shapecorr::to_string(r.stop);
    j["iterations"] = r.iterations.size();
    nlohmann::json its = nlohmann::json::array();
    for(const auto& it : r.iterations)
      its.push_back({{"iteration", it.iteration}, {"pairs", it.pairs}, {"energy", it.energy}, {"rms_distance", it.rms_distance}, {"step", it.step}});
    j["per_iteration"] = its;
    j["distance_before"] = distances_json(before);
    j["distance_after"] = distances_json(after);
    if(nonrigid) j["distance_after_rigid"] = distances_json(after_rigid);
    if(!lm_before.empty()) {
      j["landmark_ids"] = ls.ids;
      j["landmark_distances_before"] = lm_before;
      if(nonrigid) j["landmark_distances_after_rigid"] = lm_after_rigid;
      j["landmark_distances_after"] = lm_after;
    }
    j["seconds"] = secs;
    std::ofstream out = open_output(a.get("report"));
    out << j.dump(2) << "\n";
  }
  if(verbose(a)) {
    if(nonrigid)
      std::cerr << "register: " << method << (method == "nicps" ? " (" + regularizer + ")" : std::string()) << ", " << per_iteration.size() << " iterations (" << stop << ")\n";
    std::cerr << "register: " << (nonrigid ? "rigid alignment" : "rigid") << " (" << pre << (a.has("scale") ? ", scale" : "") << ", " << metric << "), " << r.iterations.size()
              << " ICP iterations (" << shapecorr::to_string(r.stop) << ", start " << r.winning_start + 1 << " of " << r.starts_tried
              << (nonrigid ? "), then " + method : std::string(")")) << "; l2 " << before.l2 << " -> " << after.l2 << ", lmax " << before.lmax << " -> " << after.lmax;
    if(!lm_after.empty()) {
      double mb = 0, ma = 0;
      for(std::size_t i = 0; i < lm_after.size(); ++i) mb += lm_before[i] / static_cast<double>(lm_after.size()), ma += lm_after[i] / static_cast<double>(lm_after.size());
      std::cerr << "; mean landmark distance " << mb << " -> " << ma;
    }
    std::cerr << "; " << secs << " s -> " << output << "\n";
  }
  return 0;
}

int run_distance(const Args& a) {
  Mesh mesh = read_mesh(a, 0);
  const Mesh target = read_mesh(a, 1);
  if(a.has("map") && extension(a.get("map")) != "ply" && extension(a.get("map")) != "png")
    throw Usage_error("distance: --map must end in .ply (coloured mesh) or .png (picture)");
  const shapecorr::Symmetric_surface_distance d = shapecorr::symmetric_surface_distance(mesh, target);
  if(a.has("map")) write_distance_map(a.get("map"), mesh, target, "distance to the target");
  if(a.has("json")) {
    nlohmann::json j;
    j["mesh"] = a.positional[0];
    j["target"] = a.positional[1];
    j["mesh_to_target"] = distances_json(d.forward);
    j["target_to_mesh"] = distances_json(d.backward);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << "mesh -> target: l1 " << d.forward.l1 << ", l2 " << d.forward.l2 << ", lmax " << d.forward.lmax << "\n"
              << "target -> mesh: l1 " << d.backward.l1 << ", l2 " << d.backward.l2 << ", lmax " << d.backward.lmax << "\n";
  }
  return 0;
}

} // namespace

const Command& register_command() {
  static const Command c{
      "register",
      "register SOURCE TARGET --output FILE [--method rigid|nicps|andresen|pauly|cpd|gmm-l2] [--pre-align pca|landmarks|none] [--landmarks S T] [options]",
      "Registers SOURCE (the template) to TARGET (thesis chapter 6). Rigid: an initialization from principal axes "
      "(default; every proper sign choice tried), landmark pairs (default when landmark files are given) or none, "
      "then trimmed ICP. NICPS: the rigid alignment, then the non-rigid fit that keeps SOURCE's connectivity "
      "(landmark pairs, when given, steer it; a progress line per iteration). andresen, pauly, cpd, gmm-l2: the rigid alignment, "
      "then the thesis's baselines (Andresen & Nielsen 2001, Pauly et al. 2005, coherent point drift, GMM-L2 with thin-plate "
      "splines) with their defaults; landmarks only measure them. Writes the registered SOURCE to FILE "
      "(.ply, .off, .obj, .stl); a summary line on stderr (surface distances l2 and lmax before and after, landmark "
      "distances: rigid, the landmarks moved; non-rigid, the vertices nearest to them carried by the fit). Landmark files: the JSON of ../shared/data/vertebrae (a list of "
      "{\"id\", \"coordinates\"}, paired by id) or text, one 'x y z' per line.",
      with_mesh_reading_options({{"output", "FILE", "the registered source mesh"},
                                 {"method", "rigid|nicps|andresen|pauly|cpd|gmm-l2", "rigid alignment only (default), or followed by a non-rigid method"},
                                 {"regularizer", "combinatorial|cotangent|edge", "NICPS's regularizer (default combinatorial)"},
                                 {"pre-align", "pca|landmarks|none", "initialization (default pca, landmarks with landmark files)"},
                                 {"landmarks", "S T", "landmark files of SOURCE and of TARGET (JSON or text; paired by id, else by order)"},
                                 {"scale", "", "also a uniform scale (a similarity)"},
                                 {"metric", "point-to-plane|point-to-point", "the ICP distance (default point-to-plane)"},
                                 {"max-pair-distance", "D", "NICPS drops pairs longer than D (mesh units; default none): outliers, extra parts"},
                                 {"iterations", "N", "iterations of the method, at most: ICP per start (50), NICPS (50), andresen's diffusion steps (500), pauly (50), cpd (150), gmm-l2 per level (50)"},
                                 {"distance-map", "FILE", "the registered source coloured by its distance to TARGET: .ply, or .png (a picture of both sides, colour bar)"},
                                 {"distance-map-before", "FILE", "SOURCE as given, coloured by its distance to TARGET (.ply or .png)"},
                                 {"report", "FILE.json", "transform, iterations, surface and landmark distances before and after"}}),
      2, 2, run_register};
  return c;
}

const Command& distance_command() {
  static const Command c{"distance", "distance MESH TARGET [--json] [--map FILE]",
                         "Surface distances between MESH and TARGET (thesis chapter 6): l1 (mean), l2 (root mean square) and "
                         "lmax (largest) distance of the points of MESH to the surface TARGET, integrated over MESH's area, and "
                         "the same from TARGET to MESH.",
                         with_mesh_reading_options({{"json", "", "one JSON object on stdout instead of text"},
                                                    {"map", "FILE", "MESH coloured by its distance to TARGET: .ply, or .png (a picture of both sides)"}}),
                         2, 2, run_distance};
  return c;
}

} // namespace cli
