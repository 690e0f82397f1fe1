// Rigid descriptor benchmarks on the libigl fandisk (../shared/data/classic/libigl/fandisk.off,
// 7229 vertices, 14454 faces; SHAPECORR_BENCH_MESH overrides; a generated torus stands in without
// data). Issue settings: 120 x 60 samples, support 100% (bounding-box diagonal), central point
// direction; 64 vertices spread over the mesh.
//  - one Spin Contour (fast construction) against one face-based spin image of the same
//    resolution (the reference) and one vertex spin image;
//  - comparing two contours (row-search L1, the kd-tree L1, the same exact L1 from two prepared
//    nearest-point indices, and the approximate L1 of two prepared distance fields) against
//    comparing two images (Johnson & Hebert correlation);
//  - with PCL (when built with it): PCL's spin image (153 bins) and SHOT352 for one point.
#include "../bench_mesh.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#ifdef SHAPECORR_WITH_PCL
#include <pcl/features/normal_3d_omp.h>
#include <pcl/features/shot.h>
#include <pcl/features/spin_image.h>
#include <pcl/point_types.h>
#endif

#include <cstdlib>
#include <iostream>

namespace {
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
namespace SP = shapecorr::parameters;

struct Fixture {
  Mesh mesh;
  std::unique_ptr<shapecorr::Spin_descriptors<Mesh>> sd;
  std::vector<shapecorr::Oriented_point> ops;
  std::vector<shapecorr::Spin_contour> contours;
  std::vector<shapecorr::Spin_image> images;
  Fixture() {
    bench::load_mesh<Mesh>(mesh, "classic/libigl/fandisk.off", [](Mesh& m) { shapecorr::make_torus(m, 2.0, 0.7, 120, 60); }, "a generated torus");
    const shapecorr::Spin_descriptors<Mesh> probe(mesh);
    sd.reset(new shapecorr::Spin_descriptors<Mesh>(mesh, SP::support_length(probe.bounding_box_diagonal())
                                                             .image_rows(std::size_t(120)).image_columns(std::size_t(60))
                                                             .spin_axis(shapecorr::Spin_axis::CENTRAL_DIRECTION)));
    const std::size_t n = mesh.number_of_vertices();
    for(std::size_t i = 0; i < 64; ++i) ops.push_back(sd->oriented_point(Mesh::Vertex_index(static_cast<Mesh::size_type>(i * n / 64))));
    for(const auto& op : ops) {
      contours.push_back(sd->spin_contour(op));
      images.push_back(sd->face_spin_image(op));
    }
  }
};
Fixture& fixture() {
  static Fixture f;
  return f;
}

template <typename F>
void per_point(benchmark::State& state, F&& f) {
  Fixture& fx = fixture();
  std::size_t i = 0;
  for(auto _ : state) benchmark::DoNotOptimize(f(*fx.sd, fx.ops[i++ % fx.ops.size()]));
  state.counters["faces"] = static_cast<double>(fx.mesh.number_of_faces());
}
void BM_SpinContour(benchmark::State& state) {
  per_point(state, [](const auto& sd, const auto& op) { return sd.spin_contour(op).size(); });
  double pts = 0;
  for(const auto& c : fixture().contours) pts += static_cast<double>(c.size());
  state.counters["mean_points"] = pts / static_cast<double>(fixture().contours.size());
}
BENCHMARK(BM_SpinContour)->Unit(benchmark::kMicrosecond);
void BM_Reference_FaceSpinImage(benchmark::State& state) {
  per_point(state, [](const auto& sd, const auto& op) { return sd.face_spin_image(op).values()[0]; });
}
BENCHMARK(BM_Reference_FaceSpinImage)->Unit(benchmark::kMicrosecond);
void BM_ExactFaceSpinImage(benchmark::State& state) {
  per_point(state, [](const auto& sd, const auto& op) { return sd.exact_face_spin_image(op).values().size(); });
}
BENCHMARK(BM_ExactFaceSpinImage)->Unit(benchmark::kMicrosecond);

void BM_SpinImage(benchmark::State& state) {
  per_point(state, [](const auto& sd, const auto& op) { return sd.spin_image(op).values()[0]; });
}
BENCHMARK(BM_SpinImage)->Unit(benchmark::kMicrosecond);

// The i-th of the 64 x 63 ordered pairs of distinct fixture descriptors: consecutive iterations
// compare different pairs, so the branch predictor cannot learn one short pattern (a branchy
// distance measured over a few repeated pairs looks faster than it is on real data).
std::pair<std::size_t, std::size_t> pair_of(std::size_t i) {
  const std::size_t x = i % 64, y = (x + 1 + (i / 64) % 63) % 64;
  return {x, y};
}

void BM_CompareContours(benchmark::State& state) {
  Fixture& fx = fixture();
  std::size_t i = 0;
  for(auto _ : state) {
    const auto p = pair_of(i++);
    benchmark::DoNotOptimize(shapecorr::contour_l1_distance(fx.contours[p.first], fx.contours[p.second]));
  }
}
BENCHMARK(BM_CompareContours)->Unit(benchmark::kMicrosecond);
void BM_CompareContours_KdTree(benchmark::State& state) {
  Fixture& fx = fixture();
  std::vector<std::vector<std::array<double, 2>>> pts;
  for(const auto& c : fx.contours) pts.push_back(c.points());
  std::size_t i = 0;
  for(auto _ : state) {
    const auto p = pair_of(i++);
    benchmark::DoNotOptimize(shapecorr::point_set_l1_distance(pts[p.first], pts[p.second]));
  }
}
BENCHMARK(BM_CompareContours_KdTree)->Unit(benchmark::kMicrosecond);
void BM_Reference_CompareImages(benchmark::State& state) {
  Fixture& fx = fixture();
  std::size_t i = 0;
  for(auto _ : state) {
    const auto p = pair_of(i++);
    benchmark::DoNotOptimize(shapecorr::spin_image_correlation(fx.images[p.first], fx.images[p.second]).first);
  }
}
BENCHMARK(BM_Reference_CompareImages)->Unit(benchmark::kMicrosecond);

// The fixture's contours prepared for comparisons (distance fields or nearest-point indices).
template <typename Prepared>
std::vector<Prepared> prepared(const std::vector<shapecorr::Spin_contour>& contours) {
  return std::vector<Prepared>(contours.begin(), contours.end());
}
// Preparing one contour (the next of the fixture at each iteration).
template <typename Prepared>
void prepare_one(benchmark::State& state) {
  Fixture& fx = fixture();
  std::size_t i = 0;
  for(auto _ : state) benchmark::DoNotOptimize(Prepared(fx.contours[i++ % 64]).memory_bytes());
}

// The same pairs through the contours' distance fields (approximate L1, prepared once per
// contour); counters: the largest absolute and relative difference from the exact L1 over all
// 64 x 64 pairs, and the field's bytes.
void BM_CompareContours_DistanceField(benchmark::State& state) {
  Fixture& fx = fixture();
  const auto f = prepared<shapecorr::Contour_distance_field>(fx.contours);
  double abs_err = 0, rel_err = 0;
  for(std::size_t a = 0; a < 64; ++a)
    for(std::size_t b = 0; b < 64; ++b) {
      const double e = std::abs(shapecorr::approximate_contour_l1_distance(f[a], f[b]) - shapecorr::contour_l1_distance(fx.contours[a], fx.contours[b]));
      abs_err = std::max(abs_err, e);
      if(a != b) rel_err = std::max(rel_err, e / shapecorr::contour_l1_distance(fx.contours[a], fx.contours[b]));
    }
  std::size_t i = 0;
  for(auto _ : state) {
    const auto p = pair_of(i++);
    benchmark::DoNotOptimize(shapecorr::approximate_contour_l1_distance(f[p.first], f[p.second]));
  }
  state.counters["max_abs_error"] = abs_err;
  state.counters["max_rel_error"] = rel_err;
  state.counters["error_bound"] = f[0].error_bound();
  state.counters["field_bytes"] = static_cast<double>(f[0].memory_bytes());
}
BENCHMARK(BM_CompareContours_DistanceField)->Unit(benchmark::kMicrosecond);
void BM_ContourDistanceField_Prepare(benchmark::State& state) { prepare_one<shapecorr::Contour_distance_field>(state); }
BENCHMARK(BM_ContourDistanceField_Prepare)->Unit(benchmark::kMicrosecond);

// The same pairs through the contours' nearest-point indices (exact L1, prepared once per
// contour); counters: the largest difference from contour_l1_distance over all 64 x 64 pairs, the
// fraction of cells that take the row search, the index's bytes and pieces.
void BM_CompareContours_NearestPointIndex(benchmark::State& state) {
  Fixture& fx = fixture();
  const auto x = prepared<shapecorr::Contour_nearest_point_index>(fx.contours);
  double diff = 0, slow = 0, bytes = 0, pieces = 0;
  for(std::size_t a = 0; a < 64; ++a) {
    for(std::size_t b = 0; b < 64; ++b)
      diff = std::max(diff, std::abs(shapecorr::contour_l1_distance(x[a], x[b]) - shapecorr::contour_l1_distance(fx.contours[a], fx.contours[b])));
    slow += x[a].slow_cell_fraction() / 64;
    bytes += static_cast<double>(x[a].memory_bytes()) / 64;
    pieces += static_cast<double>(x[a].number_of_pieces()) / 64;
  }
  std::size_t i = 0;
  for(auto _ : state) {
    const auto p = pair_of(i++);
    benchmark::DoNotOptimize(shapecorr::contour_l1_distance(x[p.first], x[p.second]));
  }
  state.counters["max_abs_difference"] = diff;
  state.counters["slow_cells"] = slow;
  state.counters["index_bytes"] = bytes;
  state.counters["pieces"] = pieces;
}
BENCHMARK(BM_CompareContours_NearestPointIndex)->Unit(benchmark::kMicrosecond);
void BM_ContourNearestPointIndex_Prepare(benchmark::State& state) { prepare_one<shapecorr::Contour_nearest_point_index>(state); }
BENCHMARK(BM_ContourNearestPointIndex_Prepare)->Unit(benchmark::kMicrosecond);

// Matching: one source descriptor (the next of the set at each iteration) against the 64 of the
// set (time per comparison); contours use the early exit at the second-best distance.
template <typename Descriptor, typename Distance>
void match_one_against_all(benchmark::State& state, const std::vector<Descriptor>& set, Distance distance) {
  std::size_t i = 0;
  for(auto _ : state) {
    const std::vector<Descriptor> one(1, set[i++ % set.size()]);
    benchmark::DoNotOptimize(shapecorr::match_descriptors(one, set, distance, 1)[0].target);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * set.size()));
}
void BM_MatchContour_PerComparison(benchmark::State& state) {
  match_one_against_all(state, fixture().contours, shapecorr::Contour_l1_distance());
}
BENCHMARK(BM_MatchContour_PerComparison)->Unit(benchmark::kMicrosecond);
void BM_Reference_MatchImage_PerComparison(benchmark::State& state) {
  match_one_against_all(state, fixture().images, shapecorr::Spin_image_distance());
}
BENCHMARK(BM_Reference_MatchImage_PerComparison)->Unit(benchmark::kMicrosecond);
void BM_MatchDistanceField_PerComparison(benchmark::State& state) {
  match_one_against_all(state, prepared<shapecorr::Contour_distance_field>(fixture().contours), shapecorr::Approximate_contour_l1_distance());
}
BENCHMARK(BM_MatchDistanceField_PerComparison)->Unit(benchmark::kMicrosecond);
void BM_MatchNearestPointIndex_PerComparison(benchmark::State& state) {
  match_one_against_all(state, prepared<shapecorr::Contour_nearest_point_index>(fixture().contours), shapecorr::Indexed_contour_l1_distance());
}
BENCHMARK(BM_MatchNearestPointIndex_PerComparison)->Unit(benchmark::kMicrosecond);

#ifdef SHAPECORR_WITH_PCL
struct Pcl_fixture {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
  pcl::PointCloud<pcl::Normal>::Ptr normals{new pcl::PointCloud<pcl::Normal>};
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree{new pcl::search::KdTree<pcl::PointXYZ>};
  double diagonal = 0, mr = 0;
  Pcl_fixture() {
    Fixture& fx = fixture();
    for(auto v : fx.mesh.vertices()) {
      const auto& p = fx.mesh.point(v);
      cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
    }
    for(auto v : fx.mesh.vertices()) {
      const Eigen::Vector3d n = fx.sd->oriented_point(v, shapecorr::Spin_axis::NORMAL).axis;
      normals->push_back(pcl::Normal(static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())));
    }
    tree->setInputCloud(cloud);
    diagonal = fx.sd->bounding_box_diagonal();
    mr = fx.sd->mesh_resolution();
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr one(std::size_t i) const {
    pcl::PointCloud<pcl::PointXYZ>::Ptr k(new pcl::PointCloud<pcl::PointXYZ>);
    k->push_back((*cloud)[i]);
    return k;
  }
  pcl::PointCloud<pcl::Normal>::Ptr one_normal(std::size_t i) const {
    pcl::PointCloud<pcl::Normal>::Ptr k(new pcl::PointCloud<pcl::Normal>);
    k->push_back((*normals)[i]);
    return k;
  }
};
Pcl_fixture& pcl_fixture() {
  static Pcl_fixture f;
  return f;
}
void BM_PCL_SpinImage(benchmark::State& state) {
  Pcl_fixture& p = pcl_fixture();
  const std::size_t n = p.cloud->size();
  std::size_t i = 0;
  for(auto _ : state) {
    pcl::SpinImageEstimation<pcl::PointXYZ, pcl::Normal, pcl::Histogram<153>> si(8, 0.0, 0); // 9 x 17 bins, no angle limit
    const std::size_t k = (i++ * 113) % n;
    si.setInputCloud(p.one(k));
    si.setSearchSurface(p.cloud);
    si.setInputNormals(p.one_normal(k)); // the oriented point's normal (no support angle: no others needed)
    si.setSearchMethod(p.tree);
    si.setRadiusSearch(p.diagonal);
    pcl::PointCloud<pcl::Histogram<153>> out;
    si.compute(out);
    benchmark::DoNotOptimize(out[0].histogram[0]);
  }
}
BENCHMARK(BM_PCL_SpinImage)->Unit(benchmark::kMicrosecond);
void BM_PCL_SHOT352(benchmark::State& state) {
  Pcl_fixture& p = pcl_fixture();
  const std::size_t n = p.cloud->size();
  std::size_t i = 0;
  for(auto _ : state) {
    pcl::SHOTEstimation<pcl::PointXYZ, pcl::Normal, pcl::SHOT352> shot;
    shot.setInputCloud(p.one((i++ * 113) % n));
    shot.setSearchSurface(p.cloud);
    shot.setInputNormals(p.normals);
    shot.setSearchMethod(p.tree);
    shot.setRadiusSearch(30 * p.mr);
    pcl::PointCloud<pcl::SHOT352> out;
    shot.compute(out);
    benchmark::DoNotOptimize(out[0].descriptor[0]);
  }
}
BENCHMARK(BM_PCL_SHOT352)->Unit(benchmark::kMicrosecond);
#endif

} // namespace

BENCHMARK_MAIN();
