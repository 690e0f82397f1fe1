// Geodesic Spin Contour (thesis chapter 4): invariance under an exact isometry (a bent strip), under
// vertex renumbering, locality (deleting far parts changes nothing), agreement of the fast
// construction with the image-then-contour definition, walks seeded by descent on spheres
// against walks seeded from every face, the geodesic spin image, errors; over Surface_mesh and
// Polyhedron_3.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/descriptors.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <random>

namespace SP = shapecorr::parameters;

namespace {

// A W x H strip, flat (bend = 0) or rolled around an axis parallel to y with radius W / (bend pi):
// an exact isometry of the flat strip (the vertices lie on the rolled surface).
template <typename Mesh>
void make_strip(Mesh& m, int nx, int ny, double W, double H, double bend) {
  shapecorr::make_grid(m, nx, ny, W, H);
  if(bend == 0) return;
  const double rho = W / (bend * CGAL_PI);
  test::transform_points(m, [rho](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(rho * std::sin(p.x() / rho), p.y(), rho * (1 - std::cos(p.x() / rho)));
  });
}

// A torus with a smooth bump field (few symmetries), as a soup, optionally renumbered.
void bumpy_torus_soup(std::vector<std::array<double, 3>>& P, std::vector<std::array<std::size_t, 3>>& T) {
  test::Surface_mesh t;
  shapecorr::make_torus(t, 1.0, 0.35, 40, 16);
  P.clear();
  T.clear();
  for(auto v : t.vertices()) {
    const auto& p = t.point(v);
    const double s = 1.0 + 0.12 * std::sin(2 * p.x() + 0.5) * std::cos(3 * p.y()) + 0.05 * p.x();
    P.push_back({s * p.x(), s * p.y(), p.z() * (1 + 0.2 * p.x())});
  }
  for(auto f : t.faces()) {
    std::array<std::size_t, 3> tri;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(t.halfedge(f), t)) tri[static_cast<std::size_t>(k++)] = v.idx();
    T.push_back(tri);
  }
}

template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> vertex_list(const Mesh& m) {
  return test::vertices_in_index_order(m);
}

// A sphere with four long "legs" around its equator and a bump on top, as a soup: seen from
// the top, the isolines split into several pieces (one per leg) at larger distances.
void legged_sphere_soup(std::vector<std::array<double, 3>>& P, std::vector<std::array<std::size_t, 3>>& T) {
  test::Surface_mesh s;
  shapecorr::make_icosphere(s, 4);
  P.clear();
  T.clear();
  const std::array<Eigen::Vector3d, 5> legs = {Eigen::Vector3d(1, 0, -0.3).normalized(), Eigen::Vector3d(0, 1, -0.35).normalized(),
                                               Eigen::Vector3d(-1, 0.1, -0.3).normalized(), Eigen::Vector3d(0.1, -1, -0.4).normalized(),
                                               Eigen::Vector3d(0.2, 0.1, 1).normalized()};
  for(auto v : s.vertices()) {
    const Eigen::Vector3d p(s.point(v).x(), s.point(v).y(), s.point(v).z());
    double r = 1.0;
    for(std::size_t i = 0; i < legs.size(); ++i) r += (i < 4 ? 1.6 : 0.3) * std::exp(-(p - legs[i]).squaredNorm() / 0.05);
    P.push_back({r * p.x(), r * p.y(), r * p.z()});
  }
  for(auto f : s.faces()) {
    std::array<std::size_t, 3> tri;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(s.halfedge(f), s)) tri[static_cast<std::size_t>(k++)] = v.idx();
    T.push_back(tri);
  }
}

template <typename Mesh>
void make_legged_sphere(Mesh& m) {
  std::vector<std::array<double, 3>> P;
  std::vector<std::array<std::size_t, 3>> T;
  legged_sphere_soup(P, T);
  shapecorr::internal::soup_to_mesh(P, T, m);
}

// The contour of a ball with the walks seeded by descent, and seeded from every face.
template <typename G, typename Ball>
std::pair<shapecorr::Spin_contour, shapecorr::Spin_contour> both_seedings(G& g, const Ball& ball) {
  shapecorr::internal::Geodesic_spin_descriptors_access::use_descent_seeds(g, true);
  shapecorr::Spin_contour a = g.geodesic_spin_contour(ball);
  shapecorr::internal::Geodesic_spin_descriptors_access::use_descent_seeds(g, false);
  shapecorr::Spin_contour b = g.geodesic_spin_contour(ball);
  return {a, b};
}

bool same_bits(const shapecorr::Spin_contour& a, const shapecorr::Spin_contour& b) {
  if(a.rows() != b.rows() || a.alphas() != b.alphas()) return false;
  for(std::size_t r = 0; r < a.rows(); ++r)
    if(a.row_begin(r) != b.row_begin(r)) return false;
  return true;
}

// The number of rows of c whose points form more than one interval (a gap wider than a column).
std::size_t rows_with_gaps(const shapecorr::Spin_contour& c, double column) {
  std::size_t n = 0;
  for(std::size_t r = 0; r < c.rows(); ++r)
    for(std::size_t i = c.row_begin(r); i + 1 < c.row_end(r); ++i)
      if(c.alphas()[i + 1] - c.alphas()[i] > 1.5 * column) {
        ++n;
        break;
      }
  return n;
}

} // namespace

TEMPLATE_LIST_TEST_CASE("GSC is invariant under an exact isometry: a flat and a rolled strip", "[descriptors][gsc]", test::Mesh_types) {
  TestType flat, rolled;
  make_strip(flat, 60, 15, 4.0, 1.0, 0.0);
  make_strip(rolled, 60, 15, 4.0, 1.0, 1.0); // rolled into a half cylinder
  const double D = std::sqrt(16.0 + 1.0);     // the flat strip's diameter: its diagonal
  for(double r : {0.0, 0.15}) {
    INFO("agd radius fraction " << r);
    const auto np = SP::support_fraction(0.3).agd_radius_fraction(r).number_of_sources(0).geodesic_diameter(D);
    const shapecorr::Geodesic_spin_descriptors<TestType> a(flat, np), b(rolled, np);
    const auto va = vertex_list(flat), vb = vertex_list(rolled);
    std::vector<std::size_t> ids;
    for(int j : {2, 7, 12})
      for(int i : {3, 17, 30, 44, 57}) ids.push_back(static_cast<std::size_t>(j * 61 + i));
    for(std::size_t i : ids) {
      const auto ca = a.geodesic_spin_contour(va[i]), cb = b.geodesic_spin_contour(vb[i]);
      REQUIRE(ca.size() > 10);
      const double same = shapecorr::contour_l1_distance(ca, cb);
      CHECK(same < 0.01);
      // a vertex elsewhere on the strip (not a mirror image of i) is much farther
      const std::size_t other = (i + 61 * 5 + 11) % (61 * 16);
      const double diff = shapecorr::contour_l1_distance(ca, b.geodesic_spin_contour(vb[other]));
      CHECK(diff > 4 * same);
    }
    // the agd itself is isometry invariant
    for(std::size_t i = 0; i < va.size(); ++i)
      CHECK(a.average_geodesic_distances()[i] == Approx(b.average_geodesic_distances()[i]).epsilon(0.01));
  }
}

TEMPLATE_LIST_TEST_CASE("GSC is invariant under vertex renumbering", "[descriptors][gsc]", test::Mesh_types) {
  std::vector<std::array<double, 3>> P, P2;
  std::vector<std::array<std::size_t, 3>> T, T2;
  bumpy_torus_soup(P, T);
  std::vector<std::size_t> perm(P.size()); // new index of old vertex i
  std::iota(perm.begin(), perm.end(), std::size_t(0));
  std::shuffle(perm.begin(), perm.end(), std::mt19937(7));
  P2.resize(P.size());
  for(std::size_t i = 0; i < P.size(); ++i) P2[perm[i]] = P[i];
  for(const auto& t : T) T2.push_back({perm[t[0]], perm[t[1]], perm[t[2]]});
  std::reverse(T2.begin(), T2.end());
  TestType a, b;
  shapecorr::internal::soup_to_mesh(P, T, a);
  shapecorr::internal::soup_to_mesh(P2, T2, b);
  const auto np = SP::support_fraction(0.25).agd_radius_fraction(0.1);
  const shapecorr::Geodesic_spin_descriptors<TestType> ga(a, np), gb(b, np);
  CHECK(ga.geodesic_diameter() == Approx(gb.geodesic_diameter()).epsilon(1e-9));
  const auto va = vertex_list(a), vb = vertex_list(b);
  for(std::size_t i = 0; i < P.size(); i += 37) {
    const auto ca = ga.geodesic_spin_contour(va[i]), cb = gb.geodesic_spin_contour(vb[perm[i]]);
    REQUIRE(!ca.empty());
    CHECK(shapecorr::contour_l1_distance(ca, cb) < 1e-6);
  }
}

TEMPLATE_LIST_TEST_CASE("a local GSC does not change when far-away parts are deleted", "[descriptors][gsc]", test::Mesh_types) {
  // A long strip; P near the left end; everything beyond x = 5 removed in the cut copy.
  const int nx = 120, ny = 10;
  const double W = 12.0, H = 1.0;
  TestType whole, cut;
  make_strip(whole, nx, ny, W, H, 0.0);
  shapecorr::make_grid(cut, 50, ny, W * 50 / nx, H); // the same vertices and diagonals for x <= 5
  const double D = std::sqrt(W * W + H * H);
  // L = 0.1 D = 1.2, r = 0.1 D: P at x = 1 needs the strip up to x = 1 + 1.2 + 1.2 (+ an edge) < 5.
  // The part gets the whole shape's lengths: D and the agd normalization.
  const shapecorr::Geodesic_spin_descriptors<TestType> gw(whole, SP::support_fraction(0.1).agd_radius_fraction(0.1).geodesic_diameter(D));
  const auto np = SP::support_fraction(0.1).agd_radius_fraction(0.1).geodesic_diameter(D).agd_offset(gw.alpha_offset()).agd_scale(gw.alpha_scale());
  const shapecorr::Geodesic_spin_descriptors<TestType> gc(cut, np);
  const auto vw = vertex_list(whole), vc = vertex_list(cut);
  for(int j : {0, 3, 5, 9})
    for(int i : {6, 10, 14}) {
      const auto a = gw.geodesic_spin_contour(vw[static_cast<std::size_t>(j * (nx + 1) + i)]);
      const auto b = gc.geodesic_spin_contour(vc[static_cast<std::size_t>(j * 51 + i)]);
      REQUIRE(a.size() > 10);
      CHECK(shapecorr::contour_l1_distance(a, b) < 1e-9);
    }
  // the same through the normalization object
  const shapecorr::Geodesic_spin_descriptors<TestType> gn(cut, SP::support_fraction(0.1).agd_radius_fraction(0.1).geodesic_spin_normalization(gw.normalization()));
  CHECK(gn.geodesic_diameter() == gw.geodesic_diameter());
  CHECK(gn.alpha_offset() == gw.alpha_offset());
  CHECK(gn.alpha_scale() == gw.alpha_scale());
  CHECK(gn.alpha_scale() != shapecorr::Geodesic_spin_descriptors<TestType>(cut, SP::support_fraction(0.1).agd_radius_fraction(0.1)).alpha_scale());
  CHECK(gn.geodesic_spin_contour(vc[3 * 51 + 10]).points() == gc.geodesic_spin_contour(vc[3 * 51 + 10]).points());
  // individual parameters take precedence over the normalization object
  CHECK(shapecorr::Geodesic_spin_descriptors<TestType>(cut, SP::geodesic_spin_normalization(gw.normalization()).agd_scale(2.0)).alpha_scale() == 2.0);
  // the global agd, by contrast, sees the cut
  const auto npg = SP::support_fraction(0.1).agd_radius_fraction(0.0).number_of_sources(0).geodesic_diameter(D).agd_offset(0.0).agd_scale(D);
  const shapecorr::Geodesic_spin_descriptors<TestType> hw(whole, npg), hc(cut, npg);
  CHECK(shapecorr::contour_l1_distance(hw.geodesic_spin_contour(vw[6]), hc.geodesic_spin_contour(vc[6])) > 0.01);
}

TEMPLATE_LIST_TEST_CASE("the fast GSC construction agrees with the contour of the geodesic spin image", "[descriptors][gsc]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 3);
  test::transform_points(m, [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(1.3 * p.x() + 0.2 * p.y() * p.y(), 0.9 * p.y(), 0.7 * p.z() + 0.15 * std::sin(3 * p.x()));
  });
  const std::size_t R = 32, C = 32;
  const auto np = SP::support_fraction(0.5).agd_radius_fraction(0.0).number_of_sources(0).image_rows(R).image_columns(C);
  const shapecorr::Geodesic_spin_descriptors<TestType> gs(m, np);
  const double L = gs.support_length(), S = gs.alpha_scale(), O = gs.alpha_offset();
  const auto vs = vertex_list(m);
  auto vim = CGAL::get_initialized_vertex_index_map(m);
  std::vector<std::vector<std::array<double, 2>>> image_contours;
  std::vector<shapecorr::Spin_contour> fast;
  for(std::size_t p : {0u, 100u, 333u}) {
    // the image: dense samples of every triangle with gd, agd interpolated linearly; occupied cells
    typename shapecorr::Geodesic_spin_descriptors<TestType>::Ball ball;
    gs.support_ball(gs.index(vs[p]), ball);
    std::vector<double> gd(vs.size(), std::numeric_limits<double>::infinity());
    for(const auto& b : ball) gd[b.first] = b.second;
    std::vector<char> occ(R * C, 0);
    const int N = 60;
    for(auto f : faces(m)) {
      std::array<std::size_t, 3> c;
      int k = 0;
      for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) c[static_cast<std::size_t>(k++)] = get(vim, v);
      for(int i = 0; i <= N; ++i)
        for(int j = 0; i + j <= N; ++j) {
          const double u = double(i) / N, w = double(j) / N, z = 1 - u - w;
          const double g = u * gd[c[0]] + w * gd[c[1]] + z * gd[c[2]];
          const double a = u * gs.average_geodesic_distances()[c[0]] + w * gs.average_geodesic_distances()[c[1]] + z * gs.average_geodesic_distances()[c[2]];
          if(!(g < L)) continue;
          const std::size_t row = std::min(R - 1, static_cast<std::size_t>(g / L * R));
          const std::size_t col = std::min(C - 1, static_cast<std::size_t>(std::max(0.0, (a - O) / S * C)));
          occ[row * C + col] = 1;
        }
    }
    // its contour: occupied cells with an empty 4-neighbour (outside counts as empty)
    std::vector<std::array<double, 2>> pts;
    for(std::size_t r = 0; r < R; ++r)
      for(std::size_t c = 0; c < C; ++c) {
        if(!occ[r * C + c]) continue;
        const bool edge = r == 0 || r + 1 == R || c == 0 || c + 1 == C || !occ[(r - 1) * C + c] || !occ[(r + 1) * C + c] ||
                          !occ[r * C + c - 1] || !occ[r * C + c + 1];
        if(edge) pts.push_back({(c + 0.5) / C, (r + 0.5) / R});
      }
    REQUIRE(pts.size() > 10);
    image_contours.push_back(pts);
    fast.push_back(gs.geodesic_spin_contour(vs[p]));
    // the same from the ball, and from a ball that lists every vertex three times (its faces are
    // listed three times, more than the mesh has: the list grows)
    CHECK(gs.geodesic_spin_contour(ball).alphas() == fast.back().alphas());
    typename shapecorr::Geodesic_spin_descriptors<TestType>::Ball thrice = ball;
    for(int k = 0; k < 2; ++k) thrice.insert(thrice.end(), ball.begin(), ball.end());
    std::vector<char> in_ball(vs.size(), 0);
    for(const auto& b : ball) in_ball[b.first] = 1;
    std::size_t owned = 0; // faces whose corner of smallest index is in the ball: the disc's face list
    for(auto f : faces(m)) {
      std::size_t lo = vs.size();
      for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) lo = std::min(lo, static_cast<std::size_t>(get(vim, v)));
      owned += in_ball[lo];
    }
    REQUIRE(3 * owned > num_faces(m) + 8);
    CHECK(gs.geodesic_spin_contour(thrice).alphas() == fast.back().alphas());
  }
  for(std::size_t i = 0; i < fast.size(); ++i) {
    const double d = shapecorr::point_set_l1_distance(fast[i].points(), image_contours[i]);
    INFO("point " << i << ": " << d);
    // within half a cell: the image's contour cells are the cells the fast contour's points fall in
    // or next to (measured: 0.29-0.32 of a cell)
    CHECK(d < 0.5 / C);
  }
}

TEMPLATE_LIST_TEST_CASE("workspaces: one per thread gives the shared workspace's contours; another object's is refused", "[descriptors][gsc]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 3);
  test::transform_points(m, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(1.2 * p.x(), p.y() + 0.1 * p.x() * p.x(), 0.8 * p.z()); });
  typedef shapecorr::Geodesic_spin_descriptors<TestType> G;
  const G g(m, SP::support_fraction(0.3)), other(m, SP::support_fraction(0.3));
  const auto vs = vertex_list(m);
  const std::size_t n = vs.size();
  std::vector<shapecorr::Spin_contour> shared(n), mine(n);
  for(std::size_t i = 0; i < n; ++i) shared[i] = g.geodesic_spin_contour(vs[i]);
  std::vector<typename G::Workspace> ws;
  for(unsigned t = 0; t < 3; ++t) ws.emplace_back(g);
  shapecorr::parallel_for(n, 3, [&](std::size_t i, unsigned tid) { mine[i] = g.geodesic_spin_contour(vs[i], ws[tid]); });
  for(std::size_t i = 0; i < n; ++i) REQUIRE(mine[i].points() == shared[i].points());
  typename G::Workspace foreign(other);
  CHECK_THROWS_AS(g.geodesic_spin_contour(vs[0], foreign), shapecorr::Invalid_argument);
  CHECK(other.geodesic_spin_contour(vs[0], foreign).points() == shared[0].points());
}

TEMPLATE_LIST_TEST_CASE("geodesic spin images, batch functions and property maps", "[descriptors][gsc]", test::Mesh_types) {
  TestType flat, rolled;
  make_strip(flat, 40, 10, 4.0, 1.0, 0.0);
  make_strip(rolled, 40, 10, 4.0, 1.0, 1.0);
  const auto np = SP::support_fraction(0.3).geodesic_diameter(std::sqrt(17.0));
  const shapecorr::Geodesic_spin_descriptors<TestType> a(flat, np), b(rolled, np);
  const auto va = vertex_list(flat), vb = vertex_list(rolled);
  const auto ia = a.geodesic_spin_image(va[100]), ib = b.geodesic_spin_image(vb[100]);
  CHECK(ia.rows() == 64);
  CHECK(ia.columns() == 64);
  // the image's mass is the area of the disc gd <= L (up to splatting at the border)
  double mass = 0;
  for(float x : ia.values()) mass += x;
  CHECK(mass > 0);
  CHECK(shapecorr::spin_image_correlation(ia, ib).first > 0.95);
  // batch = one by one; the property-map function
  const std::vector<std::size_t> ids = {0, 50, 100, 150};
  const auto batch = a.geodesic_spin_contours(ids);
  for(std::size_t k = 0; k < ids.size(); ++k) CHECK(shapecorr::contour_l1_distance(batch[k], a.geodesic_spin_contour(va[ids[k]])) == 0.0);
  std::map<typename boost::graph_traits<TestType>::vertex_descriptor, shapecorr::Spin_contour> store;
  std::vector<typename boost::graph_traits<TestType>::vertex_descriptor> some = {va[0], va[50]};
  shapecorr::compute_geodesic_spin_contours(flat, some, boost::make_assoc_property_map(store), np);
  CHECK(shapecorr::contour_l1_distance(store[va[50]], batch[1]) == 0.0);
  // rows: beta = gd / L in [0, 1], row 0 nearest to the point
  CHECK(batch[0].beta(0) == Approx(0.5 / 64));
  CHECK(batch[0].row_spacing() == Approx(1.0 / 64));
  // a rigid Spin Contour cannot be compared with a geodesic one
  shapecorr::Spin_contour rigid(64, 1.0);
  CHECK_THROWS_AS(shapecorr::contour_l1_distance(rigid, batch[0]), shapecorr::Invalid_argument);
}

TEMPLATE_LIST_TEST_CASE("a rejected ball leaves no trace: the next contours are unchanged", "[descriptors][gsc]", test::Mesh_types) {
  // The construction keeps per-thread vertex records between calls; a ball rejected half-way
  // (an index out of range after valid ones) must not leave records behind.
  TestType m;
  make_strip(m, 40, 10, 4.0, 1.0, 0.5);
  const shapecorr::Geodesic_spin_descriptors<TestType> g(m, SP::support_fraction(0.3).geodesic_diameter(std::sqrt(17.0)));
  const std::size_t n = g.number_of_vertices();
  std::vector<shapecorr::Spin_contour> before;
  typename shapecorr::Geodesic_spin_descriptors<TestType>::Ball ball;
  for(std::size_t v : {100u, 200u, 305u}) {
    g.support_ball(v, ball);
    before.push_back(g.geodesic_spin_contour(ball));
  }
  typename shapecorr::Geodesic_spin_descriptors<TestType>::Ball bad;
  for(std::size_t v = 0; v < n; ++v) bad.push_back({v, 0.0});
  bad.push_back({n, 0.0});
  CHECK_THROWS_AS(g.geodesic_spin_contour(bad), shapecorr::Invalid_argument);
  std::size_t k = 0;
  for(std::size_t v : {100u, 200u, 305u}) {
    g.support_ball(v, ball);
    const shapecorr::Spin_contour c = g.geodesic_spin_contour(ball);
    REQUIRE(c.size() == before[k].size());
    CHECK(shapecorr::contour_l1_distance(c, before[k]) == 0.0);
    ++k;
  }
}

TEMPLATE_LIST_TEST_CASE("GSC on a sphere: walks seeded by descent give the bits of walks seeded from every face", "[descriptors][gsc]", test::Mesh_types) {
  TestType m;
  make_legged_sphere(m);
  for(double L : {0.25, 0.5, 0.8}) {
    shapecorr::Geodesic_spin_descriptors<TestType> g(m, SP::support_fraction(L).agd_radius_fraction(0.1));
    REQUIRE(g.is_topological_sphere());
    const double column = 1.0 / static_cast<double>(g.columns());
    std::size_t gaps = 0;
    typename shapecorr::Geodesic_spin_descriptors<TestType>::Ball ball;
    for(std::size_t i = 0; i < g.number_of_vertices(); i += 7) {
      g.support_ball(i, ball);
      const auto ab = both_seedings(g, ball);
      REQUIRE(!ab.second.empty());
      CHECK(same_bits(ab.first, ab.second));
      gaps += rows_with_gaps(ab.second, column);
    }
    if(L >= 0.5) CHECK(gaps > 20); // the isolines do come in several pieces (the case descent seeds must not miss)
  }
}

TEMPLATE_LIST_TEST_CASE("GSC on a sphere: balls that rule out descent seeds give the same contours", "[descriptors][gsc]", test::Mesh_types) {
  // Balls the caller made: two minima (distances to the nearer of two points), a vertex exactly
  // on a row line, a ball missing the neighbours of disc vertices, a ball listing a vertex twice.
  TestType m;
  make_legged_sphere(m);
  shapecorr::Geodesic_spin_descriptors<TestType> g(m, SP::support_fraction(0.5));
  REQUIRE(g.is_topological_sphere());
  typedef typename shapecorr::Geodesic_spin_descriptors<TestType>::Ball Ball;
  const double h = g.support_length() / static_cast<double>(g.rows());
  auto both_ways = [&](const Ball& ball) {
    const auto ab = both_seedings(g, ball);
    CHECK(!ab.second.empty());
    CHECK(same_bits(ab.first, ab.second));
  };
  Ball a, b;
  for(std::size_t i : {5u, 400u, 1500u}) {
    g.support_ball(i, a);
    g.support_ball((i + 900) % g.number_of_vertices(), b);
    Ball two = a; // the nearer of the two sources, over the union of both balls
    for(const auto& p : b) {
      auto it = std::find_if(two.begin(), two.end(), [&](const std::pair<std::size_t, double>& q) { return q.first == p.first; });
      if(it == two.end()) two.push_back(p);
      else it->second = std::min(it->second, p.second);
    }
    both_ways(two);
    Ball on_row = a; // a vertex exactly on row 10 (t = d / h - 1/2 = 10)
    on_row[on_row.size() / 3].second = 10.5 * h;
    both_ways(on_row);
    Ball partial = a; // the farther half dropped
    partial.resize(partial.size() / 2);
    both_ways(partial);
    Ball twice = a;
    twice.push_back(a[a.size() / 2]);
    both_ways(twice);
  }
}

TEST_CASE("topological spheres are recognised", "[descriptors][gsc]") {
  using shapecorr::internal::build_face_links;
  using shapecorr::internal::is_topological_sphere;
  auto arrays = [](std::size_t n, const std::vector<std::array<int, 3>>& faces) {
    shapecorr::internal::Triangle_arrays a;
    a.V = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>::Random(static_cast<Eigen::Index>(n), 3);
    a.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k) a.F(static_cast<Eigen::Index>(f), k) = faces[f][static_cast<std::size_t>(k)];
    return a;
  };
  const std::vector<std::array<int, 3>> tet = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  CHECK(is_topological_sphere(build_face_links(arrays(4, tet)), 4));
  auto flipped = tet; // orientation does not matter
  std::swap(flipped[2][0], flipped[2][1]);
  CHECK(is_topological_sphere(build_face_links(arrays(4, flipped)), 4));
  CHECK_FALSE(is_topological_sphere(build_face_links(arrays(4, {tet[0], tet[1], tet[2]})), 4)); // a boundary
  CHECK_FALSE(is_topological_sphere(build_face_links(arrays(5, tet)), 5));                      // an isolated vertex
  auto two = tet; // two tetrahedra: apart, or sharing vertex 0 (a non-manifold vertex)
  for(const auto& f : tet) two.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
  CHECK_FALSE(is_topological_sphere(build_face_links(arrays(8, two)), 8));
  auto bowtie = tet;
  for(const auto& f : tet) bowtie.push_back({f[0] == 0 ? 0 : f[0] + 3, f[1] == 0 ? 0 : f[1] + 3, f[2] == 0 ? 0 : f[2] + 3});
  CHECK_FALSE(is_topological_sphere(build_face_links(arrays(7, bowtie)), 7));
  test::Surface_mesh torus, sphere;
  shapecorr::make_torus(torus, 1.0, 0.3, 12, 8);
  shapecorr::make_icosphere(sphere, 2);
  CHECK_FALSE(shapecorr::Geodesic_spin_descriptors<test::Surface_mesh>(torus).is_topological_sphere());
  CHECK(shapecorr::Geodesic_spin_descriptors<test::Surface_mesh>(sphere).is_topological_sphere());
}

TEST_CASE("GSC on the TOSCA wolf: walks seeded by descent give the bits of walks seeded from every face", "[descriptors][gsc][data]") {
  const std::string file = test::data_dir().empty() ? std::string() : test::data_dir() + "/tosca5k/meshes/wolf0.off";
  std::ifstream probe(file);
  if(file.empty() || !probe) {
    WARN("../shared/data absent: skipped");
    return;
  }
  test::Surface_mesh m;
  shapecorr::read_triangle_mesh(file, m);
  shapecorr::Geodesic_spin_descriptors<test::Surface_mesh> g(m, SP::support_fraction(0.4).agd_radius_fraction(0.15));
  REQUIRE(g.is_topological_sphere());
  std::vector<std::size_t> ids;
  for(std::size_t i = 0; i < g.number_of_vertices(); i += 11) ids.push_back(i);
  const auto a = g.geodesic_spin_contours(ids);
  shapecorr::internal::Geodesic_spin_descriptors_access::use_descent_seeds(g, false);
  const auto b = g.geodesic_spin_contours(ids);
  std::size_t same = 0, gaps = 0;
  for(std::size_t k = 0; k < ids.size(); ++k) {
    same += same_bits(a[k], b[k]) ? 1 : 0;
    gaps += rows_with_gaps(b[k], 1.0 / static_cast<double>(g.columns()));
  }
  CHECK(same == ids.size());
  CHECK(gaps > ids.size()); // rows in several pieces are common
}

TEST_CASE("geodesic spin descriptors: errors", "[descriptors][gsc]") {
  test::Surface_mesh m;
  shapecorr::make_grid(m, 4, 4);
  using G = shapecorr::Geodesic_spin_descriptors<test::Surface_mesh>;
  CHECK_THROWS_AS(G(m, SP::support_fraction(0.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(G(m, SP::support_fraction(-1.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(G(m, SP::agd_radius_fraction(-0.1)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(G(m, SP::image_rows(1)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(G(m, SP::agd_scale(0.0)), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(G(m, SP::agd_offset(std::nan(""))), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(G(m, SP::geodesic_diameter(std::nan(""))), shapecorr::Invalid_argument);
  test::Surface_mesh empty;
  CHECK_THROWS_AS(G(empty), shapecorr::Invalid_input);
  const G g(m);
  G::Ball bad = {{0, 0.0}, {999, 0.1}};
  CHECK_THROWS_AS(g.geodesic_spin_contour(bad), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(g.geodesic_spin_contours({0, 999}), shapecorr::Invalid_argument);
}
