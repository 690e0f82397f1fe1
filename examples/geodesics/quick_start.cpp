// The README's example: read a mesh, geodesic distances from one vertex, furthest point samples,
// all-pairs distances and the local average geodesic distance, reusing one heat-method engine.
// Usage: example_quick_start MESH. Prints a summary; writes no file.
//! [quick_start]
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/sampling.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
namespace SP = shapecorr::parameters;

int main(int argc, char** argv) {
  if(argc < 2) return std::cerr << "usage: example_quick_start MESH\n", 2;
  Mesh mesh;
  shapecorr::read_triangle_mesh(argv[1], mesh);          // throws shapecorr::Invalid_input on bad data
  shapecorr::Heat_method_geodesics<Mesh> heat(mesh);     // factor once ...
  auto dist = mesh.add_property_map<Mesh::Vertex_index, double>("v:dist", 0).first;
  heat.compute_geodesic_distances(std::vector<Mesh::Vertex_index>{Mesh::Vertex_index(0)}, dist); // ... query often
  std::vector<Mesh::Vertex_index> samples;               // 10 furthest point samples, reusing the engine
  shapecorr::furthest_point_sampling(mesh, 10, std::back_inserter(samples), SP::geodesic_engine(&heat).random_seed(1u));
  auto D = shapecorr::compute_all_pairs_geodesic_distances(mesh, SP::geodesic_engine(&heat)); // float n x n
  auto agd = mesh.add_property_map<Mesh::Vertex_index, double>("v:agd", 0).first;
  shapecorr::compute_local_average_geodesic_distance(mesh, 0.15 * D.diameter(), agd);
  std::cout << mesh.number_of_vertices() << " vertices, geodesic diameter " << D.diameter() << ", first sample "
            << samples.front() << " at " << dist[samples.front()] << " from vertex 0\n";
}
//! [quick_start]
