// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr descriptors --type spin-image|face-spin-image|spin-contour|improved-spin-image, and
// shapecorr match (nearest-descriptor matching for every descriptor the program knows).
#include "cli_common.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/io.h>
#include <shapecorr/sampling.h>
#include <shapecorr/spectral.h>

#include <chrono>
#include <functional>
#include <memory>

namespace cli {
namespace {

namespace SP = shapecorr::parameters;
using shapecorr::Spin_axis;

bool is_rigid(const std::string& t) {
  return t == "spin-image" || t == "face-spin-image" || t == "spin-contour" || t == "improved-spin-image";
}
bool is_spectral(const std::string& t) { return t == "hks" || t == "wks" || t == "sihks"; }
bool is_geodesic(const std::string& t) { return t == "gsc" || t == "geodesic-spin-image"; }

Spin_axis parse_axis(const std::string& s, const std::string& type) {
  if(type == "improved-spin-image") {
    if(!s.empty() && s != "shot") throw Usage_error("improved-spin-image uses the SHOT frame axis (--axis shot)");
    return Spin_axis::SHOT_LRF;
  }
  if(s.empty() || s == "normal") return Spin_axis::NORMAL;
  if(s == "central") return Spin_axis::CENTRAL_DIRECTION;
  if(s == "local-central") return Spin_axis::LOCAL_CENTRAL_DIRECTION;
  if(s == "shot") return Spin_axis::SHOT_LRF;
  throw Usage_error("--axis must be normal, central, local-central or shot");
}

// The spin descriptor settings of the command line: support and central radius as fractions of
// the extent of `reference` (the target when matching), the SHOT radius in mesh resolutions.
std::unique_ptr<shapecorr::Spin_descriptors<Mesh>> make_spin(const Mesh& m, const Args& a, const std::string& type, const Mesh& reference) {
  const shapecorr::Spin_descriptors<Mesh> probe(reference);
  const double support = to_double(a.get("support", "1.0"), "--support") * probe.extent();
  const double central = to_double(a.get("central-radius", "0.1"), "--central-radius") * probe.extent();
  const double lrf = to_double(a.get("lrf-radius", "30"), "--lrf-radius") * probe.mesh_resolution();
  const std::size_t rows = to_count(a.get("rows", "120"), "--rows"), cols = to_count(a.get("cols", "60"), "--cols");
  return std::unique_ptr<shapecorr::Spin_descriptors<Mesh>>(new shapecorr::Spin_descriptors<Mesh>(
      m, SP::support_length(support).image_rows(rows).image_columns(cols).spin_axis(parse_axis(a.get("axis"), type))
             .central_radius(central).lrf_radius(lrf)));
}

// The face-based spin image: sampled areas with bilinear splatting, or (--exact-area) the exact
// area in each bin.
shapecorr::Spin_image face_image(const shapecorr::Spin_descriptors<Mesh>& sd, const shapecorr::Oriented_point& op, bool exact) {
  return exact ? sd.exact_face_spin_image(op) : sd.face_spin_image(op);
}

// The lengths that normalize the Geodesic Spin Contour: when matching, the target's, so that a
// part of a shape is described with the whole shape's lengths.
struct Geodesic_norm {
  bool set = false;
  double diameter = 0, offset = 0, scale = 0;
};

// The Geodesic Spin Contour settings of the command line: support and agd radius as fractions of
// the geodesic diameter; `norm` (when set) imposes D and the agd normalization, else it receives
// this mesh's.
std::unique_ptr<shapecorr::Geodesic_spin_descriptors<Mesh>> make_geodesic(const Mesh& m, const Args& a, Geodesic_norm* norm,
                                                                          const std::function<void(std::size_t, std::size_t)>& progress) {
  typedef shapecorr::Geodesic_spin_descriptors<Mesh> G;
  const double support = to_double(a.get("support", "0.4"), "--support"), radius = to_double(a.get("agd-radius", "0.15"), "--agd-radius");
  const std::size_t rows = to_count(a.get("rows", "64"), "--rows"), cols = to_count(a.get("cols", "64"), "--cols");
  const auto np = SP::support_fraction(support).agd_radius_fraction(radius).image_rows(rows).image_columns(cols).progress_callback(progress);
  std::unique_ptr<G> g;
  if(norm && norm->set) g.reset(new G(m, np.geodesic_diameter(norm->diameter).agd_offset(norm->offset).agd_scale(norm->scale)));
  else g.reset(new G(m, np));
  if(norm && !norm->set) *norm = {true, g->geodesic_diameter(), g->alpha_offset(), g->alpha_scale()};
  return g;
}

std::function<void(std::size_t, std::size_t)> reporter(const Args& a, const std::string& what) {
  if(a.has("quiet")) return {};
  auto last = std::make_shared<std::size_t>(0);
  return [what, last](std::size_t done, std::size_t total) {
    const std::size_t decile = 10 * done / std::max<std::size_t>(total, 1);
    if(decile > *last || done == total) {
      *last = decile;
      std::cerr << what << ": " << done << "/" << total << "\n";
    }
  };
}

std::vector<std::size_t> all_ids(std::size_t n) {
  std::vector<std::size_t> v(n);
  for(std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

// Descriptors of one kind for the vertices `ids` of `m`, as a type-erased set with its distance.
struct Descriptor_set {
  std::vector<shapecorr::Spin_image> images;
  std::vector<shapecorr::Spin_contour> contours;
  Eigen::MatrixXd rows; // spectral: one row per id
  std::size_t size() const { return std::max({images.size(), contours.size(), static_cast<std::size_t>(rows.rows())}); }
};

Descriptor_set compute_set(const Mesh& m, const std::vector<std::size_t>& ids, const std::string& type, const Args& a, const Mesh& reference,
                           const std::string& label, Geodesic_norm* norm = nullptr) {
  Descriptor_set s;
  if(is_spectral(type)) {
    const std::size_t k = std::min<std::size_t>(to_count(a.get("eigenpairs", "300"), "--eigenpairs"), m.number_of_vertices());
    const auto basis = shapecorr::compute_laplace_beltrami_eigenbasis(m, k);
    Eigen::MatrixXd D;
    const std::size_t scales = to_count(a.get("scales", "100"), "--scales");
    if(type == "hks") D = shapecorr::heat_kernel_signature_matrix(basis, SP::number_of_scales(scales));
    else if(type == "wks") D = shapecorr::wave_kernel_signature_matrix(basis, SP::number_of_scales(scales));
    else D = shapecorr::scale_invariant_heat_kernel_signature_matrix(basis);
    s.rows.resize(static_cast<Eigen::Index>(ids.size()), D.cols());
    for(std::size_t i = 0; i < ids.size(); ++i) s.rows.row(static_cast<Eigen::Index>(i)) = D.row(static_cast<Eigen::Index>(ids[i]));
    return s;
  }
  if(is_geodesic(type)) {
    const auto gs = make_geodesic(m, a, norm, reporter(a, label + " (agd)"));
    if(type == "gsc") s.contours = gs->geodesic_spin_contours(ids, reporter(a, label));
    else s.images = gs->geodesic_spin_images(ids, reporter(a, label));
    return s;
  }
  const auto sd = make_spin(m, a, type, reference);
  std::vector<shapecorr::Oriented_point> ops;
  for(std::size_t i : ids) ops.push_back(sd->oriented_point(vertex_descriptor(static_cast<Mesh::size_type>(i))));
  const auto progress = reporter(a, label);
  if(type == "spin-contour")
    s.contours = sd->for_each_point<shapecorr::Spin_contour>(ops, [&](const auto& op) { return sd->spin_contour(op); }, progress);
  else if(type == "face-spin-image")
    s.images = sd->for_each_point<shapecorr::Spin_image>(ops, [&](const auto& op) { return face_image(*sd, op, a.has("exact-area")); }, progress);
  else
    s.images = sd->for_each_point<shapecorr::Spin_image>(ops, [&](const auto& op) { return sd->spin_image(op); }, progress);
  return s;
}

// The contours prepared for comparisons (distance fields or nearest-point indices), in parallel.
template <typename Prepared>
std::vector<Prepared> prepare(const std::vector<shapecorr::Spin_contour>& c) {
  std::vector<Prepared> f(c.size());
  shapecorr::internal::parallel_for(c.size(), 0, [&](std::size_t i, unsigned) { f[i] = Prepared(c[i]); });
  return f;
}

// Nearest descriptors; contours by the exact L1 distance (from nearest-point indices once there
// are enough sources to repay preparing them: the same distances), or (fields) the approximate
// one of their distance fields.
std::vector<shapecorr::Descriptor_match> match_sets(const Descriptor_set& s, const Descriptor_set& t, bool fields) {
  if(!s.contours.empty() && fields)
    return shapecorr::match_descriptors(prepare<shapecorr::Contour_distance_field>(s.contours), prepare<shapecorr::Contour_distance_field>(t.contours),
                                        shapecorr::Approximate_contour_l1_distance());
  if(s.contours.size() >= 32)
    return shapecorr::match_descriptors(prepare<shapecorr::Contour_nearest_point_index>(s.contours),
                                        prepare<shapecorr::Contour_nearest_point_index>(t.contours), shapecorr::Indexed_contour_l1_distance());
  if(!s.contours.empty()) return shapecorr::match_descriptors(s.contours, t.contours, shapecorr::Contour_l1_distance());
  if(!s.images.empty()) return shapecorr::match_descriptors(s.images, t.images, shapecorr::Spin_image_distance());
  std::vector<Eigen::VectorXd> a, b;
  for(Eigen::Index i = 0; i < s.rows.rows(); ++i) a.push_back(s.rows.row(i).transpose());
  for(Eigen::Index i = 0; i < t.rows.rows(); ++i) b.push_back(t.rows.row(i).transpose());
  return shapecorr::match_descriptors(a, b, [](const Eigen::VectorXd& x, const Eigen::VectorXd& y) { return (x - y).norm(); });
}

// The descriptor distance from element k of `from` to every element of `to` (spectral: Euclidean;
// images: 1 - correlation; contours: L1).
std::vector<double> distances_to(const Descriptor_set& from, const Descriptor_set& to, std::size_t k) {
  std::vector<double> d(to.size());
  shapecorr::internal::parallel_for(to.size(), 0, [&](std::size_t i, unsigned) {
    if(!from.contours.empty()) d[i] = shapecorr::contour_l1_distance(from.contours[k], to.contours[i]);
    else if(!from.images.empty()) d[i] = shapecorr::Spin_image_distance()(from.images[k], to.images[i]);
    else d[i] = (from.rows.row(static_cast<Eigen::Index>(k)) - to.rows.row(static_cast<Eigen::Index>(i))).norm();
  });
  return d;
}

} // namespace

int cmd_rigid_descriptors(const Args& a) {
  const Mesh m = read_mesh(a);
  const std::string type = a.require("type"), output = a.require("output");
  const auto t0 = std::chrono::steady_clock::now();
  if(a.has("plot") && is_geodesic(type)) {
    const std::size_t v = parse_ids(a.get("plot"), m.number_of_vertices())[0];
    if(extension(output) != "png") throw Usage_error("--plot writes a .png picture");
    const auto gs = make_geodesic(m, a, nullptr, {});
    const vertex_descriptor vd(static_cast<Mesh::size_type>(v));
    const shapecorr::Spin_image img = gs->geodesic_spin_image(vd);
    const shapecorr::Spin_contour c = gs->geodesic_spin_contour(vd);
    shapecorr::write_spin_descriptor_plot(output, img, c);
    if(!a.has("quiet"))
      std::cerr << "descriptors: vertex " << v << ", geodesic spin image " << img.rows() << "x" << img.cols() << " and its Geodesic Spin Contour ("
                << c.size() << " points; gd grows downwards, agd to the right) -> " << output << "\n";
    return 0;
  }
  if(a.has("distance-to")) { // the descriptor distance of every vertex to vertex V
    const std::size_t v = parse_ids(a.get("distance-to"), m.number_of_vertices())[0];
    const Descriptor_set s = compute_set(m, all_ids(m.number_of_vertices()), type, a, m, "descriptors");
    write_values(output, m, distances_to(s, s, v), {v});
    if(!a.has("quiet"))
      std::cerr << "descriptors: " << type << " distance of every vertex to vertex " << v << ", "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s -> " << output << "\n";
    return 0;
  }
  if(a.has("plot")) {
    const std::size_t v = parse_ids(a.get("plot"), m.number_of_vertices())[0];
    if(extension(output) != "png") throw Usage_error("--plot writes a .png picture");
    const auto sd = make_spin(m, a, type, m);
    const auto op = sd->oriented_point(vertex_descriptor(static_cast<Mesh::size_type>(v)));
    const shapecorr::Spin_image img = type == "spin-image" || type == "improved-spin-image" ? sd->spin_image(op) : face_image(*sd, op, a.has("exact-area"));
    const shapecorr::Spin_contour c = sd->spin_contour(op);
    shapecorr::write_spin_descriptor_plot(output, img, c);
    if(!a.has("quiet"))
      std::cerr << "descriptors: vertex " << v << ", " << (type == "spin-image" || type == "improved-spin-image" ? "spin image" : a.has("exact-area") ? "face-based spin image (exact areas)" : "face-based spin image")
                << " " << img.rows() << "x" << img.cols() << " and its Spin Contour (" << c.size() << " points)"
                << (op.fell_back_to_normal ? ", axis fell back to the normal" : "") << " -> " << output << "\n";
    return 0;
  }
  const std::vector<std::size_t> ids = a.has("vertices") ? parse_ids(a.get("vertices"), m.number_of_vertices()) : all_ids(m.number_of_vertices());
  if(extension(output) != "csv") throw Usage_error("descriptors are written as .csv (or --plot V --output FILE.png)");
  const Descriptor_set s = compute_set(m, ids, type, a, m, "descriptors");
  std::ofstream out(output);
  if(!out) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, output + ": cannot open for writing");
  out.precision(7);
  if(type == "spin-contour" || type == "gsc") {
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
  if(!a.has("quiet"))
    std::cerr << "descriptors: " << type << " of " << ids.size() << " vertices, "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s -> " << output << "\n";
  return 0;
}

int cmd_match(const Args& a) {
  if(a.positional.size() < 2) throw Usage_error("match needs SOURCE and TARGET meshes");
  const Mesh source = read_mesh(a, 0), target = read_mesh(a, 1);
  const std::string type = a.require("descriptor"), output = a.require("output");
  if(!is_rigid(type) && !is_spectral(type) && !is_geodesic(type))
    throw Usage_error("--descriptor must be spin-image, face-spin-image, spin-contour, improved-spin-image, gsc, geodesic-spin-image, hks, wks or sihks");
  if(a.has("exact-area") && type != "face-spin-image") throw Usage_error("--exact-area applies to --descriptor face-spin-image");
  if(a.has("distance-fields") && type != "spin-contour" && type != "gsc") throw Usage_error("--distance-fields applies to --descriptor spin-contour or gsc");
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::size_t> ids;
  if(a.has("source-points")) {
    std::ifstream in(a.get("source-points"));
    if(!in) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, a.get("source-points") + ": cannot read");
    std::string tok;
    while(in >> tok) {
      const std::size_t v = to_count(tok, "source point");
      if(v >= source.number_of_vertices())
        throw shapecorr::Invalid_input(shapecorr::Mesh_defect::invalid_argument, "source point " + tok + " out of range");
      ids.push_back(v);
    }
    if(ids.empty()) throw Usage_error(a.get("source-points") + ": no vertex ids");
  } else {
    const std::size_t n = std::min<std::size_t>(to_count(a.get("points", "100"), "--points"), source.number_of_vertices());
    std::vector<vertex_descriptor> samples;
    shapecorr::furthest_point_sampling(source, n, std::back_inserter(samples), SP::random_seed(static_cast<unsigned>(to_count(a.get("seed", "0"), "--seed"))));
    for(auto v : samples) ids.push_back(v.idx());
  }
  Geodesic_norm norm; // the target's, imposed on the source
  const Descriptor_set t = compute_set(target, all_ids(target.number_of_vertices()), type, a, target, "target descriptors", &norm);
  const Descriptor_set s = compute_set(source, ids, type, a, target, "source descriptors", &norm);
  const auto t1 = std::chrono::steady_clock::now();
  const std::vector<shapecorr::Descriptor_match> matches = match_sets(s, t, a.has("distance-fields"));
  std::ofstream out(output);
  if(!out) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, output + ": cannot open for writing");
  out.precision(9);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for(const auto& m : matches) {
    out << ids[m.source] << " " << m.target << " " << m.distance << "\n";
    pairs.emplace_back(ids[m.source], m.target);
  }
  if(a.has("lines")) shapecorr::write_correspondences(a.get("lines"), source, target, pairs);
  if(a.has("distance-view")) { // the descriptor distance to one source vertex on both shapes
    const std::size_t v = parse_ids(a.get("distance-view"), source.number_of_vertices())[0];
    const std::string prefix = a.get("distance-view-prefix", output);
    const Descriptor_set all_source = compute_set(source, all_ids(source.number_of_vertices()), type, a, target, "distance view (source)", &norm);
    write_values(prefix + "_source.ply", source, distances_to(all_source, all_source, v), {v});
    const std::vector<double> dt = distances_to(all_source, t, v);
    const std::size_t best = static_cast<std::size_t>(std::min_element(dt.begin(), dt.end()) - dt.begin());
    write_values(prefix + "_target.ply", target, dt, {best});
    if(!a.has("quiet"))
      std::cerr << "match: distance to source vertex " << v << " -> " << prefix << "_source.ply, " << prefix << "_target.ply (marked: the nearest target vertex "
                << best << ")\n";
  }
  if(!a.has("quiet"))
    std::cerr << "match: " << type << ", " << ids.size() << " source points against " << target.number_of_vertices() << " target vertices (descriptors "
              << std::chrono::duration<double>(t1 - t0).count() << " s, matching "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count() << " s) -> " << output
              << (a.has("lines") ? " and " + a.get("lines") : std::string()) << "\n";
  return 0;
}

} // namespace cli
