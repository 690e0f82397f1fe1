// Generated meshes: sizes, closedness, Euler characteristic.
#include "test_meshes.h"

#include <shapecorr/mesh.h>
#include <shapecorr/mesh/primitives.h>

#include <catch2/catch.hpp>

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
