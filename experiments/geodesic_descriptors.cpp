// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The thesis's chapter 4 evaluation (ALGORITHMS.md): hit rate and average geodesic error against
// 100 k / N for the Geodesic Spin Contour, the geodesic spin image, HKS, WKS, SI-HKS, the intrinsic
// shape context and the spin image, on TOSCA (tosca5k) same-class pairs, whole and with partial /
// resampled sources made here
// (a cut extremity, random deletion of 20/40/60 vertices, one Loop subdivision), ground truth from
// the .vts files carried through the kept vertex ids. Writes CSV curves, PNG plots and a JSON
// summary (hit rate at k = 1 and at 1%, mean geodesic error at k = 1, normalized by sqrt(area)).
//
// Pairs: TOSCA names (wolf0:wolf2), camel_gallop frames (camel3:camel1, with the pyFM map
// maps/3_to_1) and the non-isometric lion:cat (lion2cat). TOSCA pairs also get the curves that
// count the left-right symmetric match as correct (.sym.vts).
// usage: evaluate_geodesic_descriptors [--data DIR] [--output DIR] [--pairs a:b,c:d] [--variants
//        whole,cut,delete20,delete40,delete60,loop] [--descriptors gsc,gsi,hks,wks,sihks,isc,si]
//        [--points 50] [--seed 1] [--threads T] [--support L/D] [--agd-radius r/D]
#include "program.h"
#include <shapecorr/io/line_plot.h>
#include "shapes.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/evaluation/descriptor_ranking.h>
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/sampling.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/spectral.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>

namespace {
using eval::split;
using eval::K;
using eval::Mesh;
using eval::Vertex;
using eval::Shape;
using eval::none;
using eval::whole;
using eval::keep_faces;
using eval::cut_extremity;
using eval::read;
namespace SP = shapecorr::parameters;

// Random deletion of n vertices with their incident triangles (seeded).
Shape delete_vertices(const Mesh& m, std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::set<std::size_t> gone;
  std::uniform_int_distribution<std::size_t> pick(0, m.number_of_vertices() - 1);
  while(gone.size() < n) gone.insert(pick(rng));
  return keep_faces(m, [&](std::size_t v) { return gone.count(v) == 0; });
}

// One Loop subdivision: the original vertices keep their ids (moved by the Loop mask); the new edge
// vertices have no ground truth.
Shape loop_subdivision(const Mesh& m) {
  Shape s{m, {}};
  CGAL::Subdivision_method_3::Loop_subdivision(s.mesh, CGAL::parameters::number_of_iterations(1));
  for(std::size_t i = 0; i < s.mesh.number_of_vertices(); ++i) s.original.push_back(i < m.number_of_vertices() ? i : none);
  return s;
}

struct Descriptor_result {
  std::string label;
  shapecorr::Ranking_curves curves;
  double seconds = 0;
};

// The descriptors of the source points and of every target vertex, as a distance functor.
struct Case {
  std::string name, title;
  Shape source;
  Mesh target;
  std::vector<std::size_t> points; // source vertex ids (furthest-point samples with ground truth)
  std::vector<std::size_t> truth;  // target vertex per point
  std::vector<std::size_t> truth_sym; // its left-right counterpart (TOSCA .sym.vts), or empty
  double support = 0.2, radius = 0.15;
  double isc_radius = 0; // ISC radius, mesh units; 0: 0.055 x the target's geodesic diameter
};

double sqrt_area(const Mesh& m) { return std::sqrt(CGAL::Polygon_mesh_processing::area(m)); }

std::vector<Descriptor_result> run_case(const Case& c, const std::vector<std::string>& descriptors, unsigned threads) {
  const std::size_t N = c.target.number_of_vertices(), S = c.points.size();
  shapecorr::Fast_marching_geodesics<Mesh> target_fm(c.target);
  std::vector<Eigen::VectorXd> gt(S), gts(c.truth_sym.empty() ? 0 : S);
  shapecorr::parallel_for(S, shapecorr::resolve_thread_count(threads), [&](std::size_t i, unsigned) {
    gt[i] = target_fm.distances_from(c.truth[i]);
    if(!c.truth_sym.empty()) gts[i] = target_fm.distances_from(c.truth_sym[i]);
  });
  const double norm = sqrt_area(c.target);
  std::vector<std::size_t> all(N);
  for(std::size_t j = 0; j < N; ++j) all[j] = j;
  // Shared by the descriptors of a case, built when first needed (its time counts in that
  // descriptor's seconds): the geodesic spin descriptors of target and source, the eigenbases.
  typedef shapecorr::Geodesic_spin_descriptors<Mesh> G;
  std::unique_ptr<G> gsd_target, gsd_source;
  auto geodesic = [&]() {
    if(!gsd_target) {
      const auto np = SP::support_fraction(c.support).agd_radius_fraction(c.radius).number_of_threads(threads);
      gsd_target.reset(new G(c.target, np));
      gsd_source.reset(new G(c.source.mesh, np.geodesic_spin_normalization(gsd_target->normalization())));
    }
  };
  std::unique_ptr<shapecorr::Laplace_beltrami_eigenbasis> basis_target, basis_source;
  auto spectral = [&]() {
    if(!basis_target) {
      basis_target.reset(new shapecorr::Laplace_beltrami_eigenbasis(shapecorr::compute_laplace_beltrami_eigenbasis(c.target, 300)));
      basis_source.reset(new shapecorr::Laplace_beltrami_eigenbasis(shapecorr::compute_laplace_beltrami_eigenbasis(c.source.mesh, 300)));
    }
  };
  auto prepared = [&](const std::vector<shapecorr::Spin_contour>& cs) {
    std::vector<shapecorr::Contour_nearest_point_index> x(cs.size());
    shapecorr::parallel_for(cs.size(), shapecorr::resolve_thread_count(threads),
                                      [&](std::size_t i, unsigned) { x[i] = shapecorr::Contour_nearest_point_index(cs[i]); });
    return x;
  };
  std::vector<Descriptor_result> out;
  for(const std::string& d : descriptors) {
    const auto t0 = std::chrono::steady_clock::now();
    Descriptor_result r;
    auto rank = [&](auto&& dist) {
      if(c.truth_sym.empty()) return shapecorr::evaluate_descriptor_ranking(S, N, dist, c.truth, [&](std::size_t i) { return gt[i]; }, norm, threads);
      return shapecorr::evaluate_descriptor_ranking(S, N, dist, c.truth, [&](std::size_t i) { return gt[i]; }, c.truth_sym,
                                                    [&](std::size_t i) { return gts[i]; }, norm, threads);
    };
    if(d == "gsc" || d == "gsi") {
      geodesic();
      const G& gt_ = *gsd_target;
      const G& gs = *gsd_source;
      if(d == "gsc") {
        r.label = "GSC";
        // the exact L1 distance from the contours' nearest-point indices (the same distances)
        const auto T = prepared(gt_.geodesic_spin_contours(all)), P = prepared(gs.geodesic_spin_contours(c.points));
        r.curves = rank([&](std::size_t i, std::size_t j) { return shapecorr::contour_l1_distance(P[i], T[j]); });
      } else {
        r.label = "GEODESIC SI";
        const auto T = gt_.geodesic_spin_images(all), P = gs.geodesic_spin_images(c.points);
        r.curves = rank([&](std::size_t i, std::size_t j) { return shapecorr::Spin_image_distance()(P[i], T[j]); });
      }
    } else if(d == "hks" || d == "wks" || d == "sihks") {
      spectral();
      const auto& bt = *basis_target;
      const auto& bs = *basis_source;
      Eigen::MatrixXd T, P;
      if(d == "hks") {
        r.label = "HKS";
        T = shapecorr::heat_kernel_signature_matrix(bt);
        P = shapecorr::heat_kernel_signature_matrix(bs);
      } else if(d == "wks") {
        r.label = "WKS";
        T = shapecorr::wave_kernel_signature_matrix(bt);
        P = shapecorr::wave_kernel_signature_matrix(bs);
      } else {
        r.label = "SI-HKS";
        T = shapecorr::scale_invariant_heat_kernel_signature_matrix(bt);
        P = shapecorr::scale_invariant_heat_kernel_signature_matrix(bs);
      }
      r.curves = rank([&](std::size_t i, std::size_t j) {
        return (P.row(static_cast<Eigen::Index>(c.points[i])) - T.row(static_cast<Eigen::Index>(j))).norm();
      });
    } else if(d == "isc") {
      // the thesis's ISC: SI-HKS (its defaults, the spectral descriptors' 300-eigenpair bases),
      // radius 20 on TOSCA, 5 rings x 16 directions; the source described with the target's radius
      spectral();
      r.label = "ISC";
      const double R = c.isc_radius > 0 ? c.isc_radius : 0.055 * shapecorr::geodesic_diameter(c.target, SP::geodesic_method(shapecorr::Geodesic_method::FAST_MARCHING));
      const shapecorr::Intrinsic_shape_context<Mesh> it(c.target, SP::eigenbasis(basis_target.get()).support_length(R).number_of_threads(threads));
      const shapecorr::Intrinsic_shape_context<Mesh> is(c.source.mesh, SP::eigenbasis(basis_source.get()).support_length(R).number_of_threads(threads));
      const Eigen::MatrixXd T = it.descriptors(all), P = is.descriptors(c.points);
      r.curves = rank([&](std::size_t i, std::size_t j) { return (P.row(long(i)) - T.row(long(j))).norm(); });
    } else if(d == "si") {
      r.label = "SPIN IMAGE";
      // the thesis's baseline: support 0.2 x the target's bounding-box diagonal, vertex normals
      const shapecorr::Spin_descriptors<Mesh> probe(c.target);
      const auto np = SP::support_length(0.2 * probe.bounding_box_diagonal()).image_rows(64).image_columns(32).number_of_threads(threads);
      const shapecorr::Spin_descriptors<Mesh> st(c.target, np), ss(c.source.mesh, np);
      std::vector<shapecorr::Oriented_point> ot, os;
      for(std::size_t j = 0; j < N; ++j) ot.push_back(st.oriented_point(Vertex(static_cast<Mesh::size_type>(j))));
      for(std::size_t p : c.points) os.push_back(ss.oriented_point(Vertex(static_cast<Mesh::size_type>(p))));
      const auto T = st.spin_images(ot);
      const auto P = ss.spin_images(os);
      r.curves = rank([&](std::size_t i, std::size_t j) { return shapecorr::Spin_image_distance()(P[i], T[j]); });
    } else {
      throw std::runtime_error("unknown descriptor " + d);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cerr << "  " << r.label << ": hit rate k=1 " << r.curves.hit_rate[0] << ", at 1% " << r.curves.hit_rate_at_percent(1.0)
              << ", geodesic error k=1 " << r.curves.geodesic_error[0];
    if(!r.curves.hit_rate_symmetric.empty())
      std::cerr << "; symmetric counted: " << r.curves.hit_rate_symmetric[0] << ", " << r.curves.hit_rate_symmetric[r.curves.k_of_percent(1.0) - 1]
                << ", " << r.curves.geodesic_error_symmetric[0];
    std::cerr << " (" << r.seconds << " s)\n";
    out.push_back(std::move(r));
  }
  return out;
}

// Furthest-point samples (geodesic; the library's sampling, the arbitrary start dropped) among
// the source vertices that have ground truth: the others are given distance -1, so never chosen.
std::vector<std::size_t> sample_points(const Mesh& m, const std::vector<bool>& has_truth, std::size_t count) {
  shapecorr::Fast_marching_geodesics<Mesh> fm(m);
  const std::size_t n = m.number_of_vertices();
  const std::size_t first = static_cast<std::size_t>(std::find(has_truth.begin(), has_truth.end(), true) - has_truth.begin());
  if(first == n) return {};
  return shapecorr::furthest_point_sampling_indices(n, count, first, [&](std::size_t s) {
    Eigen::VectorXd d = fm.distances_from(s);
    for(std::size_t v = 0; v < n; ++v)
      if(!has_truth[v]) d[static_cast<Eigen::Index>(v)] = -1;
    return d;
  });
}

// A dense 0-based map file: line v holds the target vertex of source vertex v.
std::vector<std::size_t> read_map(const std::string& path, std::size_t n_source, std::size_t n_target) {
  std::ifstream in(path);
  if(!in) throw std::runtime_error(path + ": cannot read");
  std::vector<std::size_t> m;
  long long v;
  while(in >> v) {
    if(v < 0 || static_cast<std::size_t>(v) >= n_target) throw std::runtime_error(path + ": target id " + std::to_string(v) + " out of range");
    m.push_back(static_cast<std::size_t>(v));
  }
  if(m.size() != n_source) throw std::runtime_error(path + ": " + std::to_string(m.size()) + " entries for " + std::to_string(n_source) + " vertices");
  return m;
}

std::string upper(std::string s) {
  for(char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

} // namespace

int main(int argc, char** argv) {
  std::string data = SHAPECORR_EVAL_DATA_DIR, out = "experiments/results/geodesic";
  std::string pairs = "wolf0:wolf2,centaur0:centaur1,cat0:cat1,dog0:dog1,camel3:camel1,lion:cat";
  std::string variants = "whole,cut,delete20,delete40,delete60,loop", descriptors = "gsc,gsi,hks,wks,sihks,isc,si";
  std::size_t n_points = 50;
  unsigned seed = 1, threads = 0;
  double support_override = 0, radius_override = -1;
  const int code = eval::parse_options(argc, argv, "evaluate_geodesic_descriptors",
      "[--data DIR] [--output DIR] [--pairs a:b,...] [--variants whole,cut,delete20,...]\n"
      "       [--descriptors gsc,gsi,hks,wks,sihks,isc,si] [--points N] [--seed S] [--threads T] [--support F] [--agd-radius F]",
      [&](const std::string& k, const std::string& v) {
        if(k == "--data") data = v;
        else if(k == "--output") out = v;
        else if(k == "--pairs") pairs = v;
        else if(k == "--variants") variants = v;
        else if(k == "--descriptors") descriptors = v;
        else if(k == "--points") n_points = std::stoul(v);
        else if(k == "--seed") seed = static_cast<unsigned>(std::stoul(v));
        else if(k == "--threads") threads = static_cast<unsigned>(std::stoul(v));
        else if(k == "--support") support_override = std::stod(v);
        else if(k == "--agd-radius") radius_override = std::stod(v);
        else return false;
        return true;
      });
  if(code >= 0) return code;
  try {
    if(!eval::has_evaluation_data("evaluate_geodesic_descriptors", data)) return 1;
    std::system(("mkdir -p '" + out + "'").c_str());
    const std::string tosca = data + "/tosca5k/";
    std::ofstream json(out + "/summary.json");
    json << "{\n  \"points\": " << n_points << ", \"seed\": " << seed << ", \"geodesic_error_normalization\": \"sqrt(target area)\",\n  \"cases\": {";
    bool first_case = true;
    for(const std::string& pair : split(pairs, ',')) {
      const auto ab = split(pair, ':');
      if(ab.size() != 2) throw std::runtime_error("--pairs: expected a:b, got " + pair);
      // the shapes and the ground truth: A vertex -> B vertex (and its symmetric counterpart)
      Mesh A, B;
      std::vector<std::size_t> truth_of, sym_of;
      if(ab[0].rfind("camel", 0) == 0 && ab[1].rfind("camel", 0) == 0) { // camel_gallop frames, pyFM maps (0-based)
        const std::string i = ab[0].substr(5), j = ab[1].substr(5), dir = data + "/camel_gallop/camel_gallop/";
        auto frame = [&](const std::string& k) { return dir + "camel-gallop-" + (k.size() < 2 ? "0" : "") + k + ".off"; };
        A = read(frame(i));
        B = read(frame(j));
        truth_of = read_map(dir + "maps/" + i + "_to_" + j, A.number_of_vertices(), B.number_of_vertices());
      } else if(ab[0] == "lion" && ab[1] == "cat") { // non-isometric, dense map (0-based)
        A = read(data + "/camel_gallop/lion-00.off");
        B = read(data + "/camel_gallop/cat-00.off");
        truth_of = read_map(data + "/camel_gallop/lion2cat", A.number_of_vertices(), B.number_of_vertices());
      } else {
        A = read(tosca + "meshes/" + ab[0] + ".off");
        B = read(tosca + "meshes/" + ab[1] + ".off");
        const auto va = shapecorr::read_vts(tosca + "corres/" + ab[0] + ".vts"), vb = shapecorr::read_vts(tosca + "corres/" + ab[1] + ".vts");
        const auto vs = shapecorr::read_vts(tosca + "corres/" + ab[0] + ".sym.vts");
        if(va.size() != vb.size() || vs.size() != vb.size()) throw std::runtime_error(ab[0] + " and " + ab[1] + ": .vts files differ in length");
        truth_of.assign(A.number_of_vertices(), none);
        sym_of.assign(A.number_of_vertices(), none);
        for(std::size_t k = 0; k < va.size(); ++k) {
          if(va[k] < truth_of.size() && vb[k] < B.number_of_vertices() && truth_of[va[k]] == none) truth_of[va[k]] = vb[k];
          if(vs[k] < sym_of.size() && vb[k] < B.number_of_vertices() && sym_of[vs[k]] == none) sym_of[vs[k]] = vb[k];
        }
      }
      const bool wolf = ab[0].rfind("wolf", 0) == 0;
      const bool camel_or_lion = sym_of.empty();
      for(const std::string& variant : split(variants, ',')) {
        Case c;
        c.name = ab[0] + "-" + ab[1] + "-" + variant;
        c.target = B;
        c.support = wolf ? 0.4 : 0.2; // the thesis: wolf L = 0.4 D, r = 0.15 D; centaur (and here the others) L = 0.2 D
        c.radius = 0.15;
        if(!camel_or_lion) c.isc_radius = 20; // the thesis's ISC radius on TOSCA
        if(support_override > 0) c.support = support_override;
        if(radius_override >= 0) c.radius = radius_override;
        if(variant == "whole") c.source = whole(A);
        else if(variant == "cut") c.source = cut_extremity(A);
        else if(variant.rfind("delete", 0) == 0) c.source = delete_vertices(A, std::stoul(variant.substr(6)), seed);
        else if(variant == "loop") c.source = loop_subdivision(A);
        else throw std::runtime_error("unknown variant " + variant);
        c.title = upper(ab[0] + " TO " + ab[1] + " " + variant);
        std::cerr << "  (" << (sym_of.empty() ? "no symmetric ground truth" : "with the symmetric ground truth") << ")\n";
        std::vector<bool> has(c.source.mesh.number_of_vertices(), false);
        for(std::size_t v = 0; v < has.size(); ++v) {
          const std::size_t o = c.source.original[v];
          has[v] = o != none && truth_of[o] != none && (sym_of.empty() || sym_of[o] != none);
        }
        c.points = sample_points(c.source.mesh, has, n_points);
        for(std::size_t p : c.points) {
          c.truth.push_back(truth_of[c.source.original[p]]);
          if(!sym_of.empty()) c.truth_sym.push_back(sym_of[c.source.original[p]]);
        }
        std::cerr << c.name << ": source " << c.source.mesh.number_of_vertices() << " vertices, target " << B.number_of_vertices() << ", "
                  << c.points.size() << " points, L = " << c.support << " D, r = " << c.radius << " D\n";
        const auto rs = run_case(c, split(descriptors, ','), threads);
        std::ofstream csv(out + "/" + c.name + ".csv");
        csv << "descriptor,k,percent,hit_rate,geodesic_error\n";
        std::vector<shapecorr::Plot_curve> hit, err;
        double emax = 0;
        for(const auto& r : rs) {
          shapecorr::Plot_curve h{r.label, {}, {}}, e{r.label, {}, {}};
          const std::size_t N = r.curves.number_of_targets;
          for(std::size_t k = 1; k <= N; ++k) {
            const double pct = 100.0 * static_cast<double>(k) / static_cast<double>(N);
            csv << r.label << "," << k << "," << pct << "," << r.curves.hit_rate[k - 1] << "," << r.curves.geodesic_error[k - 1] << "\n";
            if(pct <= 10.0 + 1e-9) {
              h.x.push_back(pct);
              h.y.push_back(r.curves.hit_rate[k - 1]);
              e.x.push_back(pct);
              e.y.push_back(r.curves.geodesic_error[k - 1]);
              emax = std::max(emax, r.curves.geodesic_error[k - 1]);
            }
          }
          hit.push_back(h);
          err.push_back(e);
        }
        shapecorr::write_png(out + "/" + c.name + "_hit_rate.png", shapecorr::line_plot(hit, c.title, "100 K / N", "HIT RATE", 10.0, 1.0));
        shapecorr::write_png(out + "/" + c.name + "_geodesic_error.png",
                             shapecorr::line_plot(err, c.title, "100 K / N", "GEODESIC ERROR", 10.0, std::max(0.05, std::ceil(emax * 20) / 20)));
        json << (first_case ? "" : ",") << "\n    \"" << c.name << "\": {\"source_vertices\": " << c.source.mesh.number_of_vertices()
             << ", \"target_vertices\": " << B.number_of_vertices() << ", \"points\": " << c.points.size() << ", \"support\": " << c.support
             << ", \"agd_radius\": " << c.radius;
        first_case = false;
        for(const auto& r : rs) {
          json << ",\n      \"" << r.label << "\": {\"hit_rate_k1\": " << eval::json_number(r.curves.hit_rate[0]) << ", \"hit_rate_1pct\": "
               << eval::json_number(r.curves.hit_rate_at_percent(1.0)) << ", \"geodesic_error_k1\": " << eval::json_number(r.curves.geodesic_error[0])
               << ", \"geodesic_error_1pct\": " << eval::json_number(r.curves.geodesic_error_at_percent(1.0));
          if(!r.curves.hit_rate_symmetric.empty())
            json << ", \"hit_rate_k1_sym\": " << eval::json_number(r.curves.hit_rate_symmetric[0]) << ", \"hit_rate_1pct_sym\": "
                 << eval::json_number(r.curves.hit_rate_symmetric[r.curves.k_of_percent(1.0) - 1]) << ", \"geodesic_error_k1_sym\": "
                 << eval::json_number(r.curves.geodesic_error_symmetric[0]);
          json << ", \"seconds\": " << eval::json_number(r.seconds) << "}";
        }
        json << "}";
        json.flush();
      }
    }
    json << "\n  }\n}\n";
    std::cerr << "wrote " << out << "/summary.json, the curves (.csv) and plots (.png)\n";
  } catch(const std::exception& e) {
    std::cerr << "evaluate_geodesic_descriptors: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
