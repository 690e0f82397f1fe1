// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The shapecorr command-line program: one sub-command per capability of the library.
#include "cli_common.h"

#include <shapecorr/all.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cli {

const char* const usage = R"(shapecorr - shape correspondences from local descriptors to global registration

usage:
  shapecorr info MESH [--json]
      Validate MESH (OFF, OBJ, PLY, STL): size, components, boundaries, degenerate and non-manifold
      elements, isolated vertices. Exit 0 when the file could be read.
  shapecorr geodesics MESH --source V[,V...] [--method heat|exact|fmm] --output FILE
      Geodesic distance of every vertex to the nearest source (0-based vertex ids).
      FILE.csv: one distance per line, vertex order; FILE.ply: mesh coloured by distance.
  shapecorr sample MESH --count N [--metric geodesic|euclidean] [--seed S] [--output FILE]
      Furthest point sampling; one vertex id per line (stdout without --output).
  shapecorr agd MESH [--radius FRACTION] [--sources K] --output FILE(.csv|.ply)
      Average geodesic distance per vertex: global (K furthest-point sources, 0 = all vertices;
      default 100), or local within FRACTION x geodesic diameter.
  shapecorr descriptors MESH --type hks|wks|sihks [--eigenpairs K] [--scales N] --output FILE.csv
                         [--load-eigenbasis FILE | --save-eigenbasis FILE]
      Spectral descriptors of every vertex from K Laplace-Beltrami eigenpairs (default 300):
      one comma-separated row per vertex. With --distance-to V instead: the descriptor distance of
      every vertex to vertex V (FILE.csv: one per line; FILE.ply: mesh coloured by it, V marked).
  shapecorr descriptors MESH --type spin-image|face-spin-image|spin-contour|improved-spin-image
                         [--axis normal|central|local-central|shot] [--support F] [--rows R] [--cols C]
                         [--central-radius F] [--lrf-radius M] [--exact-area] [--vertices V,...]
                         --output FILE.csv
      Rigid descriptors (thesis chapter 3) of the listed vertices (default all). Support and
      central radius: fractions of the extent (2 x largest distance from the area centroid;
      defaults 1.0 and 0.1); SHOT frame radius in mean edge lengths (default 30); 120 x 60 samples.
      Images: one row per vertex (id, then rows x cols bins, row-major); contours: vertex,alpha,beta
      rows (normalized by the support). With --plot V --output FILE.png: the spin image (face-based
      for face-spin-image and spin-contour) and the Spin Contour of vertex V side by side.
      --exact-area: face-based images hold the exact surface area in each bin (Carmichael et
      al.'s exact method, slower) instead of sampled areas splatted bilinearly.
      With --distance-to V --output FILE.ply|.csv: the descriptor distance of every vertex to V.
  shapecorr descriptors MESH --type gsc|geodesic-spin-image [--support F] [--agd-radius F]
                         [--rows R] [--cols C] [--vertices V,...] --output FILE.csv
      Geodesic Spin Contour / geodesic spin image (thesis chapter 4): coordinates (agd, gd).
      Support L and agd radius r as fractions of the geodesic diameter D (defaults 0.4 and 0.15;
      --agd-radius 0: global agd); 64 x 64 samples; beta = gd / L, alpha = agd scaled by its
      range over the mesh (a match's source takes the target's D and scale). Same outputs
      as the Spin Contour, --plot V (gd grows downwards) and --distance-to V.
  shapecorr match SOURCE TARGET --descriptor NAME [--points N | --source-points FILE] --output FILE
                  [--lines FILE.obj|.ply] [--distance-fields] [descriptor options as above]
      NAME: spin-image, face-spin-image, spin-contour, improved-spin-image, gsc,
      geodesic-spin-image, hks, wks, sihks.
      Matches N furthest-point samples of SOURCE (default 100; or the ids in FILE) to the TARGET
      vertex of nearest descriptor; writes 'source_id target_id distance' lines (0-based). Support
      fractions refer to the TARGET's extent (gsc: the TARGET's geodesic diameter, so that a part
      of a shape matches the whole). --lines: both meshes side by side with match lines.
      Contours are compared by the exact L1 distance; from 32 sources on through prepared
      nearest-point indices (the same distances, each comparison ~15x cheaper).
      --distance-fields (spin-contour, gsc): compare the contours through their distance fields
      (approximate L1, at most 1/240 off per comparison, each about half an indexed one).
      --distance-view V: PREFIX_source.ply and PREFIX_target.ply, both shapes coloured by the
      descriptor distance to source vertex V (PREFIX: --distance-view-prefix, default FILE).
  shapecorr generate sphere|torus|grid [--subdivisions S] --output FILE
      Write a mesh generated by code (icosphere, torus, flat grid).
  shapecorr --help | --version

Reading repairs isolated vertices (removed) and polygons (triangulated); --repair-non-manifold
splits non-manifold elements. Errors: one line on stderr, exit code 1 (2 for bad usage).
)";

int cmd_info(const Args& a) {
  if(a.positional.empty()) throw Usage_error("missing MESH argument");
  const std::string path = a.positional[0];
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  shapecorr::read_polygon_soup_checked(path, points, polygons);
  const shapecorr::Mesh_report r = shapecorr::validate_polygon_soup(points, polygons);
  if(a.has("json")) {
    std::cout << "{\"file\": \"" << json_escape(path) << "\", \"vertices\": " << r.number_of_vertices
              << ", \"faces\": " << r.number_of_faces << ", \"connected_components\": " << r.connected_components
              << ", \"boundary_edges\": " << r.boundary_edges << ", \"non_triangle_faces\": " << r.non_triangle_faces
              << ", \"non_finite_vertices\": " << r.non_finite_vertices << ", \"degenerate_faces\": " << r.degenerate_faces
              << ", \"non_manifold_edges\": " << r.non_manifold_edges << ", \"non_manifold_vertices\": " << r.non_manifold_vertices
              << ", \"isolated_vertices\": " << r.isolated_vertices << ", \"area\": " << r.area
              << ", \"mean_edge_length\": " << r.mean_edge_length << ", \"bbox_diagonal\": " << r.bbox_diagonal
              << ", \"valid\": " << (r.is_valid() ? "true" : "false") << ", \"closed\": " << (r.is_closed() ? "true" : "false")
              << ", \"examples\": {";
    bool first = true;
    for(const auto& e : r.examples) {
      std::cout << (first ? "" : ", ") << "\"" << shapecorr::to_string(e.first) << "\": \"" << json_escape(e.second) << "\"";
      first = false;
    }
    std::cout << "}}\n";
  } else {
    std::cout << "file: " << path << "\n" << r.to_string();
  }
  return 0;
}

int cmd_geodesics(const Args& a) {
  Mesh m = read_mesh(a);
  const std::vector<std::size_t> ids = parse_ids(a.require("source"), m.number_of_vertices());
  const std::string output = a.require("output");
  const auto method = shapecorr::geodesic_method_from_string(a.get("method", "heat"));
  std::vector<vertex_descriptor> sources;
  for(std::size_t i : ids) sources.push_back(vertex_descriptor(static_cast<Mesh::size_type>(i)));
  auto dist = m.add_property_map<vertex_descriptor, double>("v:dist", 0.0).first;
  const auto t0 = std::chrono::steady_clock::now();
  shapecorr::compute_geodesic_distances(m, sources, dist, shapecorr::parameters::geodesic_method(method));
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<double> values(m.number_of_vertices());
  double dmax = 0;
  for(vertex_descriptor v : vertices(m)) {
    values[v.idx()] = dist[v];
    if(std::isfinite(dist[v])) dmax = std::max(dmax, dist[v]);
  }
  write_values(output, m, values, ids);
  if(!a.has("quiet"))
    std::cerr << "geodesics: " << ids.size() << " source(s), method " << a.get("method", "heat") << ", max distance " << dmax << ", "
              << secs << " s -> " << output << "\n";
  return 0;
}

int cmd_sample(const Args& a) {
  const Mesh m = read_mesh(a);
  const std::size_t count = to_count(a.require("count"), "--count");
  const unsigned seed = static_cast<unsigned>(to_count(a.get("seed", "0"), "--seed"));
  const std::string metric = a.get("metric", "geodesic");
  if(metric != "geodesic" && metric != "euclidean") throw Usage_error("--metric must be geodesic or euclidean");
  std::vector<vertex_descriptor> samples;
  shapecorr::furthest_point_sampling(m, count, std::back_inserter(samples),
                                     shapecorr::parameters::distance_metric(metric == "geodesic" ? shapecorr::Distance_metric::GEODESIC
                                                                                                 : shapecorr::Distance_metric::EUCLIDEAN)
                                         .random_seed(seed));
  std::ostringstream o;
  for(vertex_descriptor v : samples) o << v.idx() << "\n";
  if(a.has("output")) {
    std::ofstream out(a.get("output"));
    if(!out) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, a.get("output") + ": cannot open for writing");
    out << o.str();
  } else {
    std::cout << o.str();
  }
  return 0;
}

int cmd_agd(const Args& a) {
  Mesh m = read_mesh(a);
  const std::string output = a.require("output");
  auto agd = m.add_property_map<vertex_descriptor, double>("v:agd", 0.0).first;
  const auto t0 = std::chrono::steady_clock::now();
  std::string what;
  if(a.has("radius")) {
    const double fraction = to_double(a.get("radius"), "--radius");
    const double D = shapecorr::geodesic_diameter(m);
    shapecorr::compute_local_average_geodesic_distance(m, fraction * D, agd);
    what = "local agd, r = " + a.get("radius") + " D (D = " + std::to_string(D) + ")";
  } else {
    const std::size_t k = to_count(a.get("sources", "100"), "--sources");
    shapecorr::compute_average_geodesic_distance(m, agd, shapecorr::parameters::number_of_sources(k));
    what = "global agd from " + (k == 0 ? std::string("all") : std::to_string(k)) + " sources";
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<double> values(m.number_of_vertices());
  for(vertex_descriptor v : vertices(m)) values[v.idx()] = agd[v];
  write_values(output, m, values);
  if(!a.has("quiet")) std::cerr << "agd: " << what << ", " << secs << " s -> " << output << "\n";
  return 0;
}

int cmd_descriptors(const Args& a) {
  const std::string type = a.require("type");
  if(a.has("exact-area") && type != "face-spin-image" && type != "spin-contour")
    throw Usage_error("--exact-area applies to face-spin-image (and to the image of a spin-contour plot)");
  if(type == "spin-image" || type == "face-spin-image" || type == "spin-contour" || type == "improved-spin-image" || type == "gsc" ||
     type == "geodesic-spin-image")
    return cmd_rigid_descriptors(a);
  if(type != "hks" && type != "wks" && type != "sihks")
    throw Usage_error("--type must be hks, wks, sihks, spin-image, face-spin-image, spin-contour, improved-spin-image, gsc or geodesic-spin-image");
  const Mesh m = read_mesh(a);
  const std::string output = a.require("output");
  namespace SP = shapecorr::parameters;
  const auto t0 = std::chrono::steady_clock::now();
  shapecorr::Laplace_beltrami_eigenbasis basis;
  if(a.has("load-eigenbasis")) {
    basis = shapecorr::Laplace_beltrami_eigenbasis::load(a.get("load-eigenbasis"));
    if(basis.number_of_vertices() != m.number_of_vertices())
      throw shapecorr::Invalid_input(shapecorr::Mesh_defect::invalid_argument, a.get("load-eigenbasis") + ": eigenbasis of " +
                                                                                   std::to_string(basis.number_of_vertices()) + " vertices, mesh has " +
                                                                                   std::to_string(m.number_of_vertices()));
  } else {
    const std::size_t k = to_count(a.get("eigenpairs", "300"), "--eigenpairs");
    basis = shapecorr::compute_laplace_beltrami_eigenbasis(m, std::min<std::size_t>(k, m.number_of_vertices()));
    if(a.has("save-eigenbasis")) basis.save(a.get("save-eigenbasis"));
  }
  const auto t1 = std::chrono::steady_clock::now();
  const std::size_t scales = to_count(a.get("scales", "100"), "--scales");
  Eigen::MatrixXd D;
  if(type == "hks") D = shapecorr::heat_kernel_signature_matrix(basis, SP::number_of_scales(scales));
  else if(type == "wks") D = shapecorr::wave_kernel_signature_matrix(basis, SP::number_of_scales(scales));
  else D = shapecorr::scale_invariant_heat_kernel_signature_matrix(basis);
  const auto t2 = std::chrono::steady_clock::now();
  if(a.has("distance-to")) {
    const std::vector<std::size_t> v = parse_ids(a.get("distance-to"), m.number_of_vertices());
    const Eigen::VectorXd d = (D.rowwise() - D.row(static_cast<Eigen::Index>(v[0]))).rowwise().norm();
    write_values(output, m, std::vector<double>(d.data(), d.data() + d.size()), {v[0]});
  } else {
    if(extension(output) != "csv") throw Usage_error("descriptors are written as .csv (or use --distance-to V for a .ply)");
    std::ofstream out(output);
    if(!out) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, output + ": cannot open for writing");
    out.precision(9);
    for(Eigen::Index i = 0; i < D.rows(); ++i) {
      for(Eigen::Index j = 0; j < D.cols(); ++j) out << (j ? "," : "") << D(i, j);
      out << "\n";
    }
  }
  if(!a.has("quiet"))
    std::cerr << "descriptors: " << type << ", " << D.cols() << " values per vertex from " << basis.number_of_eigenpairs()
              << " eigenpairs (eigenbasis " << std::chrono::duration<double>(t1 - t0).count() << " s, descriptors "
              << std::chrono::duration<double>(t2 - t1).count() << " s) -> " << output << "\n";
  return 0;
}

int cmd_generate(const Args& a) {
  if(a.positional.empty()) throw Usage_error("generate: which shape? sphere, torus or grid");
  const std::string shape = a.positional[0], output = a.require("output");
  const int s = static_cast<int>(to_count(a.get("subdivisions", "4"), "--subdivisions"));
  Mesh m;
  if(shape == "sphere") shapecorr::make_icosphere(m, s);
  else if(shape == "torus") shapecorr::make_torus(m, 2.0, 0.7, 16 * (s + 1), 6 * (s + 1));
  else if(shape == "grid") shapecorr::make_grid(m, 8 * (s + 1), 8 * (s + 1));
  else throw Usage_error("unknown shape '" + shape + "' (sphere, torus, grid)");
  if(!CGAL::IO::write_polygon_mesh(output, m, CGAL::parameters::stream_precision(17)))
    throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, output + ": cannot write");
  if(!a.has("quiet")) std::cerr << "generate: " << shape << ", " << m.number_of_vertices() << " vertices -> " << output << "\n";
  return 0;
}

} // namespace cli

int main(int argc, char** argv) {
  if(argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" || std::string(argv[1]) == "help") {
    std::cout << cli::usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  if(cmd == "--version") {
    std::cout << "shapecorr 0.1.0\n";
    return 0;
  }
  using namespace cli;
  try {
    const Args a = parse(argc, argv, 2);
    if(a.has("help")) { std::cout << usage; return 0; }
    if(cmd == "info") return cmd_info(a);
    if(cmd == "geodesics") return cmd_geodesics(a);
    if(cmd == "sample") return cmd_sample(a);
    if(cmd == "agd") return cmd_agd(a);
    if(cmd == "descriptors") return cmd_descriptors(a);
    if(cmd == "generate") return cmd_generate(a);
    if(cmd == "match") return cmd_match(a);
    throw Usage_error("unknown command '" + cmd + "' (see shapecorr --help)");
  } catch(const Usage_error& e) {
    std::cerr << "shapecorr: " << e.what() << "\n";
    return 2;
  } catch(const shapecorr::Invalid_input& e) {
    std::cerr << "shapecorr: error: " << e.what() << " [" << shapecorr::to_string(e.defect()) << "]\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "shapecorr: error: " << e.what() << "\n";
    return 1;
  }
}
