// A mesh with its vertices renumbered: the input of the invariance-under-renumbering tests.
#ifndef SHAPECORR_TEST_TEST_RENUMBERING_H
#define SHAPECORR_TEST_TEST_RENUMBERING_H

#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace test {

/// The surface of `a` with its vertices in a random order (std::mt19937(seed)): vertex i of `a`
/// is vertex perm[i] of the copy.
inline Surface_mesh renumbered_copy(const Surface_mesh& a, unsigned seed, std::vector<std::size_t>& perm) {
  const std::size_t n = a.number_of_vertices();
  perm.resize(n);
  std::iota(perm.begin(), perm.end(), std::size_t(0));
  std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
  std::vector<Point> pts(n);
  for(std::size_t i = 0; i < n; ++i) pts[perm[i]] = a.point(Surface_mesh::Vertex_index(static_cast<unsigned>(i)));
  std::vector<std::vector<std::size_t>> polys;
  for(auto f : faces(a)) {
    polys.emplace_back();
    for(auto v : CGAL::vertices_around_face(halfedge(f, a), a)) polys.back().push_back(perm[v.idx()]);
  }
  Surface_mesh b;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, b);
  return b;
}

} // namespace test

#endif
