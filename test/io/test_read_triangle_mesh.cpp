// Reading files: formats, unreadable and bad content, documented repairs.
#include "test_meshes.h"

#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

namespace {
// file names carry the mesh type: ctest runs the instances of a template test in parallel
thread_local std::string prefix = "shapecorr_test_";
std::string write_file(const std::string& name, const std::string& content) {
  const std::string path = test::temp_path(prefix + name);
  std::ofstream(path) << content;
  return path;
}
const char* tet_off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

template <typename Mesh>
shapecorr::Mesh_defect read_defect(const std::string& path, shapecorr::Read_options opt = {}) {
  Mesh m;
  try {
    shapecorr::read_triangle_mesh(path, m, opt);
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(std::string(e.what()).find(path) == 0); // the message names the file
    return e.defect();
  }
  FAIL("no error for " << path);
  return shapecorr::Mesh_defect::unreadable_file; // not reached: FAIL throws
}
} // namespace

TEMPLATE_LIST_TEST_CASE("reading meshes with validation", "[io]", test::Mesh_types) {
  using D = shapecorr::Mesh_defect;
  prefix = std::is_same<TestType, test::Surface_mesh>::value ? "shapecorr_test_sm_" : "shapecorr_test_poly_";
  SECTION("OFF, OBJ, PLY, STL round trip") {
    TestType sphere;
    shapecorr::make_icosphere(sphere, 2);
    for(std::string ext : {"off", "obj", "ply", "stl"}) {
      const std::string path = test::temp_path(prefix + "sphere." + ext);
      REQUIRE(CGAL::IO::write_polygon_mesh(path, sphere, CGAL::parameters::stream_precision(17)));
      TestType back;
      const auto r = shapecorr::read_triangle_mesh(path, back);
      INFO(ext);
      CHECK(num_vertices(back) == 162);
      CHECK(num_faces(back) == 320);
      CHECK(r.report.is_valid());
      CHECK(r.repairs.empty());
    }
  }
  SECTION("missing, empty and garbage files") {
    CHECK(read_defect<TestType>(test::temp_path(prefix + "does_not_exist.off")) == D::unreadable_file);
    CHECK(read_defect<TestType>(write_file("empty.off", "")) == D::unreadable_file);
    CHECK(read_defect<TestType>(write_file("garbage.off", "OFF\nthis is not a mesh\n")) == D::unreadable_file);
    CHECK(read_defect<TestType>(write_file("unknown.xyz3", "1 2 3\n")) == D::unreadable_file);
  }
  SECTION("a face refers to a vertex past the end: rejected by CGAL's reader, a typed error here") {
    CHECK(read_defect<TestType>(write_file("badindex.off", "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n7 7 7\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 9\n")) ==
          D::unreadable_file);
    // the soup validator reports such a face where a reader lets it through
    const std::vector<test::Point> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const auto r = shapecorr::validate_polygon_soup(p, std::vector<std::vector<std::size_t>>{{0, 1, 2}, {0, 1, 9}});
    CHECK(r.degenerate_faces == 1);
    CHECK(r.examples.at(D::degenerate_face) == "face 1 refers to a vertex past the end");
  }
  SECTION("no faces") {
    CHECK(read_defect<TestType>(write_file("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")) == D::empty_mesh);
  }
  SECTION("NaN coordinates, in text (which CGAL's readers cannot parse) and in binary files") {
    CHECK(read_defect<TestType>(write_file("nan.off", "OFF\n4 4 0\n0 0 0\nnan 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")) ==
          D::non_finite_coordinate);
    CHECK(read_defect<TestType>(write_file("inf.obj", "v 0 0 0\nv -inf 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n")) ==
          D::non_finite_coordinate);
    test::Surface_mesh nan_mesh;
    shapecorr::make_icosphere(nan_mesh, 1);
    nan_mesh.point(test::Surface_mesh::Vertex_index(5)) = test::Point(0, std::nan(""), 0);
    REQUIRE(CGAL::IO::write_polygon_mesh(test::temp_path(prefix + "nan_binary.ply"), nan_mesh, CGAL::parameters::use_binary_mode(true)));
    CHECK(read_defect<TestType>(test::temp_path(prefix + "nan_binary.ply")) == D::non_finite_coordinate);
  }
  SECTION("a truncated file is unreadable, not half-read") {
    CHECK(read_defect<TestType>(write_file("truncated.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1\n")) ==
          D::unreadable_file);
  }
  SECTION("degenerate faces: an error, or removed on request") {
    // a closed tetrahedron plus a sliver (0, 4, 5) whose vertices lie on one line
    const std::string p = write_file("degenerate.off",
        "OFF\n6 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 0\n3 0 0\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 0 4 5\n");
    CHECK(read_defect<TestType>(p) == D::degenerate_face);
    shapecorr::Read_options opt;
    opt.remove_degenerate_faces = true;
    TestType m;
    const auto r = shapecorr::read_triangle_mesh(p, m, opt);
    CHECK(num_faces(m) == 4);
    CHECK(num_vertices(m) == 4); // the vertices only the degenerate face used are gone too
    CHECK(r.repairs.size() == 2);
  }
  SECTION("isolated vertices are removed and reported") {
    TestType m;
    const auto r = shapecorr::read_triangle_mesh(
        write_file("isolated.off", "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n9 9 9\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"), m);
    CHECK(num_vertices(m) == 4);
    CHECK(r.report.isolated_vertices == 1);
    REQUIRE(r.repairs.size() == 1);
    CHECK(r.repairs[0] == "removed 1 isolated vertices");
    shapecorr::Read_options strict;
    strict.remove_isolated_vertices = false;
    CHECK(read_defect<TestType>(write_file("isolated2.off", "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n9 9 9\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"),
                                strict) == D::isolated_vertex);
  }
  SECTION("quads are triangulated") {
    TestType m;
    const auto r = shapecorr::read_triangle_mesh(
        write_file("cube.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                               "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n"), m);
    CHECK(num_faces(m) == 12);
    CHECK(r.report.non_triangle_faces == 6);
    CHECK(CGAL::is_triangle_mesh(m));
  }
  SECTION("non-manifold: an error, or split on request") {
    const std::string p = write_file("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n");
    CHECK(read_defect<TestType>(p) == D::non_manifold_vertex);
    shapecorr::Read_options opt;
    opt.repair_non_manifold = true;
    TestType m;
    shapecorr::read_triangle_mesh(p, m, opt);
    CHECK(num_vertices(m) == 6);
  }
  SECTION("requirements: closed and connected") {
    shapecorr::Read_options opt;
    opt.requirements.closed = true;
    CHECK(read_defect<TestType>(write_file("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n"), opt) == D::boundary);
    TestType ok;
    CHECK_NOTHROW(shapecorr::read_triangle_mesh(write_file("tet.off", tet_off), ok, opt));
  }
}

TEMPLATE_LIST_TEST_CASE("coloured PLY output", "[io]", test::Mesh_types) {
  TestType m;
  shapecorr::make_icosphere(m, 1);
  std::vector<double> values(num_vertices(m));
  for(std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i);
  shapecorr::write_colored_ply(test::temp_path("shapecorr_test_colored.ply"), m, values, {0});
  test::Surface_mesh back;
  std::ifstream in(test::temp_path("shapecorr_test_colored.ply"));
  REQUIRE(CGAL::IO::read_PLY(in, back));
  CHECK(back.number_of_vertices() == num_vertices(m));
  auto colors = back.property_map<test::Surface_mesh::Vertex_index, CGAL::IO::Color>("v:color");
  REQUIRE(colors.second);
  CHECK(colors.first[test::Surface_mesh::Vertex_index(0)] == CGAL::IO::Color(230, 20, 20));
  CHECK(colors.first[test::Surface_mesh::Vertex_index(41)] == CGAL::IO::Color(253, 231, 37)); // the maximum: yellow
  CHECK_THROWS_AS(shapecorr::write_colored_ply(test::temp_path("shapecorr_test_bad.ply"), m, std::vector<double>(3)), shapecorr::Invalid_argument);
}

TEMPLATE_LIST_TEST_CASE("correspondence lines: both meshes side by side, one line per pair", "[io]", test::Mesh_types) {
  TestType a, b;
  shapecorr::make_icosphere(a, 1);
  shapecorr::make_torus(b, 2.0, 0.5, 8, 5);
  const std::vector<std::pair<std::size_t, std::size_t>> pairs = {{0, 0}, {41, 39}, {7, 3}};
  const std::string path = test::temp_path("shapecorr_test_lines.obj");
  shapecorr::write_correspondences(path, a, b, pairs);
  std::ifstream in(path);
  std::string line;
  std::size_t v = 0, f = 0, l = 0;
  std::vector<std::string> lines;
  while(std::getline(in, line)) {
    v += line.rfind("v ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
    if(line.rfind("l ", 0) == 0) lines.push_back(line);
  }
  l = lines.size();
  CHECK(v == 42 + 40);
  CHECK(f == 80 + 80);
  REQUIRE(l == 3);
  CHECK(lines[1] == "l 42 82"); // 1-based: source vertex 41, target vertex 39 after the 42 source vertices
  CHECK_THROWS_AS(shapecorr::write_correspondences(path, a, b, {{42, 0}}), shapecorr::Invalid_argument);
}
