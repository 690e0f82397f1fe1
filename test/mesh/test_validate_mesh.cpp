// Validation: every kind of bad surface is detected, counted and located; require_valid raises
// the typed error that names it.
#include "test_meshes.h"

#include <shapecorr/mesh.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace {
typedef std::vector<test::Point> Points;
typedef std::vector<std::vector<std::size_t>> Polys;

// a closed tetrahedron
Points tet_points() { return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; }
Polys tet_faces() { return {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}; }

shapecorr::Mesh_defect defect_of(const shapecorr::Mesh_report& r, shapecorr::Mesh_requirements req = {}) {
  try {
    shapecorr::require_valid(r, req, "test");
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(std::string(e.what()).find("test: ") == 0);
    return e.defect();
  }
  FAIL("require_valid accepted a bad mesh");
  return shapecorr::Mesh_defect::unreadable_file; // not reached: FAIL throws
}
} // namespace

TEST_CASE("a clean closed mesh passes", "[mesh][validation]") {
  const auto r = shapecorr::validate_polygon_soup(tet_points(), tet_faces());
  CHECK(r.is_valid());
  CHECK(r.is_closed());
  CHECK(r.connected_components == 1);
  CHECK(r.area == Approx(1.5 + std::sqrt(3.0) / 2));
  CHECK_NOTHROW(shapecorr::require_valid(r, {true, true}));
}

TEST_CASE("each defect is detected and named", "[mesh][validation]") {
  using D = shapecorr::Mesh_defect;
  SECTION("empty") {
    const auto r = shapecorr::validate_polygon_soup(Points{}, Polys{});
    CHECK(r.is_empty());
    CHECK(defect_of(r) == D::empty_mesh);
  }
  SECTION("NaN coordinate") {
    Points p = tet_points();
    p[2] = test::Point(std::nan(""), 0, 0);
    const auto r = shapecorr::validate_polygon_soup(p, tet_faces());
    CHECK(r.non_finite_vertices == 1);
    CHECK(r.examples.at(D::non_finite_coordinate) == "vertex 2");
    CHECK(defect_of(r) == D::non_finite_coordinate);
  }
  SECTION("infinite coordinate") {
    Points p = tet_points();
    p[1] = test::Point(INFINITY, 0, 0);
    CHECK(defect_of(shapecorr::validate_polygon_soup(p, tet_faces())) == D::non_finite_coordinate);
  }
  SECTION("quad face") {
    const Points p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const auto r = shapecorr::validate_polygon_soup(p, Polys{{0, 1, 2, 3}});
    CHECK(r.non_triangle_faces == 1);
    CHECK(defect_of(r) == D::non_triangle_face);
  }
  SECTION("degenerate faces: repeated vertex and zero area") {
    const Points p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    const auto r = shapecorr::validate_polygon_soup(p, Polys{{0, 1, 2}, {0, 1, 1}, {0, 1, 3}});
    CHECK(r.degenerate_faces == 2);
    CHECK(r.examples.at(D::degenerate_face) == "face 0 has zero area");
    CHECK(defect_of(r) == D::degenerate_face);
  }
  SECTION("edge with three faces") {
    const Points p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    const auto r = shapecorr::validate_polygon_soup(p, Polys{{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    CHECK(r.non_manifold_edges == 1);
    CHECK(defect_of(r) == D::non_manifold_edge);
  }
  SECTION("inconsistent orientation") {
    const Points p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    const auto r = shapecorr::validate_polygon_soup(p, Polys{{0, 1, 2}, {0, 1, 3}});
    CHECK(r.non_manifold_edges == 1);
    CHECK(r.examples.at(D::non_manifold_edge).find("inconsistent orientation") != std::string::npos);
  }
  SECTION("two fans at one vertex (bow tie)") {
    const Points p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    const auto r = shapecorr::validate_polygon_soup(p, Polys{{0, 1, 2}, {0, 3, 4}});
    CHECK(r.non_manifold_vertices == 1);
    CHECK(r.examples.at(D::non_manifold_vertex).find("vertex 0") == 0);
    CHECK(r.non_manifold_edges == 0);
    CHECK(defect_of(r) == D::non_manifold_vertex);
  }
  SECTION("isolated vertex") {
    Points p = tet_points();
    p.emplace_back(5, 5, 5);
    const auto r = shapecorr::validate_polygon_soup(p, tet_faces());
    CHECK(r.isolated_vertices == 1);
    CHECK(r.examples.at(D::isolated_vertex) == "vertex 4");
    CHECK(defect_of(r) == D::isolated_vertex);
  }
  SECTION("boundary: fine unless a closed surface is required") {
    Polys f = tet_faces();
    f.pop_back();
    const auto r = shapecorr::validate_polygon_soup(tet_points(), f);
    CHECK(r.boundary_edges == 3);
    CHECK(r.is_valid());
    CHECK_NOTHROW(shapecorr::require_valid(r));
    CHECK(defect_of(r, {true, false}) == D::boundary);
  }
  SECTION("several components: fine unless one is required") {
    Points p = tet_points();
    Polys f = tet_faces();
    for(const auto& q : tet_points()) p.emplace_back(q.x() + 3, q.y(), q.z());
    for(auto face : tet_faces()) f.push_back({face[0] + 4, face[1] + 4, face[2] + 4});
    const auto r = shapecorr::validate_polygon_soup(p, f);
    CHECK(r.connected_components == 2);
    CHECK(r.is_valid());
    CHECK(defect_of(r, {false, true}) == D::several_components);
  }
}

TEMPLATE_LIST_TEST_CASE("validate_mesh works on any FaceGraph", "[mesh][validation]", test::Mesh_types) {
  TestType m;
  shapecorr::make_grid(m, 3, 3);
  auto r = shapecorr::validate_mesh(m);
  CHECK(r.is_valid());
  CHECK(r.boundary_edges == 12);
  // collapse a vertex onto its neighbour: two faces lose their area
  auto vpm = get(CGAL::vertex_point, m);
  const auto vs = test::vertices_in_index_order(m);
  put(vpm, vs[5], get(vpm, vs[6]));
  r = shapecorr::validate_mesh(m);
  CHECK(r.degenerate_faces >= 1);
  CHECK_THROWS_AS(shapecorr::require_valid(r), shapecorr::Invalid_input);
}
