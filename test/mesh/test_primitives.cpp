// Generated meshes: sizes, closedness, Euler characteristic.
#include "test_meshes.h"

#include <shapecorr/mesh.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

TEMPLATE_LIST_TEST_CASE("generated meshes are valid", "[mesh][primitives]", test::Mesh_types) {
  TestType sphere, torus, grid;
  shapecorr::make_icosphere(sphere, 3);
  shapecorr::make_torus(torus, 2, 0.5, 20, 8);
  shapecorr::make_grid(grid, 5, 4);
  const auto rs = shapecorr::validate_mesh(sphere), rt = shapecorr::validate_mesh(torus), rg = shapecorr::validate_mesh(grid);
  CHECK(rs.number_of_vertices == 642);
  CHECK(rs.is_valid());
  CHECK(rs.is_closed());
  CHECK(rs.area == Approx(4 * 3.14159265).epsilon(0.01));
  CHECK(rt.is_valid());
  CHECK(rt.is_closed());
  CHECK(rt.number_of_vertices == 160);
  CHECK(static_cast<long>(rt.number_of_vertices) - static_cast<long>(rt.number_of_faces) / 2 == 0); // chi = V - F/2 = 0
  CHECK(rg.is_valid());
  CHECK(rg.boundary_edges == 2 * (5 + 4));
  CHECK(rg.area == Approx(1.0));
  CHECK_THROWS_AS(shapecorr::make_icosphere(sphere, -1), shapecorr::Invalid_argument);
}

TEMPLATE_LIST_TEST_CASE("the creature: an icosphere with five limbs; levels share vertices; the bend moves one limb", "[mesh][primitives]", test::Mesh_types) {
  TestType coarse, fine, bent;
  shapecorr::make_creature(coarse, 2);
  shapecorr::make_creature(fine, 3);
  shapecorr::make_creature(bent, 3, 40.0);
  const auto r = shapecorr::validate_mesh(fine);
  CHECK(r.is_valid());
  CHECK(r.is_closed());
  CHECK(r.number_of_vertices == 642);
  const auto pc = test::vertices_in_index_order(coarse), pf = test::vertices_in_index_order(fine), pb = test::vertices_in_index_order(bent);
  auto point = [](const TestType& m, typename boost::graph_traits<TestType>::vertex_descriptor v) { return get(CGAL::vertex_point, m, v); };
  // vertex i of level 2 is vertex i of level 3
  double largest = 0;
  for(std::size_t i = 0; i < pc.size(); ++i) largest = std::max(largest, std::sqrt(CGAL::to_double(CGAL::squared_distance(point(coarse, pc[i]), point(fine, pf[i])))));
  CHECK(largest < 1e-12);
  // the longest limb reaches 1 + 1.2 from the centre; the bend moves only points beyond 0.9 along it
  double reach = 0;
  std::size_t moved = 0;
  for(std::size_t i = 0; i < pf.size(); ++i) {
    const auto p = point(fine, pf[i]);
    reach = std::max(reach, std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z())));
    const double along = (CGAL::to_double(p.x()) * 1 + CGAL::to_double(p.y()) * 0.2 + CGAL::to_double(p.z()) * 0.1) / std::sqrt(1.05);
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, point(bent, pb[i]))));
    if(d > 1e-12) {
      ++moved;
      CHECK(along > 0.9);
    }
  }
  CHECK((reach > 2.0 && reach <= 2.2 + 1e-9)); // the tip of the longest limb, up to the sampling of the level
  CHECK(moved > 10);
  CHECK_THROWS_AS(shapecorr::make_creature(bent, 2, 200.0), shapecorr::Invalid_argument);
  CHECK_THROWS_AS(shapecorr::make_creature(bent, 2, 0.0, -1.0), shapecorr::Invalid_argument);
  // limb_scale 2.5: the longest limb reaches 1 + 2.5 x 1.2
  TestType longer;
  shapecorr::make_creature(longer, 3, 0.0, 2.5);
  double longest = 0;
  for(auto v : vertices(longer)) {
    const auto p = point(longer, v);
    longest = std::max(longest, std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y() + p.z() * p.z())));
  }
  CHECK((longest > 3.5 && longest <= 4.0 + 1e-9));
}
