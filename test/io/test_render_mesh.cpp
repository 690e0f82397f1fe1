// Pictures of coloured meshes: a square facing the camera shows the colour map of its values
// unshaded; a sphere's silhouette is a disc (area π/4 of its bounding square); the z-buffer keeps
// the nearer of two squares and the back view the other; bad input.
#include "spectral/spectral_test_helpers.h"
#include "test_meshes.h"

#include <shapecorr/io/render_mesh.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

namespace {
std::array<std::uint8_t, 3> pixel(const shapecorr::Rgb_picture& p, std::size_t x, std::size_t y) {
  const std::size_t i = 3 * (y * p.width + x);
  return {{p.rgb[i], p.rgb[i + 1], p.rgb[i + 2]}};
}
bool white(const std::array<std::uint8_t, 3>& c) { return c[0] == 255 && c[1] == 255 && c[2] == 255; }
int colour_distance(const std::array<std::uint8_t, 3>& a, const std::array<unsigned char, 3>& b) {
  int d = 0;
  for(std::size_t k = 0; k < 3; ++k) d = std::max(d, std::abs(int(a[k]) - int(b[k])));
  return d;
}
} // namespace

TEMPLATE_LIST_TEST_CASE("a picture of a sphere: its silhouette is a disc in each view", "[io][picture]", test::Mesh_types) {
  TestType sphere;
  shapecorr::make_icosphere(sphere, 4);
  std::vector<double> values(num_vertices(sphere), 1.0);
  shapecorr::Mesh_picture_options o;
  o.view_size = 200;
  const shapecorr::Rgb_picture p = shapecorr::colored_mesh_picture(sphere, values, o);
  REQUIRE(p.width == 2 * 200 + 100);
  REQUIRE(p.height == 200);
  for(std::size_t view = 0; view < 2; ++view) {
    double covered = 0;
    std::size_t x0 = p.width, x1 = 0, y0 = p.height, y1 = 0;
    for(std::size_t y = 0; y < 200; ++y)
      for(std::size_t x = view * 200; x < view * 200 + 200; ++x) {
        const auto c = pixel(p, x, y);
        if(white(c)) continue;
        covered += 1;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    const double box = double(x1 - x0 + 1) * double(y1 - y0 + 1);
    INFO("view " << view << ": " << covered << " pixels in a " << x1 - x0 + 1 << " x " << y1 - y0 + 1 << " box");
    CHECK(x1 - x0 + 1 == Approx(0.92 * 200).margin(3));  // the mesh fills 92 % of the view
    CHECK(covered / box == Approx(M_PI / 4).epsilon(0.03)); // a disc
  }
  // the colour bar: yellow at the top (the largest value), dark blue at the bottom
  CHECK(colour_distance(pixel(p, 400 + 20, 200 / 8 + 1), shapecorr::colormap_viridis(1.0)) < 8);
  CHECK(colour_distance(pixel(p, 400 + 20, 200 * 7 / 8 - 1), shapecorr::colormap_viridis(0.0)) < 8);
}

TEST_CASE("a picture of a square facing the camera shows the colour map of its values", "[io][picture]") {
  test::Surface_mesh square;
  shapecorr::make_grid(square, 20, 20, 2.0, 2.0); // [0, 2]², values = x / 2
  std::vector<double> values;
  for(auto v : vertices(square)) values.push_back(square.point(v).x() / 2);
  shapecorr::Mesh_picture_options o;
  o.view_size = 100;
  o.both_sides = false;
  o.view_direction = Eigen::Vector3d(0, 0, -1);
  o.view_up = Eigen::Vector3d(0, 1, 0);
  o.title = "x / 2";
  const shapecorr::Rgb_picture p = shapecorr::colored_mesh_picture(square, values, o);
  REQUIRE(p.height == 100 + 20);
  // the view spans x in [0, 2] over pixels 4..96; pixel column c sees x = 2 (c + 0.5 - 4) / 92
  for(std::size_t c : {10, 30, 50, 70, 90}) {
    const double t = (double(c) + 0.5 - 4) / 92;
    INFO("column " << c << ", value " << t);
    CHECK(colour_distance(pixel(p, c, 20 + 50), shapecorr::colormap_viridis(t)) <= 6);
  }
  // nothing outside the square; the title is drawn in black
  CHECK(white(pixel(p, 1, 20 + 50)));
  CHECK(white(pixel(p, 50, 20 + 1)));
  bool ink = false;
  for(std::size_t x = 0; x < 60; ++x)
    for(std::size_t y = 6; y < 13; ++y) ink = ink || pixel(p, x, y) == std::array<std::uint8_t, 3>{{0, 0, 0}};
  CHECK(ink);
  // a fixed range: values above max_value are clamped to yellow
  o.min_value = 0;
  o.max_value = 0.25;
  const shapecorr::Rgb_picture q = shapecorr::colored_mesh_picture(square, values, o);
  CHECK(colour_distance(pixel(q, 80, 70), shapecorr::colormap_viridis(1.0)) <= 2);
}

TEST_CASE("a picture keeps the nearer of two squares; the back view shows the other", "[io][picture]") {
  // two unit squares at z = 0 (value 0) and z = 1 (value 1), seen along −z: the z = 1 one is nearer
  std::vector<std::array<double, 3>> P = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<std::array<std::size_t, 3>> T = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  test::Surface_mesh m;
  shapecorr::internal::soup_to_mesh(P, T, m);
  std::vector<double> values = {0, 0, 0, 0, 1, 1, 1, 1};
  shapecorr::Mesh_picture_options o;
  o.view_size = 64;
  o.view_direction = Eigen::Vector3d(0, 0, -1);
  o.view_up = Eigen::Vector3d(0, 1, 0);
  const shapecorr::Rgb_picture p = shapecorr::colored_mesh_picture(m, values, o);
  CHECK(colour_distance(pixel(p, 32, 32), shapecorr::colormap_viridis(1.0)) <= 2);
  CHECK(colour_distance(pixel(p, 64 + 32, 32), shapecorr::colormap_viridis(0.0)) <= 2);
  // the same picture twice (deterministic)
  CHECK(shapecorr::colored_mesh_picture(m, values, o).rgb == p.rgb);
}

TEST_CASE("pictures of meshes: bad input and the PNG file", "[io][picture]") {
  test::Surface_mesh sphere, empty;
  shapecorr::make_icosphere(sphere, 2);
  const std::vector<double> values(num_vertices(sphere), std::nan(""));
  shapecorr::Mesh_picture_options o;
  o.view_size = 32;
  const shapecorr::Rgb_picture p = shapecorr::colored_mesh_picture(sphere, values, o); // no finite value: grey
  CHECK(pixel(p, 16, 16)[0] == pixel(p, 16, 16)[1]);
  CHECK(pixel(p, 16, 16)[1] == pixel(p, 16, 16)[2]);
  CHECK_THROWS_AS(shapecorr::colored_mesh_picture(sphere, std::vector<double>(3, 0.0), o), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::colored_mesh_picture(empty, std::vector<double>(), o), shapecorr::Invalid_input);
  o.view_size = 8;
  CHECK_THROWS_AS(shapecorr::colored_mesh_picture(sphere, values, o), shapecorr::Invalid_argument);
  o.view_size = 32;
  o.view_direction = Eigen::Vector3d(0, 0, 1);
  o.view_up = Eigen::Vector3d(0, 0, 2);
  CHECK_THROWS_AS(shapecorr::colored_mesh_picture(sphere, values, o), shapecorr::Invalid_argument);
  o.view_up = Eigen::Vector3d(0, 1, 0);
  const std::string path = test::temp_path("sphere.png");
  shapecorr::write_colored_mesh_png(path, sphere, values, o);
  std::ifstream in(path, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  CHECK(std::string(signature + 1, 3) == "PNG");
  CHECK_THROWS_AS(shapecorr::write_colored_mesh_png("/nonexistent-dir/x.png", sphere, values, o), shapecorr::Output_error);
}
