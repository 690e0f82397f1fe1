// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "descriptor_sets.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/io/write_spin_descriptor_plot.h>
#include <shapecorr/spectral.h>

#include <functional>
#include <memory>

namespace cli {
namespace {

namespace SP = shapecorr::parameters;
using shapecorr::Spin_axis;

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
  const double support = to_double(a.get("support", "1.0"), "--support", 0, 10, true) * probe.extent();
  const double central = to_double(a.get("central-radius", "0.1"), "--central-radius", 0, 10, true) * probe.extent();
  const double lrf = to_double(a.get("lrf-radius", "30"), "--lrf-radius", 0, 1e6, true) * probe.mesh_resolution();
  const std::size_t rows = to_count(a.get("rows", "120"), "--rows", 1, max_bins), columns = to_count(a.get("columns", "60"), "--columns", 1, max_bins);
  return std::unique_ptr<shapecorr::Spin_descriptors<Mesh>>(new shapecorr::Spin_descriptors<Mesh>(
      m, SP::support_length(support).image_rows(rows).image_columns(columns).spin_axis(parse_axis(a.get("axis"), type))
             .central_radius(central).lrf_radius(lrf)));
}

// The face-based spin image: sampled areas with bilinear splatting, or (--exact-area) the exact
// area in each bin.
shapecorr::Spin_image face_image(const shapecorr::Spin_descriptors<Mesh>& sd, const shapecorr::Oriented_point& op, bool exact) {
  return exact ? sd.exact_face_spin_image(op) : sd.face_spin_image(op);
}

std::function<void(std::size_t, std::size_t)> reporter(const Args& a, const std::string& what) {
  if(!verbose(a)) return {};
  auto last = std::make_shared<std::size_t>(0);
  return [what, last](std::size_t done, std::size_t total) {
    const std::size_t decile = 10 * done / std::max<std::size_t>(total, 1);
    if(decile > *last || done == total) {
      *last = decile;
      std::cerr << what << ": " << done << "/" << total << "\n";
    }
  };
}

// The Geodesic Spin Contour settings of the command line: support and agd radius as fractions of
// the geodesic diameter; `norm` (when set) imposes D and the agd normalization, else it receives
// this mesh's.
std::unique_ptr<shapecorr::Geodesic_spin_descriptors<Mesh>> make_geodesic(const Mesh& m, const Args& a, shapecorr::Geodesic_spin_normalization* norm,
                                                                          const std::function<void(std::size_t, std::size_t)>& progress) {
  typedef shapecorr::Geodesic_spin_descriptors<Mesh> G;
  const double support = to_double(a.get("support", "0.4"), "--support", 0, 10, true), radius = to_double(a.get("agd-radius", "0.15"), "--agd-radius", 0, 1);
  const std::size_t rows = to_count(a.get("rows", "64"), "--rows", 1, max_bins), columns = to_count(a.get("columns", "64"), "--columns", 1, max_bins);
  const auto np = SP::support_fraction(support).agd_radius_fraction(radius).image_rows(rows).image_columns(columns).progress_callback(progress);
  std::unique_ptr<G> g(new G(m, np.geodesic_spin_normalization(norm ? *norm : shapecorr::Geodesic_spin_normalization())));
  if(norm && norm->geodesic_diameter == 0) *norm = g->normalization();
  return g;
}

} // namespace

bool is_rigid(const std::string& t) {
  return t == "spin-image" || t == "face-spin-image" || t == "spin-contour" || t == "improved-spin-image";
}
bool is_spectral(const std::string& t) { return t == "hks" || t == "wks" || t == "sihks"; }
bool is_geodesic(const std::string& t) { return t == "gsc" || t == "geodesic-spin-image"; }
bool is_contour(const std::string& t) { return t == "spin-contour" || t == "gsc"; }

void check_descriptor_type(const std::string& type, const std::string& option) {
  if(!is_rigid(type) && !is_spectral(type) && !is_geodesic(type))
    throw Usage_error(option + " must be hks, wks, sihks, spin-image, face-spin-image, spin-contour, improved-spin-image, gsc or "
                      "geodesic-spin-image (got '" + type + "')");
}

std::vector<Option> descriptor_options() {
  return {{"eigenpairs", "K", "hks|wks|sihks: Laplace-Beltrami eigenpairs (default 300)"},
          {"scales", "N", "hks|wks: number of times or energies (default 100)"},
          {"axis", "normal|central|local-central|shot", "rigid descriptors: the spin axis (default normal; improved-spin-image: shot)"},
          {"support", "F", "support: fraction of the extent (rigid, default 1.0) or of the geodesic diameter (gsc, default 0.4)"},
          {"rows", "R", "beta samples (default 120 rigid, 64 geodesic)"},
          {"columns", "C", "alpha samples (default 60 rigid, 64 geodesic)"},
          {"central-radius", "F", "local-central axis: radius as a fraction of the extent (default 0.1)"},
          {"lrf-radius", "M", "shot axis: SHOT frame radius in mean edge lengths (default 30)"},
          {"exact-area", "", "face-spin-image: the exact area in each bin (slower) instead of sampled areas"},
          {"agd-radius", "F", "gsc: local agd radius as a fraction of D (default 0.15; 0 = global agd)"}};
}

std::size_t Descriptor_set::size() const { return std::max({images.size(), contours.size(), static_cast<std::size_t>(rows.rows())}); }

std::vector<std::size_t> all_ids(std::size_t n) {
  std::vector<std::size_t> v(n);
  for(std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

Descriptor_set compute_descriptor_set(const Mesh& m, const std::vector<std::size_t>& ids, const std::string& type, const Args& a,
                                      const Mesh& reference, const std::string& label, shapecorr::Geodesic_spin_normalization* norm) {
  Descriptor_set s;
  if(is_spectral(type)) {
    const std::size_t k = std::min<std::size_t>(to_count(a.get("eigenpairs", "300"), "--eigenpairs", 1, 100000), m.number_of_vertices());
    const auto basis = shapecorr::compute_laplace_beltrami_eigenbasis(m, k);
    const Eigen::MatrixXd D = shapecorr::spectral_signature_matrix(basis, shapecorr::spectral_signature_from_string(type),
                                                                   SP::number_of_scales(to_count(a.get("scales", "100"), "--scales", 1, 10000)));
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
    s.contours = sd->spin_contours(ops, progress);
  else if(type == "face-spin-image")
    s.images = a.has("exact-area") ? sd->exact_face_spin_images(ops, progress) : sd->face_spin_images(ops, progress);
  else
    s.images = sd->spin_images(ops, progress);
  return s;
}

namespace {
std::vector<Eigen::VectorXd> row_vectors(const Eigen::MatrixXd& m) {
  std::vector<Eigen::VectorXd> v;
  for(Eigen::Index i = 0; i < m.rows(); ++i) v.push_back(m.row(i).transpose());
  return v;
}
const auto euclidean = [](const Eigen::VectorXd& x, const Eigen::VectorXd& y) { return (x - y).norm(); };
} // namespace

std::vector<std::vector<shapecorr::Descriptor_neighbor>> nearest_descriptors(const Descriptor_set& s, const Descriptor_set& t, std::size_t k,
                                                                            shapecorr::Contour_comparison comparison) {
  if(!s.contours.empty()) return shapecorr::k_nearest_contours(s.contours, t.contours, k, comparison);
  if(!s.images.empty()) return shapecorr::k_nearest_descriptors(s.images, t.images, shapecorr::Spin_image_distance(), k);
  return shapecorr::k_nearest_descriptors(row_vectors(s.rows), row_vectors(t.rows), euclidean, k);
}

std::vector<double> distances_from(const Descriptor_set& from, const Descriptor_set& to, std::size_t k) {
  if(!from.contours.empty()) return shapecorr::descriptor_distances(from.contours[k], to.contours, shapecorr::Contour_l1_distance());
  if(!from.images.empty()) return shapecorr::descriptor_distances(from.images[k], to.images, shapecorr::Spin_image_distance());
  return shapecorr::descriptor_distances(Eigen::VectorXd(from.rows.row(static_cast<Eigen::Index>(k)).transpose()), row_vectors(to.rows), euclidean);
}

void write_descriptor_plot(const Mesh& m, const Args& a, const std::string& type, std::size_t v, const std::string& output) {
  if(extension(output) != "png") throw Usage_error("--plot writes a .png picture");
  if(is_spectral(type)) throw Usage_error("--plot applies to spin images, spin contours and geodesic spin descriptors");
  const vertex_descriptor vd(static_cast<Mesh::size_type>(v));
  if(is_geodesic(type)) {
    const auto gs = make_geodesic(m, a, nullptr, {});
    const shapecorr::Spin_image img = gs->geodesic_spin_image(vd);
    const shapecorr::Spin_contour c = gs->geodesic_spin_contour(vd);
    shapecorr::write_spin_descriptor_plot(output, img, c);
    if(verbose(a))
      std::cerr << "descriptors: vertex " << v << ", geodesic spin image " << img.rows() << "x" << img.columns() << " and its Geodesic Spin Contour ("
                << c.size() << " points; gd grows downwards, agd to the right) -> " << output << "\n";
    return;
  }
  const auto sd = make_spin(m, a, type, m);
  const auto op = sd->oriented_point(vd);
  const bool point_image = type == "spin-image" || type == "improved-spin-image";
  const shapecorr::Spin_image img = point_image ? sd->spin_image(op) : face_image(*sd, op, a.has("exact-area"));
  const shapecorr::Spin_contour c = sd->spin_contour(op);
  shapecorr::write_spin_descriptor_plot(output, img, c);
  if(verbose(a))
    std::cerr << "descriptors: vertex " << v << ", "
              << (point_image ? "spin image" : a.has("exact-area") ? "face-based spin image (exact areas)" : "face-based spin image") << " "
              << img.rows() << "x" << img.columns() << " and its Spin Contour (" << c.size() << " points)"
              << (op.fell_back_to_normal ? ", axis fell back to the normal" : "") << " -> " << output << "\n";
}

} // namespace cli
