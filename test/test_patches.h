// Part of a shape as a CGAL user passes it: a Face_filtered_graph over a Surface_mesh, and the
// oracle of every test that runs on one, the same patch copied into a mesh of its own.
#ifndef SHAPECORR_TEST_TEST_PATCHES_H
#define SHAPECORR_TEST_TEST_PATCHES_H

#include "test_meshes.h"

#include <shapecorr/mesh/primitives.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <iterator>
#include <map>
#include <memory>
#include <vector>

namespace test {

typedef CGAL::Face_filtered_graph<Surface_mesh> Filtered_surface_mesh;

/// A patch of a mesh. `filtered` sees the faces of `whole` that were selected: its vertices keep
/// their descriptors (and so their indices in `whole`, not contiguous), and the filtered graph
/// numbers them 0..n-1 in its own vertex index map. `copy` is the same patch copied by
/// `CGAL::copy_face_graph`, and `to_copy` maps each vertex of the patch to its copy.
struct Patch {
  typedef Surface_mesh::Vertex_index vertex_descriptor;
  Surface_mesh whole;
  std::unique_ptr<Filtered_surface_mesh> filtered;
  Surface_mesh copy;
  std::map<vertex_descriptor, vertex_descriptor> to_copy;

  std::vector<vertex_descriptor> patch_vertices() const { return {vertices(*filtered).begin(), vertices(*filtered).end()}; }
};

/// The faces of `whole` whose centroid satisfies `keep(x, y, z)`, as a patch (not movable: the
/// filtered graph refers to `whole`).
template <typename Keep>
std::unique_ptr<Patch> make_patch(const Surface_mesh& whole, Keep keep) {
  auto p = std::make_unique<Patch>();
  p->whole = whole;
  std::vector<Surface_mesh::Face_index> selected;
  for(auto f : faces(p->whole)) {
    double c[3] = {0, 0, 0};
    for(auto v : CGAL::vertices_around_face(halfedge(f, p->whole), p->whole))
      for(int k = 0; k < 3; ++k) c[k] += CGAL::to_double(p->whole.point(v)[k]) / 3;
    if(keep(c[0], c[1], c[2])) selected.push_back(f);
  }
  p->filtered = std::make_unique<Filtered_surface_mesh>(p->whole, selected);
  std::vector<std::pair<Patch::vertex_descriptor, Patch::vertex_descriptor>> v2v;
  CGAL::copy_face_graph(*p->filtered, p->copy, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
  p->to_copy.insert(v2v.begin(), v2v.end());
  return p;
}

/// Most of a unit sphere (icosphere, 642 vertices): the faces with x + 0.3 y + 0.4 y z > -0.35, a
/// patch with one boundary and no symmetry (so that no two vertices tie in a furthest point
/// search); its vertices are scattered among the sphere's indices.
inline std::unique_ptr<Patch> sphere_patch() {
  Surface_mesh sphere;
  shapecorr::make_icosphere(sphere, 3);
  return make_patch(sphere, [](double x, double y, double z) { return x + 0.3 * y + 0.4 * y * z > -0.35; });
}

} // namespace test

#endif
