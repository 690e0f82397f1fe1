// All-pairs geodesic distances, the diameter, furthest point samples and the local average
// geodesic distance of a mesh.
// Usage: example_all_pairs_and_sampling [MESH] (default: a generated sphere).
// Writes local_agd.ply into the current folder (and says so).
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/sampling.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <filesystem>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
namespace SP = shapecorr::parameters;

int main(int argc, char** argv) {
  Mesh mesh;
  if(argc > 1) shapecorr::read_triangle_mesh(argv[1], mesh);
  else shapecorr::make_icosphere(mesh, 4);

  shapecorr::Heat_method_geodesics<Mesh> engine(mesh);
  const shapecorr::Geodesic_distance_matrix D = shapecorr::compute_all_pairs_geodesic_distances(
      mesh, SP::geodesic_engine(&engine).progress_callback(std::function<void(std::size_t, std::size_t)>(
                [](std::size_t done, std::size_t total) {
                  if(done == total) std::cout << "all-pairs: " << total << " sources done\n";
                })));
  std::cout << "diameter D = " << D.diameter() << ", matrix uses " << D.memory_bytes() / 1e6 << " MB\n";

  std::vector<vertex_descriptor> samples;
  shapecorr::furthest_point_sampling(mesh, 10, std::back_inserter(samples), SP::geodesic_engine(&engine).random_seed(1u));
  std::cout << "10 furthest point samples:";
  for(vertex_descriptor v : samples) std::cout << ' ' << v.idx();
  std::cout << "\n";

  auto agd = mesh.add_property_map<vertex_descriptor, double>("v:agd", 0).first;
  shapecorr::compute_local_average_geodesic_distance(mesh, 0.15 * D.diameter(), agd);
  std::vector<double> values;
  for(vertex_descriptor v : vertices(mesh)) values.push_back(agd[v]);
  std::vector<std::size_t> highlight;
  for(vertex_descriptor v : samples) highlight.push_back(v.idx());
  shapecorr::write_colored_ply("local_agd.ply", mesh, values, highlight);
  std::cout << "wrote " << std::filesystem::absolute("local_agd.ply").string() << ": local agd (r = 0.15 D), samples in red\n";
}
