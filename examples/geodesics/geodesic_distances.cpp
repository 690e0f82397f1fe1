// Geodesic distances from one vertex of a mesh with the three engines, written as coloured PLY.
// Usage: example_geodesic_distances [MESH] (default: a generated torus).
// Writes geodesic_distances.ply into the current folder (and says so).
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <filesystem>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

int main(int argc, char** argv) {
  Mesh mesh;
  if(argc > 1) shapecorr::read_triangle_mesh(argv[1], mesh); // validates; throws shapecorr::Invalid_input
  else shapecorr::make_torus(mesh, 2.0, 0.7, 64, 24);

  // Precompute once, query many times.
  shapecorr::Heat_method_geodesics<Mesh> heat(mesh, shapecorr::parameters::use_intrinsic_delaunay(true));
  auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  const vertex_descriptor source(0);
  heat.compute_geodesic_distances(std::vector<vertex_descriptor>{source}, distance);

  // The reference: CGAL's exact shortest paths, through the one-call function.
  auto exact = mesh.add_property_map<vertex_descriptor, double>("v:exact", 0).first;
  shapecorr::compute_geodesic_distances(mesh, source, exact,
                                        shapecorr::parameters::geodesic_method(shapecorr::Geodesic_method::EXACT));
  double err = 0, dmax = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    err += std::abs(distance[v] - exact[v]);
    dmax = std::max(dmax, exact[v]);
  }
  std::cout << "heat vs exact: mean |error| = " << 100 * err / mesh.number_of_vertices() / dmax << "% of the largest distance\n";

  std::vector<double> values;
  for(vertex_descriptor v : vertices(mesh)) values.push_back(distance[v]);
  shapecorr::write_colored_ply("geodesic_distances.ply", mesh, values, {0});
  std::cout << "wrote " << std::filesystem::absolute("geodesic_distances.ply").string() << " (open it in MeshLab)\n";
}
