// Fully automatic near-isometric registration (chapter 5) on synthetic pairs with exact ground
// truth: the creature of the primitives (a sphere with five limbs) and a moved, renumbered copy
// (no symmetry: every match correct), a flat
// and a rolled strip (an isometry; correct up to the rectangle's four symmetries); the two coarse
// solvers agree; run() keeps the start of lowest energy; the same seed gives the same result; bad
// input; a near-isometric pair: a long-limbed creature and a bent, renumbered copy. (The default
// creature, bent and renumbered, is not here: its limbs are short, the coarse level finds a wrong
// configuration from most starts; see the limitations in Isometric_correspondence's documentation.)
#include "test_meshes.h"

#include <shapecorr/mesh.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration/isometric_correspondence.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <numeric>
#include <random>

namespace SP = shapecorr::parameters;

namespace {

struct Soup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

template <typename Mesh>
Soup soup_of(const Mesh& m) {
  Soup s;
  const auto order = test::vertices_in_index_order(m);
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> id;
  for(std::size_t i = 0; i < order.size(); ++i) {
    const auto& p = get(CGAL::vertex_point, m, order[i]);
    s.points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    id[order[i]] = i;
  }
  for(auto f : faces(m)) {
    std::array<std::size_t, 3> t;
    int c = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) t[std::size_t(c++)] = id[v];
    s.triangles.push_back(t);
  }
  return s;
}

// the soup with vertex i moved by f and renumbered to perm[i]
template <typename F>
Soup transformed(const Soup& s, const std::vector<std::size_t>& perm, F&& f) {
  Soup out;
  out.points.resize(s.points.size());
  for(std::size_t i = 0; i < s.points.size(); ++i) out.points[perm[i]] = f(s.points[i]);
  for(const auto& t : s.triangles) out.triangles.push_back({perm[t[0]], perm[t[1]], perm[t[2]]});
  return out;
}

std::vector<std::size_t> shuffled(std::size_t n, unsigned seed) {
  std::vector<std::size_t> p(n);
  std::iota(p.begin(), p.end(), 0);
  std::shuffle(p.begin(), p.end(), std::mt19937(seed));
  return p;
}

// The creature of the primitives: five limbs of different lengths, no symmetry.
Soup creature() {
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> m;
  shapecorr::make_creature(m, 4);
  return soup_of(m);
}

Soup flat_strip() {
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> m;
  shapecorr::make_grid(m, 40, 16, 2.0, 0.8);
  return soup_of(m);
}

// roll the strip's x axis ([0, 2]) onto half a circle
std::array<double, 3> rolled(const std::array<double, 3>& p) {
  const double R = 2.0 / M_PI, t = p[0] / R;
  return {R * std::sin(t), p[1], R * (1 - std::cos(t))};
}

template <typename Mesh>
Mesh mesh_of(const Soup& s) {
  Mesh m;
  shapecorr::internal::soup_to_mesh(s.points, s.triangles, m);
  return m;
}

// geodesic error of each match on the target, against the truth `truth[source vertex]`, in mean edge lengths
template <typename Method>
std::vector<double> match_errors(const Method& method, const std::vector<shapecorr::Vertex_match>& matches,
                                 const std::vector<std::size_t>& truth, const Eigen::MatrixXd& target_geodesics, double edge) {
  std::vector<double> e;
  for(const auto& m : matches) e.push_back(target_geodesics(long(m.target), long(truth[m.source])) / edge);
  (void)method;
  return e;
}

double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

template <typename Mesh>
Eigen::MatrixXd all_geodesics(const Mesh& m) {
  shapecorr::Fast_marching_geodesics<Mesh> e(m);
  Eigen::MatrixXd d(long(e.number_of_vertices()), long(e.number_of_vertices()));
  for(std::size_t i = 0; i < e.number_of_vertices(); ++i) d.col(long(i)) = e.distances_from(i);
  return d;
}

double mean_edge(const Soup& s) {
  double sum = 0;
  for(const auto& t : s.triangles)
    for(int c = 0; c < 3; ++c) {
      const auto &a = s.points[t[std::size_t(c)]], &b = s.points[t[std::size_t((c + 1) % 3)]];
      sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
  return sum / double(3 * s.triangles.size());
}

// The soup without the triangles that have a vertex beyond `height` along `dir` (a limb cut off:
// a boundary), its vertices renumbered in order of first use.
Soup cut_off(const Soup& s, std::array<double, 3> dir, double height) {
  const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  std::vector<std::size_t> new_of_old(s.points.size(), s.points.size());
  Soup out;
  for(const auto& t : s.triangles) {
    bool beyond = false;
    for(std::size_t v : t) beyond = beyond || (s.points[v][0] * dir[0] + s.points[v][1] * dir[1] + s.points[v][2] * dir[2]) / n > height;
    if(beyond) continue;
    std::array<std::size_t, 3> nt;
    for(std::size_t c = 0; c < 3; ++c) {
      std::size_t& id = new_of_old[t[c]];
      if(id == s.points.size()) {
        id = out.points.size();
        out.points.push_back(s.points[t[c]]);
      }
      nt[c] = id;
    }
    out.triangles.push_back(nt);
  }
  return out;
}

// A long-limbed creature (limbs 2.5 times the default's) and a copy with its longest limb bent by
// 10 degrees, renumbered (seed 11); the target's all-pairs geodesics and mean edge length.
struct Bent_pair {
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  Soup a, b;
  std::vector<std::size_t> perm;
  Mesh source, target;
  Eigen::MatrixXd gt;
  double edge = 0;
  Bent_pair() {
    Mesh straight, bent;
    shapecorr::make_creature(straight, 4, 0.0, 2.5);
    shapecorr::make_creature(bent, 4, 10.0, 2.5);
    a = soup_of(straight);
    perm = shuffled(a.points.size(), 11);
    b = transformed(soup_of(bent), perm, [](const std::array<double, 3>& p) { return p; });
    source = mesh_of<Mesh>(a);
    target = mesh_of<Mesh>(b);
    gt = all_geodesics(target);
    edge = mean_edge(b);
  }
};

} // namespace

TEMPLATE_LIST_TEST_CASE("isometric correspondence: a creature and its moved, renumbered copy", "[isometric]", test::Mesh_types) {
  const Soup a = creature();
  const std::vector<std::size_t> perm = shuffled(a.points.size(), 5);
  const Soup b = transformed(a, perm, [](const std::array<double, 3>& p) {
    // a rotation about z by 40 degrees and a shift
    const double c = std::cos(0.7), s = std::sin(0.7);
    return std::array<double, 3>{c * p[0] - s * p[1] + 3, s * p[0] + c * p[1] - 1, p[2] + 0.5};
  });
  const TestType source = mesh_of<TestType>(a), target = mesh_of<TestType>(b);
  shapecorr::Isometric_correspondence<TestType> method(source, target, SP::number_of_levels(2).number_of_eigenpairs(30));
  const shapecorr::Isometric_correspondence_report& report = method.run();
  const Eigen::MatrixXd gt = all_geodesics(target);
  const double edge = mean_edge(b);
  // the coarse level: 8 of 10 features matched, each within 2 edge lengths after local optimization
  REQUIRE(report.levels.size() == 3);
  CHECK(report.levels[0].new_matches == 8);
  CHECK(report.levels[0].optimal);
  const std::vector<double> coarse = match_errors(method, report.levels[0].snapshots.back(), perm, gt, edge);
  CHECK(max_of(coarse) <= 2.0);
  // all levels: 8 + 16 + 16 matches, every one within 2 edge lengths
  CHECK(report.matches.size() == 40);
  const std::vector<double> all = match_errors(method, report.matches, perm, gt, edge);
  CHECK(max_of(all) <= 2.0);
  // local optimization never increases E
  for(const auto& level : report.levels)
    for(std::size_t i = 1; i < level.energies.size(); ++i) CHECK(level.energies[i] <= level.energies[i - 1] * (1 + 1e-12));
  // the dense map: mean error below one edge length, at least 90 % within one edge
  const auto& dense = method.dense_map();
  REQUIRE(dense.size() == a.points.size());
  double sum = 0;
  std::size_t close = 0;
  for(std::size_t v = 0; v < dense.size(); ++v) {
    const double e = gt(long(dense[v]), long(perm[v])) / edge;
    sum += e;
    close += e <= 1.0 ? 1 : 0;
  }
  INFO("dense mean error " << sum / double(dense.size()) << " edges, " << close << " of " << dense.size() << " within one edge");
  CHECK(sum / double(dense.size()) < 1.0);
  CHECK(double(close) >= 0.9 * double(dense.size()));
}

TEST_CASE("isometric correspondence: a long-limbed creature and a bent, renumbered copy (near-isometric), over seeds", "[isometric]") {
  // limbs 2.5 times as long as the default creature's: they are the extremities, which furthest
  // point sampling finds first on both shapes (with the default limbs it picks body points and
  // the renumbered pair fails: see the limitations); the longest limb bent by 10 degrees
  typedef Bent_pair::Mesh Mesh;
  const Bent_pair pair;
  const Soup& a = pair.a;
  const std::vector<std::size_t>& perm = pair.perm;
  const Mesh &source = pair.source, &target = pair.target;
  const Eigen::MatrixXd& gt = pair.gt;
  const double edge = pair.edge;
  for(unsigned seed = 0; seed < 6; ++seed) {
    shapecorr::Isometric_correspondence<Mesh> method(source, target, SP::number_of_levels(2).random_seed(seed));
    const auto& report = method.run();
    const std::vector<double> e = match_errors(method, report.matches, perm, gt, edge);
    double dense = 0;
    for(std::size_t v = 0; v < a.points.size(); ++v) dense += gt(long(method.dense_map()[v]), long(perm[v])) / edge;
    dense /= double(a.points.size());
    // measured: largest sparse error 2.3-2.7 edge lengths, dense mean 0.01; a wrong configuration
    // puts matches 30 edge lengths away and the dense map 10 on average
    INFO("seed " << seed << ": largest error " << max_of(e) << " edges over " << e.size() << " matches; dense mean " << dense << " edges");
    CHECK(e.size() == 40);
    CHECK(max_of(e) <= 4.0);
    CHECK(dense <= 0.1);
  }
}

TEST_CASE("isometric correspondence: each trim descriptor (GSC, WKS, ISC) on the long-limbed, bent, renumbered pair", "[isometric]") {
  typedef Bent_pair::Mesh Mesh;
  const Bent_pair pair;
  const std::vector<std::size_t>& perm = pair.perm;
  const Mesh &source = pair.source, &target = pair.target;
  const Eigen::MatrixXd& gt = pair.gt;
  const double edge = pair.edge;
  // GSC and WKS: right from seeds 0 and 1 (measured: from each of 0 to 5); ISC: right from 4 of
  // seeds 0 to 5 (measured: 0, 3, 4, 5; from 1 and 2 the coarse level keeps a wrong configuration,
  // matches tens of edge lengths away)
  std::size_t isc_right = 0;
  for(auto trim : {shapecorr::Trim_descriptor::GEODESIC_SPIN_CONTOUR, shapecorr::Trim_descriptor::WAVE_KERNEL_SIGNATURE,
                   shapecorr::Trim_descriptor::INTRINSIC_SHAPE_CONTEXT}) {
    const bool isc = trim == shapecorr::Trim_descriptor::INTRINSIC_SHAPE_CONTEXT;
    for(unsigned seed = 0; seed < (isc ? 6u : 2u); ++seed) {
      shapecorr::Isometric_correspondence<Mesh> method(source, target, SP::number_of_levels(1).trim_descriptor(trim).random_seed(seed));
      const auto& report = method.run();
      const std::vector<double> e = match_errors(method, report.matches, perm, gt, edge);
      INFO("trim " << int(trim) << ", seed " << seed << ": largest error " << max_of(e) << " edges over " << e.size() << " matches; "
                   << report.levels[0].candidates << " candidate pairs");
      CHECK(e.size() == 24);
      CHECK(report.levels[0].candidates < 100); // the trim keeps fewer pairs than all of them
      if(isc) isc_right += max_of(e) <= 4.0 ? 1 : 0;
      else CHECK(max_of(e) <= 4.0);
    }
  }
  CHECK(isc_right >= 4);
}

TEST_CASE("isometric correspondence: run() keeps the start of lowest energy after local optimization", "[isometric]") {
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  Mesh straight, bent;
  shapecorr::make_creature(straight, 3);
  shapecorr::make_creature(bent, 3, 30.0);
  const Soup a = soup_of(straight);
  const Soup b = transformed(soup_of(bent), shuffled(a.points.size(), 4), [](const std::array<double, 3>& p) { return p; });
  const Mesh source = mesh_of<Mesh>(a), target = mesh_of<Mesh>(b);
  const auto np = SP::number_of_levels(0).number_of_eigenpairs(0).number_of_starts(4).random_seed(7);
  std::vector<double> energies;
  for(unsigned seed = 7; seed < 11; ++seed) {
    shapecorr::Isometric_correspondence<Mesh> one(source, target, SP::random_seed(seed));
    one.sample_features();
    one.trim();
    one.solve_coarse();
    one.optimize_locally();
    energies.push_back(one.report().levels[0].energies.back());
  }
  shapecorr::Isometric_correspondence<Mesh> method(source, target, np);
  const auto& report = method.run();
  REQUIRE(report.levels.size() == 1);
  CHECK(report.starts == 4);
  const std::size_t best = std::size_t(std::min_element(energies.begin(), energies.end()) - energies.begin());
  CHECK(report.chosen_seed == 7 + best);
  CHECK(report.levels[0].energies.back() == Approx(energies[best]).epsilon(1e-12));
  CHECK(report.matches.size() == 8);
}

TEST_CASE("isometric correspondence: a flat and a rolled strip, up to the rectangle's symmetries", "[isometric]") {
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  const Soup a = flat_strip();
  const std::vector<std::size_t> perm = shuffled(a.points.size(), 9);
  const Soup b = transformed(a, perm, rolled);
  const Mesh source = mesh_of<Mesh>(a), target = mesh_of<Mesh>(b);
  shapecorr::Isometric_correspondence<Mesh> method(source, target, SP::number_of_levels(1).number_of_eigenpairs(0));
  const auto& report = method.run();
  const Eigen::MatrixXd gt = all_geodesics(target);
  const double edge = mean_edge(b);
  // the four symmetries of the grid: vertex (i, j) -> (i or 40 - i, j or 16 - j)
  auto sym = [&](std::size_t v, int s) {
    std::size_t i = v % 41, j = v / 41;
    if(s & 1) i = 40 - i;
    if(s & 2) j = 16 - j;
    return perm[j * 41 + i];
  };
  double best = std::numeric_limits<double>::infinity();
  int best_s = 0;
  for(int s = 0; s < 4; ++s) {
    double worst = 0;
    for(const auto& m : report.matches) worst = std::max(worst, gt(long(m.target), long(sym(m.source, s))) / edge);
    if(worst < best) { best = worst; best_s = s; }
  }
  INFO("symmetry " << best_s << ", largest match error " << best << " edge lengths over " << report.matches.size() << " matches");
  CHECK(report.matches.size() == 8 + 16);
  CHECK(best <= 2.0);
}

TEST_CASE("isometric correspondence: the coarse solvers agree, the seed fixes the result", "[isometric]") {
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  const Soup a = creature();
  const std::vector<std::size_t> perm = shuffled(a.points.size(), 3);
  const Soup b = transformed(a, perm, [](const std::array<double, 3>& p) { return p; });
  const Mesh source = mesh_of<Mesh>(a), target = mesh_of<Mesh>(b);
  auto coarse = [&](shapecorr::Coarse_solver solver, unsigned seed) {
    shapecorr::Isometric_correspondence<Mesh> method(source, target, SP::coarse_solver(solver).random_seed(seed).number_of_candidates(4));
    method.sample_features();
    method.trim();
    method.solve_coarse();
    return std::make_pair(method.report().levels[0], method.matches());
  };
  const auto bb = coarse(shapecorr::Coarse_solver::BRANCH_AND_BOUND, 1);
  const auto mip = coarse(shapecorr::Coarse_solver::MIXED_INTEGER_PROGRAM, 1);
  CHECK(bb.first.objective == Approx(mip.first.objective).epsilon(1e-7));
  CHECK(bb.first.optimal);
  const auto again = coarse(shapecorr::Coarse_solver::BRANCH_AND_BOUND, 1);
  REQUIRE(again.second.size() == bb.second.size());
  for(std::size_t i = 0; i < bb.second.size(); ++i) {
    CHECK(again.second[i].source == bb.second[i].source);
    CHECK(again.second[i].target == bb.second[i].target);
  }
  const auto other = coarse(shapecorr::Coarse_solver::BRANCH_AND_BOUND, 2);
  bool same = other.second.size() == bb.second.size();
  for(std::size_t i = 0; same && i < bb.second.size(); ++i) same = other.second[i].source == bb.second[i].source;
  CHECK_FALSE(same); // another seed starts the sampling elsewhere
}

TEST_CASE("isometric correspondence: bad input", "[isometric]") {
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  const Soup a = creature();
  const Mesh sphere = mesh_of<Mesh>(a);
  // two components
  Soup two = a;
  const std::size_t n = two.points.size();
  for(std::size_t i = 0; i < n; ++i) two.points.push_back({a.points[i][0] + 5, a.points[i][1], a.points[i][2]});
  for(std::size_t t = 0, m = a.triangles.size(); t < m; ++t)
    two.triangles.push_back({a.triangles[t][0] + n, a.triangles[t][1] + n, a.triangles[t][2] + n});
  const Mesh pair = mesh_of<Mesh>(two);
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<Mesh>(sphere, pair), shapecorr::Invalid_input);
  // fewer vertices than features
  Mesh tetra;
  shapecorr::internal::soup_to_mesh(std::vector<std::array<double, 3>>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                          std::vector<std::array<std::size_t, 3>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, tetra);
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<Mesh>(tetra, sphere), shapecorr::Invalid_input);
  // NaN coordinates
  Soup bad = a;
  bad.points[7][1] = std::numeric_limits<double>::quiet_NaN();
  const Mesh nan_mesh = mesh_of<Mesh>(bad);
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<Mesh>(nan_mesh, sphere), shapecorr::Invalid_input);
  // parameters
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<Mesh>(sphere, sphere, SP::number_of_features(1)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<Mesh>(sphere, sphere, SP::match_fraction(0.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<Mesh>(sphere, sphere, SP::number_of_candidates(0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<Mesh>(sphere, sphere, SP::number_of_starts(0)), shapecorr::Invalid_argument);
  // stages out of order
  shapecorr::Isometric_correspondence<Mesh> method(sphere, sphere);
  CHECK_THROWS_AS(method.solve_coarse(), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(method.compute_dense_map(), shapecorr::Invalid_argument);
}

TEST_CASE("isometric correspondence: a partial shape (a limb cut off, a boundary) is accepted", "[isometric]") {
  // Documented behaviour, not accuracy: shapes with boundaries run through every stage and give a
  // valid map. (On this creature the matches of a cut shape are wrong: see the limitations.)
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  const Soup a = creature();
  const Soup cut = cut_off(a, {-0.5, -0.6, 0.7}, 1.6);
  REQUIRE(cut.points.size() < a.points.size());
  const Mesh whole = mesh_of<Mesh>(a), part = mesh_of<Mesh>(cut);
  REQUIRE(shapecorr::validate_mesh(part).boundary_edges > 0);
  for(int direction = 0; direction < 2; ++direction) {
    const Mesh& source = direction == 0 ? part : whole;
    const Mesh& target = direction == 0 ? whole : part;
    shapecorr::Isometric_correspondence<Mesh> method(source, target, SP::number_of_levels(1));
    const auto& report = method.run();
    CHECK(report.matches.size() == 8 + 16);
    REQUIRE(method.dense_map().size() == num_vertices(source));
    for(std::size_t t : method.dense_map()) CHECK(t < num_vertices(target));
  }
}

namespace {

// shapecorr::make_animal, bilaterally symmetric (mirror plane y = 0): its mirror image is an
// isometry that reverses the orientation
Soup animal(int subdivisions) {
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> m;
  shapecorr::make_animal(m, subdivisions);
  return soup_of(m);
}

// a proper rigid motion: a rotation about (1, 2, 3) by 50 degrees and a shift
std::array<double, 3> moved(const std::array<double, 3>& p) {
  const Eigen::Vector3d x = Eigen::AngleAxisd(0.87, Eigen::Vector3d(1, 2, 3).normalized()) * Eigen::Vector3d(p[0], p[1], p[2]) + Eigen::Vector3d(2, -1, 0.5);
  return {x.x(), x.y(), x.z()};
}

// The mean distance, in mean edge lengths of `a`, from where the map sends each source vertex to
// where it should: `expected[v]` (a source vertex), the target being `a` moved and renumbered by
// `perm` (so a target vertex is the source vertex perm^-1 of it).
double mean_map_error(const Soup& a, const std::vector<std::size_t>& perm, const std::vector<std::size_t>& map, const std::vector<std::size_t>& expected) {
  std::vector<std::size_t> inverse(perm.size());
  for(std::size_t i = 0; i < perm.size(); ++i) inverse[perm[i]] = i;
  double sum = 0;
  for(std::size_t v = 0; v < map.size(); ++v) {
    const auto &p = a.points[inverse[map[v]]], &q = a.points[expected[v]];
    sum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
  return sum / double(map.size()) / mean_edge(a);
}

// each vertex's mirror image (the vertex nearest to its point reflected in y = 0)
std::vector<std::size_t> mirror_vertices(const Soup& a) {
  std::vector<std::size_t> out(a.points.size());
  for(std::size_t v = 0; v < a.points.size(); ++v) {
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t w = 0; w < a.points.size(); ++w) {
      const auto &p = a.points[v], &q = a.points[w];
      const double d = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] + q[1]) * (p[1] + q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
      if(d < best) { best = d; out[v] = w; }
    }
  }
  return out;
}

} // namespace

TEMPLATE_LIST_TEST_CASE("isometric correspondence: a bilaterally symmetric shape comes back direct, or mirrored on request", "[isometric][orientation]",
                        test::Mesh_types) {
  const Soup a = animal(3);
  const std::vector<std::size_t> perm = shuffled(a.points.size(), 3);
  const Soup b = transformed(a, perm, moved);
  const TestType source = mesh_of<TestType>(a), target = mesh_of<TestType>(b);
  std::vector<std::size_t> identity(a.points.size());
  std::iota(identity.begin(), identity.end(), 0);
  const std::vector<std::size_t> mirror = mirror_vertices(a);
  // a direct map is ~0 edge lengths from the identity; the mirror map 4.7 away (measured: with ANY,
  // seeds 0 to 4 return the mirror)
  const bool all_seeds = std::is_same<TestType, test::Surface_mesh>::value;
  for(unsigned seed = 0; seed < (all_seeds ? 6u : 1u); ++seed)
    for(auto orientation : {shapecorr::Map_orientation::PRESERVING, shapecorr::Map_orientation::REVERSING}) {
      const bool direct = orientation == shapecorr::Map_orientation::PRESERVING;
      if(!all_seeds && !direct) continue;
      shapecorr::Isometric_correspondence<TestType> method(source, target, SP::number_of_levels(1).number_of_eigenpairs(30).random_seed(seed).orientation(orientation));
      const auto& report = method.run();
      const double to_identity = mean_map_error(a, perm, method.dense_map(), identity), to_mirror = mean_map_error(a, perm, method.dense_map(), mirror);
      INFO("seed " << seed << ", " << (direct ? "preserving" : "reversing") << ": " << to_identity << " edges from the identity, " << to_mirror
                   << " from the mirror; orientation score " << report.orientation_score << ", coarse " << report.levels[0].orientation_score);
      CHECK(report.requested_orientation == orientation);
      CHECK(report.orientation == orientation);
      CHECK(report.levels[0].orientation_met);
      CHECK((direct ? report.orientation_score : -report.orientation_score) > 0.5);
      CHECK((direct ? to_identity : to_mirror) < 1.0);
      CHECK((direct ? to_mirror : to_identity) > 3.0);
    }
  // ANY: the thesis's method, whichever distorts least; the report still says which it is
  shapecorr::Isometric_correspondence<TestType> any(source, target, SP::number_of_levels(1).number_of_eigenpairs(30).orientation(shapecorr::Map_orientation::ANY));
  const auto& report = any.run();
  const double to_identity = mean_map_error(a, perm, any.dense_map(), identity);
  CHECK((report.orientation == shapecorr::Map_orientation::PRESERVING) == (to_identity < 1.0));
}

TEST_CASE("isometric correspondence: a scaled copy (x 1.5) matches as well as the unscaled one", "[isometric][orientation]") {
  typedef test::Surface_mesh Mesh;
  const Soup a = animal(3);
  const std::vector<std::size_t> perm = shuffled(a.points.size(), 4);
  std::vector<std::size_t> identity(a.points.size());
  std::iota(identity.begin(), identity.end(), 0);
  const Mesh source = mesh_of<Mesh>(a);
  double error[2];
  for(int scaled = 0; scaled < 2; ++scaled) {
    const double f = scaled ? 1.5 : 1.0;
    const Mesh target = mesh_of<Mesh>(transformed(a, perm, [f](const std::array<double, 3>& p) { return moved({f * p[0], f * p[1], f * p[2]}); }));
    shapecorr::Isometric_correspondence<Mesh> method(source, target, SP::number_of_levels(1).number_of_eigenpairs(30));
    const auto& report = method.run();
    error[scaled] = mean_map_error(a, perm, method.dense_map(), identity);
    INFO("scale " << f << ": " << error[scaled] << " edge lengths from the identity; energy " << report.levels[0].energies.back());
    CHECK(report.orientation == shapecorr::Map_orientation::PRESERVING);
    CHECK(error[scaled] < 1.0);
  }
  CHECK(error[1] <= 1.25 * error[0] + 0.05);
}

TEMPLATE_LIST_TEST_CASE("isometric correspondence: keep_largest_component works on the largest component and maps the others' vertices",
                        "[isometric][orientation]", test::Mesh_types) {
  // the animal with a small sphere beside it (a second component), onto the moved, renumbered animal
  const Soup a = animal(3);
  const std::vector<std::size_t> perm = shuffled(a.points.size(), 6);
  const Soup b = transformed(a, perm, moved);
  Soup with_ball = a;
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> ball;
  shapecorr::make_icosphere(ball, 1, 0.2);
  const Soup s = soup_of(ball);
  const std::size_t n = a.points.size();
  for(const auto& p : s.points) with_ball.points.push_back({p[0] + 6, p[1], p[2]});
  for(const auto& t : s.triangles) with_ball.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  const TestType source = mesh_of<TestType>(with_ball), target = mesh_of<TestType>(b);
  CHECK_THROWS_AS(shapecorr::Isometric_correspondence<TestType>(source, target), shapecorr::Invalid_input);
  shapecorr::Isometric_correspondence<TestType> method(source, target, SP::number_of_levels(1).number_of_eigenpairs(30).keep_largest_component(true));
  const auto& report = method.run();
  CHECK(report.source_vertices_dropped == s.points.size());
  CHECK(report.target_vertices_dropped == 0);
  const std::vector<std::size_t>& map = method.dense_map();
  REQUIRE(map.size() == with_ball.points.size());
  // the animal's vertices: the direct map (in the user's numbering); the ball's: a vertex of the target
  std::vector<std::size_t> identity(n);
  std::iota(identity.begin(), identity.end(), 0);
  CHECK(mean_map_error(a, perm, std::vector<std::size_t>(map.begin(), map.begin() + long(n)), identity) < 1.0);
  for(std::size_t v = n; v < map.size(); ++v) CHECK(map[v] < b.points.size());
  for(const auto& m : report.matches) CHECK(m.source < n);
  CHECK(report.orientation == shapecorr::Map_orientation::PRESERVING);
}

TEST_CASE("isometric correspondence: the same shape at two resolutions (2562 and 642 vertices), both ways", "[isometric][orientation]") {
  // vertex i of the coarse animal is vertex i of the fine one (make_icosphere keeps the ids of
  // the level before): the truth for the first 642 vertices
  typedef test::Surface_mesh Mesh;
  const Soup fine = animal(4), coarse = animal(3);
  const std::vector<std::size_t> perm = shuffled(coarse.points.size(), 8);
  const Soup coarse_moved = transformed(coarse, perm, moved);
  const Mesh F = mesh_of<Mesh>(fine), C = mesh_of<Mesh>(coarse_moved);
  const double edge = mean_edge(coarse);
  std::vector<std::size_t> inverse(perm.size());
  for(std::size_t i = 0; i < perm.size(); ++i) inverse[perm[i]] = i;
  auto distance = [](const std::array<double, 3>& p, const std::array<double, 3>& q) {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  };
  { // fine -> coarse: the first 642 source vertices should go to their own (renumbered) vertex
    shapecorr::Isometric_correspondence<Mesh> method(F, C, SP::number_of_levels(2).number_of_eigenpairs(30));
    const auto& report = method.run();
    double sum = 0;
    for(std::size_t v = 0; v < coarse.points.size(); ++v) sum += distance(coarse.points[inverse[method.dense_map()[v]]], coarse.points[v]);
    INFO("fine -> coarse: " << sum / double(coarse.points.size()) / edge << " coarse edge lengths; orientation " << report.orientation_score);
    CHECK(report.orientation == shapecorr::Map_orientation::PRESERVING);
    CHECK(sum / double(coarse.points.size()) / edge < 1.0);
  }
  { // coarse -> fine: coarse vertex perm[i] should go to fine vertex i
    shapecorr::Isometric_correspondence<Mesh> method(C, F, SP::number_of_levels(2).number_of_eigenpairs(30));
    const auto& report = method.run();
    double sum = 0;
    for(std::size_t i = 0; i < coarse.points.size(); ++i) sum += distance(fine.points[method.dense_map()[perm[i]]], fine.points[i]);
    INFO("coarse -> fine: " << sum / double(coarse.points.size()) / edge << " coarse edge lengths; orientation " << report.orientation_score);
    CHECK(report.orientation == shapecorr::Map_orientation::PRESERVING);
    CHECK(sum / double(coarse.points.size()) / edge < 1.0);
  }
}
