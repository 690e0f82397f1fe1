// Surface distances between two meshes (thesis chapter 6 metrics): l1, l2 and lmax in both
// directions with the quadrature's error bound, and the distance of every vertex of the first mesh
// to the second written as a coloured PLY.
// Usage: example_surface_distance [R T] (default: a bumpy sphere and an ellipsoid, generated).
// Writes surface_distance.ply into the current folder (and says so).
#include <shapecorr/evaluation.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

int main(int argc, char** argv) {
  Mesh R, T;
  if(argc > 2) {
    shapecorr::read_triangle_mesh(argv[1], R); // validates; throws shapecorr::Invalid_input
    shapecorr::read_triangle_mesh(argv[2], T);
  } else {
    shapecorr::make_icosphere(R, 3);
    for(vertex_descriptor v : vertices(R)) {
      const K::Point_3 p = R.point(v);
      R.point(v) = K::Point_3(CGAL::ORIGIN + (1.0 + 0.1 * std::sin(3 * p.x()) * std::cos(2 * p.y())) * (p - CGAL::ORIGIN));
    }
    shapecorr::make_icosphere(T, 4);
    for(vertex_descriptor v : vertices(T)) T.point(v) = K::Point_3(1.1 * T.point(v).x(), 0.9 * T.point(v).y(), T.point(v).z());
  }

  //! [distances]
  // R to T and T to R: l1 (mean), l2 (root mean square), lmax (Hausdorff), each within error_bound
  const shapecorr::Symmetric_surface_distance s = shapecorr::symmetric_surface_distance(R, T);
  std::cout << "R to T: l1 " << s.forward.l1 << ", l2 " << s.forward.l2 << ", lmax " << s.forward.lmax
            << " (each within " << s.forward.error_bound << ")\n"
            << "T to R: l1 " << s.backward.l1 << ", l2 " << s.backward.l2 << ", lmax " << s.backward.lmax << "\n"
            << "symmetric: l1 " << s.l1 << ", l2 " << s.l2 << ", Hausdorff " << s.lmax << "\n";

  // the distance of every vertex of R to T, in a property map
  auto distance = R.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  shapecorr::compute_distances_to_surface(R, T, distance);
  //! [distances]

  std::vector<double> values;
  for(vertex_descriptor v : vertices(R)) values.push_back(distance[v]);
  shapecorr::write_colored_ply("surface_distance.ply", R, values);
  std::cout << "wrote " << std::filesystem::absolute("surface_distance.ply").string() << " (R coloured by its distance to T)\n";
}
