// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The chapter 6 evaluation (issue "Registration II"): NICPS against the thesis's baselines
// (Andresen 2001, Pauly 2005, CPD, GMM-L2) and BCPD (a peer, run as a separate program), every
// method on the same rigidly pre-aligned template; the rigid stage against Open3D's point-to-plane
// ICP (a separate Python process) from the same start.
//
// Cases (each a list of template -> target instances):
//   vertebrae  ref_20 -> the 10 raw vertebrae (landmarks: pre-alignment and measure)
//   femurs     femur_01 -> the 13 others (principal axes)
//   tosca      one pair per class of tosca5k (independent triangulations, .vts ground truth): the
//              geodesic error on the target between where each ground-truth template vertex
//              landed and its true match, normalized by sqrt(target area); direct and
//              symmetry-aware
//   sampling   vertebrae with the target remeshed to 1/5, 1x and 5x the template's density
//   partial    vertebrae with a fifth of the target cut away (along its longest axis)
//   noise      vertebrae with Gaussian noise of 0.5 % of the bounding-box diagonal on the target
//   (the last three on the first --robustness-specimens vertebrae, default 5)
// Per instance and method: l1/l2/lmax (template -> target, mm), mean landmark distance (the
// template vertex nearest to each landmark, carried by the fit), iterations, time, divergence
// (l2 after >= l2 before, or not finite). Writes OUT/CASE.csv, OUT/CASE_l2.png,
// OUT/tosca_cumulative[_symmetric].png and OUT/summary.json (cases run before into OUT stay in it).
#include <shapecorr/io/line_plot.h>
#include "program.h"

#include <shapecorr/evaluation.h>
#include <shapecorr/evaluation/descriptor_ranking.h>
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/registration.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <random>
#include <sstream>

namespace {
using eval::split;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
namespace SP = shapecorr::parameters;

Eigen::Vector3d vec(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }
Point point(const Eigen::Vector3d& v) { return Point(v.x(), v.y(), v.z()); }
double seconds_since(std::chrono::steady_clock::time_point t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); }

Mesh read(const std::string& path) {
  Mesh m;
  shapecorr::read_triangle_mesh(path, m);
  return m;
}

std::vector<Point> read_landmarks(const std::string& path) {
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  std::vector<Point> p;
  for(const auto& e : j) p.emplace_back(e["coordinates"][0].get<double>(), e["coordinates"][1].get<double>(), e["coordinates"][2].get<double>());
  return p;
}

// One template -> target registration problem.
struct Instance {
  std::string specimen;
  Mesh tmpl, target;
  std::vector<Point> landmarks_template, landmarks_target; // empty: none
  std::vector<std::size_t> truth, truth_sym;               // per template vertex: its target vertex (none: -1), TOSCA only
};
const std::size_t none = static_cast<std::size_t>(-1);

double mean_edge_length(const Mesh& m) {
  double s = 0;
  for(auto e : edges(m)) s += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  return s / static_cast<double>(num_edges(m));
}

// The target remeshed (isotropic remeshing) to `factor` x the template's vertex density.
Mesh resample(const Mesh& target, const Mesh& tmpl, double factor) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const double density = static_cast<double>(tmpl.number_of_vertices()) / PMP::area(tmpl);
  const double goal = density * factor * PMP::area(target); // vertices wanted
  const double length = mean_edge_length(target) * std::sqrt(static_cast<double>(target.number_of_vertices()) / goal);
  Mesh m = target;
  PMP::isotropic_remeshing(faces(m), length, m, CGAL::parameters::number_of_iterations(3).protect_constraints(false));
  m.collect_garbage();
  return m;
}

// The target without the fifth of its vertices furthest along its longest principal axis.
Mesh cut(const Mesh& target) {
  Eigen::MatrixXd V(target.number_of_vertices(), 3);
  for(auto v : vertices(target)) V.row(v.idx()) = vec(target.point(v)).transpose();
  const Eigen::RowVector3d c = V.colwise().mean();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es((V.rowwise() - c).transpose() * (V.rowwise() - c));
  const Eigen::Vector3d axis = es.eigenvectors().col(2);
  std::vector<double> t(target.number_of_vertices());
  for(auto v : vertices(target)) t[v.idx()] = (vec(target.point(v)) - c.transpose()).dot(axis);
  std::vector<double> sorted = t;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(0.8 * sorted.size()), sorted.end());
  const double limit = sorted[static_cast<std::size_t>(0.8 * sorted.size())];
  std::vector<Point> pts;
  std::vector<std::vector<std::size_t>> tris;
  std::vector<std::size_t> id(target.number_of_vertices(), none);
  for(auto f : faces(target)) {
    std::vector<std::size_t> tri;
    bool keep = true;
    for(auto v : CGAL::vertices_around_face(halfedge(f, target), target)) {
      if(t[v.idx()] > limit) keep = false;
      tri.push_back(v.idx());
    }
    if(!keep) continue;
    for(auto& i : tri) {
      if(id[i] == none) id[i] = pts.size(), pts.push_back(target.point(vertex_descriptor(static_cast<Mesh::size_type>(i))));
      i = id[i];
    }
    tris.push_back(tri);
  }
  Mesh m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, tris, m);
  return m;
}

// The target with Gaussian noise of `fraction` of its bounding-box diagonal on every vertex.
Mesh noisy(const Mesh& target, double fraction, unsigned seed) {
  Mesh m = target;
  const auto box = CGAL::Polygon_mesh_processing::bbox(m);
  const double diagonal = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) + std::pow(box.zmax() - box.zmin(), 2));
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, fraction * diagonal);
  for(auto v : vertices(m)) m.point(v) = Point(m.point(v).x() + g(rng), m.point(v).y() + g(rng), m.point(v).z() + g(rng));
  return m;
}

// Writes the vertices of a mesh as "x y z" lines (BCPD's input).
void write_points(const std::string& path, const Mesh& m) {
  std::ofstream out(path);
  out.precision(17);
  for(auto v : vertices(m)) out << m.point(v).x() << "\t" << m.point(v).y() << "\t" << m.point(v).z() << "\n";
}

// One method's result on one instance.
struct Result {
  std::string method;
  shapecorr::Surface_distance distance;
  double landmarks = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0;
  std::size_t iterations = 0;
  std::string stop;
  bool diverged = false;
  std::string error; // a method that threw or whose peer failed
  std::vector<double> geodesic_error, geodesic_error_sym; // TOSCA: per ground-truth point
};

struct Options {
  std::string data, out, bcpd, python = "/usr/bin/python3", helper;
  std::vector<std::string> cases = {"vertebrae", "femurs", "tosca", "sampling", "partial", "noise"};
  std::vector<std::string> methods = {"nicps", "andresen", "pauly", "cpd", "gmm-l2", "bcpd"};
  std::size_t skip = 0, limit = 0, truth_points = 500, robustness_specimens = 5;
  bool open3d = true;
};

// The instances of a case.
std::vector<std::function<Instance()>> instances(const std::string& kind, const Options& o) {
  std::vector<std::function<Instance()>> out;
  const std::string vdir = o.data + "/vertebrae";
  std::vector<std::string> vertebrae;
  for(const auto& e : std::filesystem::directory_iterator(vdir + "/raw"))
    if(e.path().extension() == ".ply") vertebrae.push_back(e.path().string());
  std::sort(vertebrae.begin(), vertebrae.end());
  auto vertebra = [vdir](const std::string& path) {
    Instance in;
    in.specimen = std::filesystem::path(path).stem().string();
    in.specimen = in.specimen.substr(4, in.specimen.find("_segment") - 4);
    in.tmpl = read(vdir + "/ref_20.ply");
    in.target = read(path);
    in.landmarks_template = read_landmarks(vdir + "/ref_20.json");
    in.landmarks_target = read_landmarks(std::filesystem::path(path).replace_extension(".json").string());
    return in;
  };
  if(kind == "vertebrae") {
    for(const auto& p : vertebrae) out.push_back([=] { return vertebra(p); });
  } else if(kind == "femurs") {
    for(int i = 2; i <= 14; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "femur_%02d", i);
      const std::string p = o.data + "/femurs/" + name + ".ply";
      if(!std::ifstream(p)) continue;
      out.push_back([=] {
        Instance in;
        in.specimen = name;
        in.tmpl = read(o.data + "/femurs/femur_01.ply");
        in.target = read(p);
        return in;
      });
    }
  } else if(kind == "tosca") {
    const std::string t = o.data + "/tosca5k/";
    std::ifstream pairs(t + "test_pairs.txt");
    std::string a, b;
    std::set<std::string> classes;
    while(pairs >> a >> b) {
      std::string cls = a;
      while(!cls.empty() && std::isdigit(static_cast<unsigned char>(cls.back()))) cls.pop_back();
      if(!classes.insert(cls).second) continue; // the first pair of each class
      out.push_back([=] {
        Instance in;
        in.specimen = a + "-" + b;
        in.tmpl = read(t + "meshes/" + a + ".off");
        in.target = read(t + "meshes/" + b + ".off");
        const auto va = shapecorr::read_vts(t + "corres/" + a + ".vts"), vb = shapecorr::read_vts(t + "corres/" + b + ".vts");
        const auto vs = shapecorr::read_vts(t + "corres/" + a + ".sym.vts");
        in.truth.assign(in.tmpl.number_of_vertices(), none);
        in.truth_sym.assign(in.tmpl.number_of_vertices(), none);
        for(std::size_t k = 0; k < va.size() && k < vb.size(); ++k) {
          if(va[k] < in.truth.size() && vb[k] < in.target.number_of_vertices() && in.truth[va[k]] == none) in.truth[va[k]] = vb[k];
          if(k < vs.size() && vs[k] < in.truth_sym.size() && vb[k] < in.target.number_of_vertices() && in.truth_sym[vs[k]] == none) in.truth_sym[vs[k]] = vb[k];
        }
        return in;
      });
    }
  } else {
    // the robustness cases: the first vertebrae
    const std::size_t count = std::min<std::size_t>(o.robustness_specimens, vertebrae.size());
    for(std::size_t i = 0; i < count; ++i) {
      const std::string p = vertebrae[i];
      if(kind == "sampling") {
        for(double factor : {0.2, 1.0, 5.0})
          out.push_back([=] {
            Instance in = vertebra(p);
            in.target = resample(in.target, in.tmpl, factor);
            in.specimen += factor == 0.2 ? "-x0.2" : factor == 1.0 ? "-x1" : "-x5";
            return in;
          });
      } else if(kind == "partial") {
        out.push_back([=] {
          Instance in = vertebra(p);
          in.target = cut(in.target);
          in.specimen += "-cut";
          return in;
        });
      } else if(kind == "noise") {
        out.push_back([=] {
          Instance in = vertebra(p);
          in.target = noisy(in.target, 0.005, 7 + static_cast<unsigned>(i));
          in.specimen += "-noise";
          return in;
        });
      }
    }
  }
  out.erase(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(std::min(o.skip, out.size())));
  if(o.limit > 0 && out.size() > o.limit) out.resize(o.limit);
  return out;
}

// Runs every method on one instance.
std::vector<Result> evaluate(Instance& in, const Options& o, const std::string& work, nlohmann::json& rigid_json) {
  std::vector<Result> results;
  const bool lm = !in.landmarks_template.empty();
  // the start (initialization only) and our rigid alignment from it
  Mesh start = in.tmpl;
  const auto init_np = SP::rigid_initialization(lm ? shapecorr::Rigid_initialization::LANDMARKS : shapecorr::Rigid_initialization::PRINCIPAL_AXES);
  const shapecorr::Rigid_alignment_report r0 = lm ? shapecorr::align_rigidly(start, in.target, init_np.landmark_points(in.landmarks_template).number_of_iterations(0),
                                                                             SP::landmark_points(in.landmarks_target))
                                                  : shapecorr::align_rigidly(start, in.target, init_np.number_of_iterations(0));
  shapecorr::apply_transform(start, r0.transform);
  const shapecorr::Surface_distance at_start = shapecorr::surface_distance(start, in.target);
  // the rigid stage as users run it (principal axes: ICP from every start, the best kept): the
  // input of every non-rigid method
  auto t0 = std::chrono::steady_clock::now();
  Mesh aligned = in.tmpl;
  const shapecorr::Rigid_alignment_report r = lm ? shapecorr::align_rigidly(aligned, in.target, init_np.landmark_points(in.landmarks_template),
                                                                            SP::landmark_points(in.landmarks_target))
                                                 : shapecorr::align_rigidly(aligned, in.target, init_np);
  shapecorr::apply_transform(aligned, r.transform);
  const double rigid_seconds = seconds_since(t0);
  // the rigid comparison with Open3D: both ICPs from one start (the initialization of least residual)
  Mesh from_start = start;
  const auto t_icp = std::chrono::steady_clock::now();
  const shapecorr::Rigid_alignment_report rs = shapecorr::align_rigidly(from_start, in.target, SP::rigid_initialization(shapecorr::Rigid_initialization::NONE));
  shapecorr::apply_transform(from_start, rs.transform);
  const double icp_seconds = seconds_since(t_icp);
  const double from_start_l2 = shapecorr::surface_distance(from_start, in.target).l2;
  // landmarks: the aligned template's vertex nearest to each template landmark
  std::vector<vertex_descriptor> steer;
  {
    std::vector<Point> moved;
    for(const auto& l : in.landmarks_template) moved.push_back(point(r.transform(vec(l))));
    for(const auto& m : moved) {
      vertex_descriptor best;
      double bd = std::numeric_limits<double>::infinity();
      for(auto v : vertices(aligned)) {
        const double d = CGAL::squared_distance(aligned.point(v), m);
        if(d < bd) bd = d, best = v;
      }
      steer.push_back(best);
    }
  }
  auto landmark_mean = [&](const Mesh& fitted) {
    if(steer.empty()) return std::numeric_limits<double>::quiet_NaN();
    double s = 0;
    for(std::size_t i = 0; i < steer.size(); ++i) s += std::sqrt(CGAL::squared_distance(fitted.point(steer[i]), in.landmarks_target[i]));
    return s / static_cast<double>(steer.size());
  };

  // TOSCA: geodesic distances on the target from the true matches of (at most truth_points) ground-truth vertices
  std::vector<std::size_t> gt;
  std::vector<Eigen::VectorXd> gd, gds;
  double sqrt_area = 1;
  Eigen::MatrixXd target_points; // the target's vertices, for the nearest vertex where a point landed
  if(!in.truth.empty()) {
    std::vector<std::size_t> all;
    for(std::size_t v = 0; v < in.truth.size(); ++v)
      if(in.truth[v] != none) all.push_back(v);
    const std::size_t stride = std::max<std::size_t>(1, all.size() / o.truth_points);
    for(std::size_t k = 0; k < all.size(); k += stride) gt.push_back(all[k]);
    shapecorr::Fast_marching_geodesics<Mesh> fm(in.target);
    for(std::size_t v : gt) {
      gd.push_back(fm.distances_from(in.truth[v]));
      gds.push_back(in.truth_sym[v] != none ? fm.distances_from(in.truth_sym[v]) : gd.back());
    }
    sqrt_area = std::sqrt(CGAL::Polygon_mesh_processing::area(in.target));
    target_points.resize(static_cast<Eigen::Index>(in.target.number_of_vertices()), 3);
    for(auto v : vertices(in.target)) target_points.row(v.idx()) = vec(in.target.point(v)).transpose();
  }
  auto measure = [&](Result& res, const Mesh& fitted, double before_l2) {
    res.distance = shapecorr::surface_distance(fitted, in.target);
    res.landmarks = landmark_mean(fitted);
    res.diverged = !std::isfinite(res.distance.l2) || res.distance.l2 >= before_l2;
    for(std::size_t k = 0; k < gt.size(); ++k) {
      const Point& p = fitted.point(vertex_descriptor(static_cast<Mesh::size_type>(gt[k])));
      Eigen::Index landed = 0;
      (target_points.rowwise() - vec(p).transpose()).rowwise().squaredNorm().minCoeff(&landed);
      res.geodesic_error.push_back(gd[k](static_cast<Eigen::Index>(landed)) / sqrt_area);
      res.geodesic_error_sym.push_back(std::min(gd[k](static_cast<Eigen::Index>(landed)), gds[k](static_cast<Eigen::Index>(landed))) / sqrt_area);
    }
  };
  {
    Result rigid;
    rigid.method = "rigid";
    rigid.seconds = rigid_seconds;
    rigid.iterations = r.iterations.size();
    rigid.stop = shapecorr::to_string(r.stop);
    measure(rigid, aligned, std::numeric_limits<double>::infinity());
    results.push_back(rigid);
  }
  rigid_json = {{"start_l2", at_start.l2}, {"shapecorr_l2", from_start_l2}, {"shapecorr_seconds", icp_seconds}, {"pipeline_l2", results[0].distance.l2}};
  // Open3D's point-to-plane ICP from the same start (a separate Python process)
  if(o.open3d) {
    const std::string s = work + "/start.ply", t = work + "/target.ply", tf = work + "/open3d.txt";
    CGAL::IO::write_polygon_mesh(s, start, CGAL::parameters::stream_precision(17));
    CGAL::IO::write_polygon_mesh(t, in.target, CGAL::parameters::stream_precision(17));
    const auto box = CGAL::Polygon_mesh_processing::bbox(in.target);
    const double diagonal = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) + std::pow(box.zmax() - box.zmin(), 2));
    std::filesystem::remove(tf);
    t0 = std::chrono::steady_clock::now();
    const std::string cmd = o.python + " " + o.helper + " " + s + " " + t + " " + std::to_string(0.05 * diagonal) + " " + tf + " > /dev/null 2>&1";
    const int rc = std::system(cmd.c_str());
    const double secs = seconds_since(t0);
    std::ifstream in_tf(tf);
    Eigen::Matrix4d M;
    bool ok = rc == 0 && static_cast<bool>(in_tf);
    for(int i = 0; ok && i < 16; ++i) ok = static_cast<bool>(in_tf >> M(i / 4, i % 4));
    if(ok) {
      Mesh o3 = start;
      for(auto v : vertices(o3)) o3.point(v) = point((M * vec(o3.point(v)).homogeneous()).head<3>());
      const auto d = shapecorr::surface_distance(o3, in.target);
      rigid_json["open3d_l2"] = d.l2;
      rigid_json["open3d_seconds"] = secs; // includes Python's start and the file reading
    } else {
      rigid_json["open3d_error"] = "the Open3D helper failed (python3-open3d installed?)";
    }
  }
  const double before = results[0].distance.l2;
  for(const std::string& method : o.methods) {
    Result res;
    res.method = method;
    Mesh fitted = aligned;
    t0 = std::chrono::steady_clock::now();
    try {
      if(method == "bcpd") {
        const std::string x = work + "/bcpd_x.txt", y = work + "/bcpd_y_in.txt", prefix = work + "/bcpd_";
        write_points(x, in.target);
        write_points(y, aligned);
        std::filesystem::remove(prefix + "y.txt");
        // roughly registered inputs: normalized by the target (-ux), gamma 0.1 (the README's advice);
        // accelerated (-A: Nystrom + k-d tree), outlier probability 0.1, beta 2, lambda 2 (its defaults)
        const std::string cmd = o.bcpd + " -x " + x + " -y " + y + " -o " + prefix + " -ux -g0.1 -w0.1 -b2 -l2 -A -r1 -c1e-5 -n500 -q > /dev/null 2>&1";
        if(std::system(cmd.c_str()) != 0) throw std::runtime_error("bcpd failed");
        std::ifstream yin(prefix + "y.txt");
        for(auto v : vertices(fitted)) {
          double a, b, c;
          if(!(yin >> a >> b >> c)) throw std::runtime_error("bcpd: short output");
          fitted.point(v) = Point(a, b, c);
        }
        res.stop = "bcpd";
      } else {
        auto out = fitted.add_property_map<vertex_descriptor, Point>("v:fitted").first;
        if(method == "nicps") {
          const auto rep = shapecorr::nicps(aligned, in.target, out);
          res.iterations = rep.iterations.size();
          res.stop = shapecorr::to_string(rep.stop);
        } else {
          shapecorr::Registration_report rep;
          if(method == "andresen") rep = shapecorr::andresen_registration(aligned, in.target, out);
          else if(method == "pauly") rep = shapecorr::pauly_registration(aligned, in.target, out);
          else if(method == "cpd") rep = shapecorr::cpd_registration(aligned, in.target, out);
          else if(method == "gmm-l2") rep = shapecorr::gmm_l2_registration(aligned, in.target, out);
          else throw std::runtime_error("unknown method " + method);
          res.iterations = rep.iterations.size();
          res.stop = shapecorr::to_string(rep.stop);
        }
        for(auto v : vertices(fitted)) fitted.point(v) = out[v];
        fitted.remove_property_map(out);
      }
      res.seconds = seconds_since(t0);
      measure(res, fitted, before);
    } catch(const std::exception& e) {
      res.seconds = seconds_since(t0);
      res.error = e.what();
      res.diverged = true;
    }
    std::cerr << "  " << method << ": l2 " << before << " -> " << res.distance.l2 << (res.landmarks == res.landmarks ? ", landmarks " + std::to_string(res.landmarks) : "")
              << (res.geodesic_error.empty() ? "" : ", geodesic error " + std::to_string(std::accumulate(res.geodesic_error.begin(), res.geodesic_error.end(), 0.0) / res.geodesic_error.size()))
              << ", " << res.seconds << " s" << (res.error.empty() ? "" : " (" + res.error + ")") << "\n";
    results.push_back(res);
  }
  return results;
}

double mean(const std::vector<double>& v) { return v.empty() ? std::numeric_limits<double>::quiet_NaN() : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }

// Fraction of the errors at most e, for e in [0, 0.25] (the Princeton protocol's curve).
shapecorr::Plot_curve cumulative(const std::string& label, const std::vector<double>& errors) {
  shapecorr::Plot_curve c;
  c.label = label;
  std::vector<double> s = errors;
  std::sort(s.begin(), s.end());
  for(int i = 0; i <= 50; ++i) {
    const double e = 0.25 * i / 50;
    c.x.push_back(e);
    c.y.push_back(s.empty() ? 0.0 : static_cast<double>(std::upper_bound(s.begin(), s.end(), e) - s.begin()) / static_cast<double>(s.size()));
  }
  return c;
}

} // namespace

int main(int argc, char** argv) {
  Options o;
  o.data = SHAPECORR_EVAL_DATA_DIR;
  o.out = "registration-evaluation";
  o.helper = std::string(SHAPECORR_EXPERIMENTS_DIR) + "/open3d_icp.py";
  const std::string usage = "[--data DIR] [--output DIR] [--cases vertebrae,femurs,tosca,sampling,partial,noise] "
                            "[--methods nicps,andresen,pauly,cpd,gmm-l2,bcpd] [--bcpd PATH] [--open3d 0|1] [--skip N] [--limit N] [--truth-points N] "
                            "[--robustness-specimens N]";
  const int rc = eval::parse_options(argc, argv, "evaluate_registration", usage, [&](const std::string& k, const std::string& v) {
    if(k == "--data") o.data = v;
    else if(k == "--output") o.out = v;
    else if(k == "--cases") o.cases = split(v, ',');
    else if(k == "--methods") o.methods = split(v, ',');
    else if(k == "--bcpd") o.bcpd = v;
    else if(k == "--open3d") o.open3d = v != "0";
    else if(k == "--skip") o.skip = std::stoul(v);
    else if(k == "--limit") o.limit = std::stoul(v);
    else if(k == "--truth-points") o.truth_points = std::max<std::size_t>(1, std::stoul(v));
    else if(k == "--robustness-specimens") o.robustness_specimens = std::stoul(v);
    else return false;
    return true;
  });
  if(rc >= 0) return rc;
  if(!eval::has_evaluation_data("evaluate_registration", o.data)) return 0;
  if(o.bcpd.empty()) o.methods.erase(std::remove(o.methods.begin(), o.methods.end(), "bcpd"), o.methods.end());
  std::filesystem::create_directories(o.out);
  const std::string work = o.out + "/work";
  std::filesystem::create_directories(work);
  // cases run before into the same folder stay in the summary (a case may be run again alone)
  nlohmann::json summary;
  if(std::ifstream previous{o.out + "/summary.json"}) {
    try {
      summary = nlohmann::json::parse(previous);
    } catch(const std::exception&) {
      summary = nlohmann::json();
    }
  }
  summary["methods"] = o.methods;
  summary["parameters"] = {{"nicps", "combinatorial Laplacian, alpha 100 / 1.1^f, 50 iterations"},
                           {"andresen", "time step 0.1, 500 diffusion steps"},
                           {"pauly", "alpha 100 / 1.1^f, 50 iterations, consistency width = mean edge length"},
                           {"cpd", "beta 2, lambda 3, w 0.1, rank 50, 150 iterations, tolerance 1e-5"},
                           {"gmm-l2", "scales 0.5,0.2,0.1,0.05, lambda 1e-2..1e-5, 300 control points, 50 L-BFGS iterations per level"},
                           {"bcpd", "-ux -g0.1 -w0.1 -b2 -l2 -A -r1 -c1e-5 -n500"},
                           {"open3d", "registration_icp point-to-plane, max correspondence distance 5% of the target's diagonal, 50 iterations"}};
  for(const std::string& kind : o.cases) {
    std::cerr << "case " << kind << "\n";
    std::ofstream csv(o.out + "/" + kind + ".csv");
    csv << "specimen,method,l1,l2,lmax,landmarks,geodesic_error,geodesic_error_sym,iterations,seconds,stop,diverged,error\n";
    std::map<std::string, std::vector<double>> l2_of, lm_of, sec_of, ge_of, ges_of;
    std::map<std::string, std::size_t> failures;
    std::map<std::string, std::vector<double>> all_errors, all_errors_sym;
    nlohmann::json rigid_rows = nlohmann::json::array();
    std::vector<std::string> names;
    for(const auto& make : instances(kind, o)) {
      Instance in = make();
      std::cerr << " " << in.specimen << " (" << in.tmpl.number_of_vertices() << " -> " << in.target.number_of_vertices() << " vertices)\n";
      names.push_back(in.specimen);
      nlohmann::json rigid_json;
      for(const Result& r : evaluate(in, o, work, rigid_json)) {
        csv << in.specimen << "," << r.method << "," << r.distance.l1 << "," << r.distance.l2 << "," << r.distance.lmax << "," << r.landmarks << ","
            << mean(r.geodesic_error) << "," << mean(r.geodesic_error_sym) << "," << r.iterations << "," << r.seconds << "," << r.stop << ","
            << (r.diverged ? 1 : 0) << "," << (r.error.empty() ? "" : "\"" + r.error + "\"") << "\n";
        l2_of[r.method].push_back(r.distance.l2);
        lm_of[r.method].push_back(r.landmarks);
        sec_of[r.method].push_back(r.seconds);
        if(!r.geodesic_error.empty()) {
          ge_of[r.method].push_back(mean(r.geodesic_error));
          ges_of[r.method].push_back(mean(r.geodesic_error_sym));
          all_errors[r.method].insert(all_errors[r.method].end(), r.geodesic_error.begin(), r.geodesic_error.end());
          all_errors_sym[r.method].insert(all_errors_sym[r.method].end(), r.geodesic_error_sym.begin(), r.geodesic_error_sym.end());
        }
        failures[r.method] += r.method != "rigid" && r.diverged ? 1 : 0;
      }
      rigid_json["specimen"] = in.specimen;
      rigid_rows.push_back(rigid_json);
      csv.flush();
    }
    nlohmann::json c;
    c["specimens"] = names;
    c["rigid_stage"] = rigid_rows;
    std::vector<shapecorr::Plot_curve> curves;
    double ymax = 0;
    for(const auto& kv : l2_of) {
      nlohmann::json m;
      m["mean_l2"] = mean(kv.second);
      m["l2"] = kv.second;
      std::vector<double> lms;
      for(double v : lm_of[kv.first])
        if(v == v) lms.push_back(v);
      if(!lms.empty()) m["mean_landmarks"] = mean(lms);
      m["mean_seconds"] = mean(sec_of[kv.first]);
      m["failures"] = failures[kv.first];
      if(!ge_of[kv.first].empty()) {
        m["mean_geodesic_error"] = mean(all_errors[kv.first]);
        m["mean_geodesic_error_sym"] = mean(all_errors_sym[kv.first]);
      }
      c["methods"][kv.first] = m;
      shapecorr::Plot_curve cv;
      cv.label = kv.first;
      for(std::size_t i = 0; i < kv.second.size(); ++i) {
        cv.x.push_back(static_cast<double>(i + 1));
        cv.y.push_back(std::isfinite(kv.second[i]) ? kv.second[i] : 0.0);
        ymax = std::max(ymax, cv.y.back());
      }
      curves.push_back(cv);
    }
    summary["cases"][kind] = c;
    if(!names.empty())
      shapecorr::write_png(o.out + "/" + kind + "_l2.png",
                           shapecorr::line_plot(curves, kind + ": l2 distance to the target per specimen", "specimen", "l2", static_cast<double>(names.size()) + 1, ymax * 1.1));
    if(!all_errors.empty()) {
      std::vector<shapecorr::Plot_curve> cum, cum_sym;
      for(const auto& kv : all_errors) cum.push_back(cumulative(kv.first, kv.second));
      for(const auto& kv : all_errors_sym) cum_sym.push_back(cumulative(kv.first, kv.second));
      shapecorr::write_png(o.out + "/" + kind + "_cumulative.png",
                           shapecorr::line_plot(cum, kind + ": correspondences within a geodesic error", "geodesic error / sqrt(area)", "fraction", 0.25, 1.0));
      shapecorr::write_png(o.out + "/" + kind + "_cumulative_symmetric.png",
                           shapecorr::line_plot(cum_sym, kind + ": the same, a left-right flip counted as correct", "geodesic error / sqrt(area)", "fraction", 0.25, 1.0));
    }
    std::ofstream(o.out + "/summary.json") << summary.dump(1) << "\n";
  }
  std::ofstream(o.out + "/summary.json") << summary.dump(1) << "\n";
  std::cerr << "wrote " << o.out << "/summary.json\n";
  return 0;
}
