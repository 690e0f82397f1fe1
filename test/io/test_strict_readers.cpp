// The strict readers (issue 21): each defect of the hostile-input report as a named regression
// test, plus the formats' round trips through CGAL's writers.
#include "test_meshes.h"

#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace {
std::string write_bytes(const std::string& name, const std::string& content) {
  const std::string path = test::temp_path("shapecorr_strict_" + name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}
typedef std::vector<std::vector<std::size_t>> Faces;

// The message of the error reading `content` as `name`, "" when it reads.
std::string read_error(const std::string& name, const std::string& content) {
  const std::string path = write_bytes(name, content);
  std::vector<test::Point> p;
  Faces f;
  try {
    shapecorr::read_polygon_soup(path, p, f);
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(e.defect() == shapecorr::Mesh_defect::unreadable_file);
    const std::string m = e.what();
    CHECK(m.find(path + ": ") == 0);       // names the file
    CHECK(m.find('\n') == std::string::npos); // one line
    return m.substr(path.size() + 2);
  }
  return "";
}

const std::string ply_header3 = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
std::string binary_ply(bool little, int last_index, const std::string& extra = "") {
  std::string s = std::string("ply\nformat ") + (little ? "binary_little_endian" : "binary_big_endian") +
                  " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                  "property list uchar int vertex_indices\nend_header\n";
  auto put = [&](const void* v, std::size_t n) {
    char b[8];
    std::memcpy(b, v, n);
    for(std::size_t i = 0; i < n; ++i) s += little ? b[i] : b[n - 1 - i];
  };
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for(float c : xyz) put(&c, 4);
  s += char(3);
  const std::int32_t ids[3] = {0, 1, last_index};
  for(std::int32_t i : ids) put(&i, 4);
  return s + extra;
}
std::string binary_stl(std::uint32_t declared, int facets) {
  std::string s = "solid binary header";
  s.resize(80, ' ');
  for(int k = 0; k < 4; ++k) s += static_cast<char>((declared >> (8 * k)) & 255);
  for(int t = 0; t < facets; ++t) {
    const float v[12] = {0, 0, 1, 0, 0, float(t), 1, 0, float(t), 0, 1, float(t)};
    s.append(reinterpret_cast<const char*>(v), 48); // the test machines are little-endian, as STL
    s += std::string(2, '\0');
  }
  return s;
}
} // namespace

TEST_CASE("regression 31.2: a PLY face index of -1 is an error, not the last vertex", "[io][regression]") {
  CHECK(read_error("neg.ply", ply_header3 + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n") == "line 13: face 0 refers to vertex -1 (negative), but there are 3 vertices");
  CHECK(read_error("neg_le.ply", binary_ply(true, -1)).find("face 0 refers to vertex -1 (negative)") != std::string::npos);
  CHECK(read_error("neg_be.ply", binary_ply(false, -1)).find("byte ") == 0);
  // through read_triangle_mesh with isolated-vertex removal: still the reader's error
  test::Surface_mesh m;
  CHECK_THROWS_WITH(shapecorr::read_triangle_mesh(write_bytes("neg2.ply", ply_header3 + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"), m),
                    Catch::Contains("negative"));
}

TEST_CASE("regression 31.2: OFF indices past 2^64 or fractional are errors", "[io][regression]") {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  CHECK(read_error("big.off", head + "3 0 1 18446744073709551616\n") ==
        "line 6: face 0: vertex index is a number too large '18446744073709551616' (at most 18446744073709551615)");
  CHECK(read_error("frac.off", head + "3 0 1.5 2\n") == "line 6: face 0: vertex index is not an integer: '1.5'");
  CHECK(read_error("past.off", head + "3 0 1 3\n") == "line 6: face 0 refers to vertex 3, but there are 3 vertices");
  CHECK(read_error("negcount.off", "OFF\n-3 1 0\n") == "line 2: vertex count is a negative number '-3'");
}

TEST_CASE("regression 31.2: counts that disagree with the data are errors", "[io][regression]") {
  // binary STL: fewer facets declared than present, and more
  CHECK(read_error("fewer.stl", binary_stl(1, 2)).find("declares 1 triangles, which take 134 bytes, but the file has 184") != std::string::npos);
  CHECK(read_error("more.stl", binary_stl(3, 2)).find("declares 3 triangles") != std::string::npos);
  // OFF with more faces than declared
  CHECK(read_error("extra.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n") ==
        "line 7: data after the last of the 1 declared faces: '3' (the counts disagree with the content)");
  // PLY with trailing bytes, ASCII and binary
  CHECK(read_error("trail.ply", binary_ply(true, 2, "xy")) == "byte 218: 2 bytes after the last declared element (the counts disagree with the content)");
  CHECK(read_error("trail_a.ply", ply_header3 + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n9\n") == "line 14: data after the last declared element: '9'");
  // and short of data: every section of an OFF truncated
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  for(std::size_t n = 1; n + 1 < off.size(); ++n) {
    const std::string e = read_error("cut.off", off.substr(0, n));
    INFO("OFF cut at " << n << " bytes: " << e);
    CHECK_FALSE(e.empty());
  }
  const std::string ply = binary_ply(true, 2);
  for(std::size_t n = 1; n < ply.size(); n += 3) {
    INFO("PLY cut at " << n);
    CHECK_FALSE(read_error("cut.ply", ply.substr(0, n)).empty());
  }
}

TEST_CASE("regression 31.3: declared counts are checked against the file size before allocating", "[io][regression]") {
  CHECK(read_error("huge.off", "OFF\n3 300000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
        "line 2: declares 300000000 faces, but the bytes after the header hold at most 4 besides 3 vertices");
  CHECK(read_error("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
                               "property float z\nend_header\n0123") ==
        "line 3: declares 4000000000 vertex entries, but the 4 bytes after the header hold at most 0");
  // a list count far beyond the bytes left
  std::string ply = binary_ply(true, 2);
  ply[ply.size() - 13] = char(200);
  CHECK(read_error("list.ply", ply).find("a list of 200 items does not fit in the 12 bytes left") != std::string::npos);
}

TEST_CASE("regression 31.6: messages say what, where and why", "[io][regression]") {
  const std::string dir = test::temp_path("shapecorr_strict_dir.off");
  std::filesystem::create_directories(dir);
  std::vector<test::Point> p;
  Faces f;
  CHECK_THROWS_WITH(shapecorr::read_polygon_soup(dir, p, f), Catch::EndsWith("is a directory, not a mesh file"));
  CHECK(read_error("empty.off", "") == "the file is empty (0 bytes)");
  CHECK(read_error("random.off", std::string("\x93\x01\xfe\x00zz", 6)).find("control byte") != std::string::npos);
  CHECK(read_error("random.stl", std::string(100, '\x07')).find("the header declares 117901063 triangles") != std::string::npos);
  CHECK(read_error("x.xyz", "1 2 3").find("unknown mesh file extension '.xyz'") == 0);
  CHECK(read_error("float_index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                      "element face 1\nproperty list uchar float vertex_indices\nend_header\n") ==
        "line 7: face vertex indices of a floating-point type");
  CHECK(read_error("range.ply", ply_header3 + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n") ==
        "line 13: face 0, property 'vertex_indices': value '300' outside the range of its type [0, 255]");
  CHECK(read_error("obj.obj", "v 0 0 0\nv 1 0 0\nx 1\n") == "line 3: unknown OBJ statement 'x'");
  CHECK(read_error("obj0.obj", "v 0 0 0\nf 0 1 1\n") == "line 2: face 0: vertex index 0 (OBJ indices start at 1, or are negative)");
  CHECK(read_error("stl4.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n") ==
        "line 7: facet 0 has more than 3 vertices (STL facets are triangles)");
  // a face of fewer than three vertices is named for what it is
  const auto r = shapecorr::validate_polygon_soup(std::vector<test::Point>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, Faces{{0, 1, 2}, {0, 1}});
  CHECK(r.examples.at(shapecorr::Mesh_defect::degenerate_face) == "face 1 has only 2 vertices");
}

TEST_CASE("the strict readers accept what the formats allow", "[io]") {
  // BOM, CRLF and lone CR line ends, comments, counts on the header line
  std::vector<test::Point> p;
  Faces f;
  shapecorr::read_polygon_soup(write_bytes("crlf.off", "\xEF\xBB\xBFOFF 3 1 0\r\n# c\r0 0 0 # corner\n1 0 0\r\n0 1 0\n3 0 1 2"), p, f);
  CHECK((p.size() == 3 && f == Faces{{0, 1, 2}}));
  shapecorr::read_polygon_soup(write_bytes("rel.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf -3 -2 -1\n"), p, f);
  CHECK((p.size() == 3 && f == Faces{{0, 1, 2}, {0, 1, 2}}));
  for(bool little : {true, false}) {
    shapecorr::read_polygon_soup(write_bytes("b.ply", binary_ply(little, 2)), p, f);
    CHECK((p.size() == 3 && p[1] == test::Point(1, 0, 0) && f == Faces{{0, 1, 2}}));
  }
  shapecorr::read_polygon_soup(write_bytes("two.stl", binary_stl(2, 2)), p, f);
  CHECK((p.size() == 6 && f.size() == 2)); // two facets in different planes share no corner
  // equal corners become one vertex: two triangles over a shared edge
  std::string ascii = "solid t\n";
  for(const char* tri : {"0 0 0\nvertex 1 0 0\nvertex 0 1 0", "1 0 0\nvertex 1 1 0\nvertex 0 1 0"})
    ascii += std::string("facet normal 0 0 1\nouter loop\nvertex ") + tri + "\nendloop\nendfacet\n";
  shapecorr::read_polygon_soup(write_bytes("shared.stl", ascii + "endsolid t\n"), p, f);
  CHECK((p.size() == 4 && f == Faces{{0, 1, 2}, {1, 3, 2}}));
}

TEMPLATE_LIST_TEST_CASE("strict readers read what CGAL writes", "[io]", test::Mesh_types) {
  TestType sphere;
  shapecorr::make_icosphere(sphere, 2);
  for(const char* ext : {"off", "obj", "ply", "stl"})
    for(bool binary : {false, true}) {
      const std::string path = test::temp_path(std::string("shapecorr_strict_cgal_") + (binary ? "b." : "a.") + ext);
      REQUIRE(CGAL::IO::write_polygon_mesh(path, sphere, CGAL::parameters::stream_precision(17).use_binary_mode(binary)));
      std::vector<test::Point> p;
      Faces f;
      INFO(path);
      shapecorr::read_polygon_soup(path, p, f);
      CHECK(p.size() == 162);
      CHECK(f.size() == 320);
      CHECK(shapecorr::validate_polygon_soup(p, f).is_valid());
    }
}

TEST_CASE("regression 31.4: coordinates that overflow double arithmetic are rejected", "[io][regression]") {
  const std::vector<test::Point> p = {{0, 0, 0}, {1e200, 0, 0}, {0, 1e200, 0}, {0, 0, 1}};
  const auto r = shapecorr::validate_polygon_soup(p, Faces{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  CHECK(r.out_of_range_vertices == 2);
  CHECK_FALSE(r.is_valid());
  CHECK(std::isfinite(r.area));
  CHECK(std::isfinite(r.mean_edge_length));
  CHECK(std::isfinite(r.bbox_diagonal));
  CHECK_THROWS_WITH(shapecorr::require_valid(r), Catch::Contains("2 vertices with a coordinate beyond 1e38"));
  test::Surface_mesh m;
  try {
    shapecorr::read_triangle_mesh(write_bytes("huge.off", "OFF\n4 4 0\n0 0 0\n1e200 0 0\n0 1e200 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"), m);
    FAIL("accepted");
  } catch(const shapecorr::Invalid_input& e) {
    CHECK(e.defect() == shapecorr::Mesh_defect::coordinate_out_of_range);
  }
  // float-range meshes stay valid: 1e30 is fine
  const std::vector<test::Point> q = {{0, 0, 0}, {1e30, 0, 0}, {0, 1e30, 0}, {0, 0, 1e30}};
  CHECK(shapecorr::validate_polygon_soup(q, Faces{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}).is_valid());
}
