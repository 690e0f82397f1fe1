// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The thesis's rigid-descriptor protocol (ALGORITHMS.md, chapter 3): recall vs 1-precision of
// SI, FSI-fn, FSI-cd, FSIx-cd (exact areas), SC-fn, SC-cd, ISI, and (when built with PCL) PCL's SHOT352 and spin image,
// on real data from ../shared/data, in one run.
//
// For each experiment: N random points uniform on the source surface (seeded), their closest
// points on the target surface as ground truth (the target's points, in the same order); every
// descriptor is computed at both point sets; each source point is matched to the target point of
// nearest descriptor; a match is correct when it is its own ground-truth point. Sweeping a
// threshold on the descriptor distance gives recall (correct accepted / N) against 1 - precision
// (false accepted / accepted). Writes <out>/<experiment>.csv (the curves), <out>/<experiment>.png
// and <out>/summary.json (area under each curve, final recall = share of correct matches, summed
// distance of the incorrect matches in mesh resolutions). The area is taken under the upper
// envelope R(x) = best recall at 1 - precision <= x over x in [0, 1] (1 for a perfect descriptor).
//
// Usage: evaluate_rigid_descriptors [--data DIR] [--output DIR] [--points N] [--seed S]
//                                   [--experiments NAME,...] [--threads T]
#include "program.h"
#include <shapecorr/io/line_plot.h>

#include <shapecorr/descriptors.h>
#include <shapecorr/io.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#ifdef SHAPECORR_WITH_PCL
#include <pcl/features/shot.h>
#include <pcl/features/spin_image.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#endif

#include <chrono>
#include <functional>
#include <map>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;
typedef shapecorr::Spin_descriptors<Mesh>::Face_location Location;
namespace SP = shapecorr::parameters;
namespace PMP = CGAL::Polygon_mesh_processing;
using shapecorr::Spin_axis;

struct Experiment {
  std::string name, title;
  Mesh source, target;
  double support_fraction = 1.0; // of the target's bounding-box diagonal
  bool local = false;            // partial data: the "cd" variants use the local central direction
};

Mesh read(const std::string& path, bool repair = false) {
  Mesh m;
  shapecorr::Read_options o;
  o.repair_non_manifold = repair;
  shapecorr::read_triangle_mesh(path, m, o);
  return m;
}

double mesh_resolution(const Mesh& m) {
  double s = 0;
  for(auto e : m.edges()) s += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  return s / static_cast<double>(m.number_of_edges());
}

double bbox_diagonal(const Mesh& m) {
  const auto b = CGAL::Polygon_mesh_processing::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

// Uniform random points on the surface (faces by area, uniform barycentric coordinates).
std::vector<Location> random_surface_points(const Mesh& m, std::size_t n, std::mt19937& rng) {
  std::vector<face_descriptor> fs;
  std::vector<double> cum;
  double acc = 0;
  for(auto f : m.faces()) {
    acc += CGAL::Polygon_mesh_processing::face_area(f, m);
    fs.push_back(f);
    cum.push_back(acc);
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Location> out;
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t k = static_cast<std::size_t>(std::lower_bound(cum.begin(), cum.end(), u(rng) * acc) - cum.begin());
    double a = u(rng), b = u(rng);
    if(a + b > 1) { a = 1 - a; b = 1 - b; }
    out.push_back(Location(fs[std::min(k, fs.size() - 1)], {{1 - a - b, a, b}}));
  }
  return out;
}

K::Point_3 point_of(const Mesh& m, const Location& l) { return PMP::construct_point(l, m); }

std::vector<Location> closest_points(const Mesh& target, const Mesh& source, const std::vector<Location>& pts) {
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;
  Tree tree;
  PMP::build_AABB_tree(target, tree);
  std::vector<Location> out;
  for(const auto& l : pts) out.push_back(PMP::locate_with_AABB_tree(point_of(source, l), tree, target));
  return out;
}

// Curve and summary of one descriptor on one experiment.
struct Result {
  std::string label;
  std::vector<double> one_minus_precision, recall, threshold;
  double auc = 0, final_recall = 0, wrong_distance_mr = 0;
  std::size_t correct = 0;
  double seconds = 0;
};

Result evaluate(const std::string& label, const std::vector<shapecorr::Descriptor_match>& matches, const std::vector<K::Point_3>& target_points,
                double mr) {
  Result r;
  r.label = label;
  std::vector<std::pair<double, bool>> acc;
  for(const auto& m : matches) {
    const bool ok = m.target == m.source;
    acc.emplace_back(m.distance, ok);
    r.correct += ok;
    if(!ok) r.wrong_distance_mr += std::sqrt(CGAL::squared_distance(target_points[m.target], target_points[m.source])) / mr;
  }
  std::stable_sort(acc.begin(), acc.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const double n = static_cast<double>(matches.size());
  std::size_t tp = 0, fp = 0;
  r.one_minus_precision.push_back(0);
  r.recall.push_back(0);
  r.threshold.push_back(0);
  for(std::size_t i = 0; i < acc.size(); ++i) {
    (acc[i].second ? tp : fp) += 1;
    if(i + 1 < acc.size() && acc[i + 1].first == acc[i].first) continue; // one point per distinct threshold
    const double x = static_cast<double>(fp) / static_cast<double>(tp + fp), y = static_cast<double>(tp) / n;
    r.one_minus_precision.push_back(x);
    r.recall.push_back(y);
    r.threshold.push_back(acc[i].first);
  }
  r.final_recall = static_cast<double>(r.correct) / n;
  // Area under the curve over 1 - precision in [0, 1]: R(x) = the best recall reached at a
  // 1 - precision of at most x (the upper envelope, a step function; 1 for a perfect descriptor).
  std::vector<std::pair<double, double>> pts;
  for(std::size_t k = 0; k < r.recall.size(); ++k) pts.emplace_back(r.one_minus_precision[k], r.recall[k]);
  std::sort(pts.begin(), pts.end());
  double best = 0;
  for(std::size_t k = 0; k < pts.size(); ++k) {
    best = std::max(best, pts[k].second);
    const double next = k + 1 < pts.size() ? pts[k + 1].first : 1.0;
    r.auc += (next - pts[k].first) * best;
  }
  return r;
}

std::vector<shapecorr::Oriented_point> oriented_points(const shapecorr::Spin_descriptors<Mesh>& sd, const std::vector<Location>& pts, Spin_axis axis) {
  std::vector<shapecorr::Oriented_point> ops;
  for(const auto& l : pts) ops.push_back(sd.oriented_point(l, axis));
  return ops;
}

#ifdef SHAPECORR_WITH_PCL
struct Pcl_cloud {
  pcl::PointCloud<pcl::PointXYZ>::Ptr surface{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::PointCloud<pcl::Normal>::Ptr normals{new pcl::PointCloud<pcl::Normal>};
  pcl::PointCloud<pcl::PointXYZ>::Ptr keys{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::PointCloud<pcl::Normal>::Ptr key_normals{new pcl::PointCloud<pcl::Normal>};
};
Pcl_cloud pcl_cloud(const Mesh& m, const shapecorr::Spin_descriptors<Mesh>& sd, const std::vector<Location>& pts) {
  Pcl_cloud c;
  auto n3 = [](const Eigen::Vector3d& n) { return pcl::Normal(static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())); };
  for(auto v : m.vertices()) {
    Eigen::Vector3d normal;
    try {
      normal = sd.oriented_point(v, Spin_axis::NORMAL).axis;
    } catch(const shapecorr::Invalid_input&) {
      continue; // a vertex with no normal (only degenerate faces around it): left out of PCL's surface
    }
    const auto& p = m.point(v);
    c.surface->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
    c.normals->push_back(n3(normal));
  }
  for(const auto& l : pts) {
    const auto p = point_of(m, l);
    c.keys->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
    c.key_normals->push_back(n3(sd.oriented_point(l, Spin_axis::NORMAL).axis));
  }
  return c;
}
// Runs a PCL feature estimator on the key points over the surface; `values(point)` gives a
// descriptor's floats. NaN descriptors (PCL's mark for points without a frame) are never matched.
template <typename Descriptor, typename Estimator, typename Values>
std::vector<Eigen::VectorXf> pcl_features(Estimator& est, const Pcl_cloud& c, const pcl::PointCloud<pcl::Normal>::Ptr& normals, double radius,
                                          int size, Values&& values) {
  typedef pcl::PointCloud<Descriptor> Cloud_out;
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  est.setSearchMethod(tree);
  est.setInputCloud(c.keys);
  est.setSearchSurface(c.surface);
  est.setInputNormals(normals);
  est.setRadiusSearch(radius);
  Cloud_out out;
  est.compute(out);
  std::vector<Eigen::VectorXf> d;
  for(const auto& p : out.points) {
    Eigen::VectorXf v = Eigen::Map<const Eigen::VectorXf>(values(p), size);
    if(!v.allFinite()) v.setConstant(1e3f);
    d.push_back(v);
  }
  return d;
}
std::vector<Eigen::VectorXf> pcl_shot(const Pcl_cloud& c, double radius) {
  pcl::SHOTEstimation<pcl::PointXYZ, pcl::Normal, pcl::SHOT352> shot; // surface normals: the frame's support
  return pcl_features<pcl::SHOT352>(shot, c, c.normals, radius, 352, [](const pcl::SHOT352& s) { return s.descriptor; });
}
std::vector<Eigen::VectorXf> pcl_spin_image(const Pcl_cloud& c, double radius) {
  pcl::SpinImageEstimation<pcl::PointXYZ, pcl::Normal, pcl::Histogram<153>> si(8, 0.0, 1); // key normals: the axes
  return pcl_features<pcl::Histogram<153>>(si, c, c.key_normals, radius, 153, [](const pcl::Histogram<153>& h) { return h.histogram; });
}
#endif

std::vector<Result> run(const Experiment& ex, std::size_t n_points, unsigned seed, unsigned threads) {
  std::mt19937 rng(seed);
  const std::vector<Location> src = random_surface_points(ex.source, n_points, rng);
  const std::vector<Location> tgt = closest_points(ex.target, ex.source, src);
  std::vector<K::Point_3> tpts;
  for(const auto& l : tgt) tpts.push_back(point_of(ex.target, l));
  const double L = ex.support_fraction * bbox_diagonal(ex.target);
  const double mr = std::max(mesh_resolution(ex.source), mesh_resolution(ex.target));
  const auto np = SP::support_length(L).image_rows(std::size_t(120)).image_columns(std::size_t(60)).central_radius(0.1 * bbox_diagonal(ex.target))
                      .lrf_radius(std::min(30 * mr, L)).number_of_threads(threads);
  const double shot_radius = std::min(30 * mr, L); // 30 mr (thesis), but never beyond the support (partial data)
  const shapecorr::Spin_descriptors<Mesh> ds(ex.source, np), dt(ex.target, np);
  const Spin_axis cd = ex.local ? Spin_axis::LOCAL_CENTRAL_DIRECTION : Spin_axis::CENTRAL_DIRECTION;
  std::vector<Result> results;
  auto timed = [&](const std::string& label, auto&& fn) {
    const auto t0 = std::chrono::steady_clock::now();
    Result r = evaluate(label, fn(), tpts, mr);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cerr << "  " << ex.name << " " << label << ": final recall " << r.final_recall << ", AUC " << r.auc << " (" << r.seconds << " s)\n";
    results.push_back(r);
  };
  enum class Image { VERTICES, FACES_SAMPLED, FACES_EXACT };
  auto images = [&](Spin_axis axis, Image kind) {
    return [&, axis, kind] {
      auto of = [&](const shapecorr::Spin_descriptors<Mesh>& d, const std::vector<Location>& pts) {
        const auto ops = oriented_points(d, pts, axis);
        return kind == Image::FACES_EXACT ? d.exact_face_spin_images(ops) : kind == Image::FACES_SAMPLED ? d.face_spin_images(ops) : d.spin_images(ops);
      };
      return shapecorr::match_descriptors(of(ds, src), of(dt, tgt), shapecorr::Spin_image_distance(), threads);
    };
  };
  // contours by the exact L1 distance, from their nearest-point indices (the same distances)
  auto contours = [&](Spin_axis axis) {
    return [&, axis] {
      return shapecorr::match_contours(ds.spin_contours(oriented_points(ds, src, axis)), dt.spin_contours(oriented_points(dt, tgt, axis)),
                                       shapecorr::Contour_comparison::NEAREST_POINT_INDEX, threads);
    };
  };
  // the same contours compared through their distance fields (approximate L1)
  auto fields = [&](Spin_axis axis) {
    return [&, axis] {
      return shapecorr::match_contours(ds.spin_contours(oriented_points(ds, src, axis)), dt.spin_contours(oriented_points(dt, tgt, axis)),
                                       shapecorr::Contour_comparison::DISTANCE_FIELD, threads);
    };
  };
  timed("SI", images(Spin_axis::NORMAL, Image::VERTICES));
  timed("FSI-fn", images(Spin_axis::NORMAL, Image::FACES_SAMPLED));
  timed("FSI-cd", images(cd, Image::FACES_SAMPLED));
  timed("FSIx-cd", images(cd, Image::FACES_EXACT));
  timed("SC-fn", contours(Spin_axis::NORMAL));
  timed("SC-cd", contours(cd));
  timed("SCf-cd", fields(cd));
  timed("ISI", images(Spin_axis::SHOT_LRF, Image::VERTICES));
#ifdef SHAPECORR_WITH_PCL
  const Pcl_cloud cs = pcl_cloud(ex.source, ds, src), ct = pcl_cloud(ex.target, dt, tgt);
  auto l2 = [](const Eigen::VectorXf& a, const Eigen::VectorXf& b) { return static_cast<double>((a - b).norm()); };
  timed("PCL-SHOT352", [&] { return shapecorr::match_descriptors(pcl_shot(cs, shot_radius), pcl_shot(ct, shot_radius), l2, threads); });
  timed("PCL-SI", [&] { return shapecorr::match_descriptors(pcl_spin_image(cs, L), pcl_spin_image(ct, L), l2, threads); });
#endif
  return results;
}

Mesh with_noise(const Mesh& m, double amplitude, unsigned seed) {
  Mesh n = m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for(auto v : n.vertices()) {
    const auto& p = n.point(v);
    n.point(v) = K::Point_3(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
  }
  return n;
}

// The faces of `m` whose centres lie within `radius` of vertex `centre`: a cut part as the scene.
Mesh cut_part(const Mesh& m, Mesh::Vertex_index centre, double radius) {
  std::vector<K::Point_3> pts;
  std::vector<std::vector<std::size_t>> polys;
  std::map<Mesh::Vertex_index, std::size_t> id;
  const K::Point_3 c = m.point(centre);
  for(auto f : m.faces()) {
    std::vector<Mesh::Vertex_index> vs;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) vs.push_back(v);
    const K::Point_3 g = CGAL::centroid(m.point(vs[0]), m.point(vs[1]), m.point(vs[2]));
    if(CGAL::squared_distance(g, c) > radius * radius) continue;
    std::vector<std::size_t> poly;
    for(auto v : vs) {
      auto it = id.find(v);
      if(it == id.end()) {
        it = id.emplace(v, pts.size()).first;
        pts.push_back(m.point(v));
      }
      poly.push_back(it->second);
    }
    polys.push_back(poly);
  }
  Mesh part;
  PMP::polygon_soup_to_polygon_mesh(pts, polys, part);
  return part;
}

} // namespace

int main(int argc, char** argv) {
  std::string data = SHAPECORR_EVAL_DATA_DIR, out = "experiments/results/rigid", only;
  std::size_t n_points = 1000;
  unsigned seed = 1, threads = 0;
  const int code = eval::parse_options(argc, argv, "evaluate_rigid_descriptors",
      "[--data DIR] [--output DIR] [--points N] [--seed S] [--experiments a,b,...] [--threads T]",
      [&](const std::string& k, const std::string& v) {
        if(k == "--data") data = v;
        else if(k == "--output") out = v;
        else if(k == "--points") n_points = std::stoul(v);
        else if(k == "--seed") seed = static_cast<unsigned>(std::stoul(v));
        else if(k == "--experiments") only = "," + v + ",";
        else if(k == "--threads") threads = static_cast<unsigned>(std::stoul(v));
        else return false;
        return true;
      });
  if(code >= 0) return code;
  try {
    if(!eval::has_evaluation_data("evaluate_rigid_descriptors", data)) return 1;
    std::system(("mkdir -p '" + out + "'").c_str());
    const std::string c = data + "/classic/";
    std::vector<std::function<Experiment()>> makers;
    makers.push_back([&] { return Experiment{"uneven-fandisk", "FANDISK LIBIGL TO COMMON3D", read(c + "libigl/fandisk.off"), read(c + "common3d/fandisk.obj")}; });
    makers.push_back([&] { return Experiment{"uneven-bunny", "BUNNY 3.5K TO 36K", read(c + "libigl/bunny.off"), read(c + "common3d/stanford-bunny.obj")}; });
    makers.push_back([&] {
      return Experiment{"uneven-dragon", "DRAGON RES4 TO RES3", read(c + "stanford_npm/dragon_vrip_res4.ply", true), read(c + "stanford_npm/dragon_vrip_res3.ply", true)};
    });
    for(double a : {0.1, 0.2, 0.3})
      makers.push_back([&, a] {
        Mesh m = read(c + "libigl/fandisk.off");
        std::ostringstream name, title;
        name << "noise-fandisk-" << a;
        title << "FANDISK NOISE " << a << " MR";
        return Experiment{name.str(), title.str(), m, with_noise(m, a * mesh_resolution(m), 7)};
      });
    makers.push_back([&] {
      Mesh m = read(c + "libigl/fandisk.off");
      Experiment e{"partial-fandisk", "FANDISK PART (BALL 0.3 D) TO WHOLE", cut_part(m, Mesh::Vertex_index(0), 0.3 * bbox_diagonal(m)), m, 0.1, true};
      return e;
    });
    std::ofstream json(out + "/summary.json");
    json << "{\n  \"points\": " << n_points << ", \"seed\": " << seed << ",\n  \"experiments\": {";
    bool first_ex = true;
    for(const auto& make : makers) {
      Experiment ex = make();
      if(!only.empty() && only.find("," + ex.name + ",") == std::string::npos) continue;
      std::cerr << ex.name << ": source " << ex.source.number_of_vertices() << " vertices, target " << ex.target.number_of_vertices()
                << " vertices, support " << ex.support_fraction * 100 << "% of the target's bbox diagonal\n";
      const std::vector<Result> rs = run(ex, n_points, seed, threads);
      std::ofstream csv(out + "/" + ex.name + ".csv");
      csv << "descriptor,threshold,one_minus_precision,recall\n";
      std::vector<shapecorr::Plot_curve> curves;
      for(const auto& r : rs) {
        for(std::size_t k = 0; k < r.recall.size(); ++k)
          csv << r.label << "," << r.threshold[k] << "," << r.one_minus_precision[k] << "," << r.recall[k] << "\n";
        curves.push_back({r.label, r.one_minus_precision, r.recall});
      }
      shapecorr::write_png(out + "/" + ex.name + ".png", shapecorr::line_plot(curves, ex.title, "1 - PRECISION", "RECALL"));
      json << (first_ex ? "" : ",") << "\n    \"" << ex.name << "\": {";
      first_ex = false;
      for(std::size_t k = 0; k < rs.size(); ++k)
        json << (k ? "," : "") << "\n      \"" << rs[k].label << "\": {\"auc\": " << eval::json_number(rs[k].auc) << ", \"final_recall\": "
             << eval::json_number(rs[k].final_recall) << ", \"correct\": " << rs[k].correct << ", \"wrong_summed_distance_mr\": "
             << eval::json_number(rs[k].wrong_distance_mr) << ", \"seconds\": " << eval::json_number(rs[k].seconds) << "}";
      json << "\n    }";
    }
    json << "\n  }\n}\n";
    std::cerr << "wrote " << out << "/summary.json, the curves (.csv) and plots (.png)\n";
  } catch(const std::exception& e) {
    std::cerr << "evaluate_rigid_descriptors: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
