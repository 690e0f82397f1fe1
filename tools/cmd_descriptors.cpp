// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr descriptors: spectral, rigid and geodesic descriptors of a mesh's vertices.
#include "descriptor_sets.h"

#include <shapecorr/spectral/Laplace_beltrami_eigenbasis.h>
#include <shapecorr/spectral/spectral_signature_matrix.h>

#include <chrono>

namespace cli {
namespace {

namespace SP = shapecorr::parameters;

// Spectral signatures of every vertex, with an eigenbasis that may be loaded or saved.
int run_spectral(const Mesh& m, const Args& a, const std::string& type, const std::string& output) {
  const auto t0 = std::chrono::steady_clock::now();
  shapecorr::Laplace_beltrami_eigenbasis basis;
  if(a.has("load-eigenbasis")) {
    if(a.has("eigenpairs") || a.has("save-eigenbasis")) throw Usage_error("descriptors: --load-eigenbasis excludes --eigenpairs and --save-eigenbasis");
    basis = shapecorr::Laplace_beltrami_eigenbasis::load(a.get("load-eigenbasis"));
    if(basis.number_of_vertices() != m.number_of_vertices())
      throw shapecorr::Invalid_argument(a.get("load-eigenbasis") + ": eigenbasis of " + std::to_string(basis.number_of_vertices()) +
                                        " vertices, mesh has " + std::to_string(m.number_of_vertices()));
  } else {
    const std::size_t k = to_count(a.get("eigenpairs", "300"), "--eigenpairs", 1, 100000);
    basis = shapecorr::compute_laplace_beltrami_eigenbasis(m, std::min<std::size_t>(k, m.number_of_vertices()));
    if(a.has("save-eigenbasis")) basis.save(a.get("save-eigenbasis"));
  }
  const auto t1 = std::chrono::steady_clock::now();
  const Eigen::MatrixXd D = shapecorr::spectral_signature_matrix(basis, shapecorr::spectral_signature_from_string(type),
                                                                 SP::number_of_scales(to_count(a.get("scales", "100"), "--scales", 1, 10000)));
  const auto t2 = std::chrono::steady_clock::now();
  if(a.has("distance-to")) {
    const std::vector<std::size_t> v = parse_ids(a.get("distance-to"), m.number_of_vertices());
    const Eigen::VectorXd d = (D.rowwise() - D.row(static_cast<Eigen::Index>(v[0]))).rowwise().norm();
    write_values(output, m, std::vector<double>(d.data(), d.data() + d.size()), {v[0]});
  } else {
    if(extension(output) != "csv") throw Usage_error("descriptors are written as .csv (or use --distance-to V for a .ply)");
    std::ofstream out = open_output(output);
    out.precision(9);
    for(Eigen::Index i = 0; i < D.rows(); ++i) {
      for(Eigen::Index j = 0; j < D.cols(); ++j) out << (j ? "," : "") << D(i, j);
      out << "\n";
    }
  }
  if(verbose(a))
    std::cerr << "descriptors: " << type << ", " << D.cols() << " values per vertex from " << basis.number_of_eigenpairs()
              << " eigenpairs (eigenbasis " << std::chrono::duration<double>(t1 - t0).count() << " s, descriptors "
              << std::chrono::duration<double>(t2 - t1).count() << " s) -> " << output << "\n";
  return 0;
}

int run_descriptors(const Args& a) {
  const std::string type = a.require("type");
  check_descriptor_type(type, "--type");
  if(a.has("exact-area") && type != "face-spin-image" && type != "spin-contour")
    throw Usage_error("--exact-area applies to face-spin-image (and to the image of a spin-contour plot)");
  if((a.has("load-eigenbasis") || a.has("save-eigenbasis")) && !is_spectral(type))
    throw Usage_error("--load-eigenbasis and --save-eigenbasis apply to hks, wks and sihks");
  if(a.has("vertices") && is_spectral(type)) throw Usage_error("--vertices applies to rigid and geodesic descriptors (spectral ones are computed for all)");
  const Mesh m = read_mesh(a);
  const std::string output = a.require("output");
  if(a.has("plot")) {
    write_descriptor_plot(m, a, type, parse_ids(a.get("plot"), m.number_of_vertices())[0], output);
    return 0;
  }
  if(is_spectral(type)) return run_spectral(m, a, type, output);
  const auto t0 = std::chrono::steady_clock::now();
  if(a.has("distance-to")) { // the descriptor distance of every vertex to vertex V
    const std::size_t v = parse_ids(a.get("distance-to"), m.number_of_vertices())[0];
    const Descriptor_set s = compute_descriptor_set(m, all_ids(m.number_of_vertices()), type, a, m, "descriptors");
    const std::size_t undefined = write_values(output, m, distances_from(s, s, v), {v});
    if(verbose(a)) {
      std::cerr << "descriptors: " << type << " distance of every vertex to vertex " << v << ", " << seconds_since(t0) << " s -> " << output << "\n";
      if(undefined)
        std::cerr << "note: " << undefined << " vertices have no distance (one of the two descriptors is empty: a flat neighbourhood; an empty line in .csv, grey in .ply)\n";
    }
    return 0;
  }
  const std::vector<std::size_t> ids = a.has("vertices") ? parse_ids(a.get("vertices"), m.number_of_vertices()) : all_ids(m.number_of_vertices());
  if(extension(output) != "csv") throw Usage_error("descriptors are written as .csv (or --plot V --output FILE.png)");
  const Descriptor_set s = compute_descriptor_set(m, ids, type, a, m, "descriptors");
  std::ofstream out = open_output(output);
  out.precision(7);
  if(is_contour(type)) {
    out << "vertex,alpha,beta\n";
    for(std::size_t i = 0; i < ids.size(); ++i)
      for(const auto& p : s.contours[i].points()) out << ids[i] << "," << p[0] << "," << p[1] << "\n";
  } else {
    for(std::size_t i = 0; i < ids.size(); ++i) {
      out << ids[i];
      for(float v : s.images[i].values()) out << "," << v;
      out << "\n";
    }
  }
  if(verbose(a)) {
    std::cerr << "descriptors: " << type << " of " << ids.size() << " vertices, " << seconds_since(t0) << " s -> " << output << "\n";
    const std::size_t empty = static_cast<std::size_t>(std::count_if(s.contours.begin(), s.contours.end(), [](const shapecorr::Spin_contour& c) { return c.empty(); }));
    if(empty) std::cerr << "note: " << empty << " vertices have an empty contour (no descriptor: a flat neighbourhood): no rows\n";
  }
  return 0;
}

std::vector<Option> options() {
  std::vector<Option> o = {{"type", "NAME", "hks, wks, sihks, spin-image, face-spin-image, spin-contour, improved-spin-image, gsc, geodesic-spin-image"},
                           {"output", "FILE", ".csv (descriptors or distances), .ply (with --distance-to) or .png (with --plot)"},
                           {"vertices", "V[,V...]", "rigid and geodesic: only these vertices (default all)"},
                           {"distance-to", "V", "the descriptor distance of every vertex to vertex V instead (.csv values or .ply colours)"},
                           {"plot", "V", "spin image and contour of vertex V side by side (.png)"},
                           {"load-eigenbasis", "FILE", "hks|wks|sihks: use this saved eigenbasis"},
                           {"save-eigenbasis", "FILE", "hks|wks|sihks: save the computed eigenbasis"}};
  for(const Option& x : descriptor_options()) o.push_back(x);
  return with_mesh_reading_options(o);
}

} // namespace

const Command& descriptors_command() {
  static const Command c{
      "descriptors", "descriptors MESH --type NAME [options] --output FILE",
      "Spectral, rigid or geodesic descriptors of the vertices of MESH (--type NAME, see below). Spectral (hks, wks, sihks; from K Laplace-Beltrami eigenpairs): one "
      "comma-separated row per vertex. Rigid (thesis chapter 3: spin-image, face-spin-image, spin-contour, "
      "improved-spin-image; support and central radius are fractions of the extent, 2 x the largest distance from the "
      "area centroid): images as one row per vertex (id, then rows x columns bins, row-major), contours as "
      "vertex,alpha,beta rows normalized by the support (none for a vertex whose contour is empty: no descriptor, "
      "counted in a note). Geodesic (thesis chapter 4: gsc, geodesic-spin-image; "
      "coordinates (agd, gd), support and agd radius fractions of the geodesic diameter D; beta = gd / L, alpha = agd "
      "scaled by its range over the mesh): the same outputs. --plot V draws vertex V's image and contour; --distance-to V "
      "writes every vertex's descriptor distance to V.",
      options(), 1, 1, run_descriptors};
  return c;
}

} // namespace cli
