// Geodesic Spin Contour (thesis chapter 4): the GSC of every vertex (one geodesic engine, all
// threads, progress on stderr), and the contour distance of every vertex to one vertex written as
// a coloured PLY (the view of the thesis's Figures 4.6-4.7).
// Usage: example_geodesic_spin_contour [MESH [VERTEX]] (default: a generated torus, vertex 0).
// Writes gsc_distance.ply into the current folder (and says so).
#include <shapecorr/descriptors.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

int main(int argc, char** argv) {
  Mesh mesh;
  if(argc > 1) shapecorr::read_triangle_mesh(argv[1], mesh); // validates; throws shapecorr::Invalid_input
  else shapecorr::make_torus(mesh, 2.0, 0.7, 64, 24);
  const long id = argc > 2 ? std::atol(argv[2]) : 0;
  if(id < 0 || static_cast<std::size_t>(id) >= mesh.number_of_vertices()) {
    std::cerr << "vertex " << id << " out of range (the mesh has " << mesh.number_of_vertices() << " vertices)\n";
    return 1;
  }
  const vertex_descriptor source(static_cast<Mesh::size_type>(id));

  //! [gsc]
  namespace SP = shapecorr::parameters;
  // L = 0.4 D, local agd with r = 0.15 D (the thesis's wolf settings); D, the agd of every vertex
  // and the face adjacency are computed once, here
  shapecorr::Geodesic_spin_descriptors<Mesh> gsd(mesh, SP::support_fraction(0.4).agd_radius_fraction(0.15));
  shapecorr::Spin_contour a = gsd.geodesic_spin_contour(source);                  // one vertex
  std::vector<std::size_t> ids = {gsd.index(source), 1, 2};                       // vertex indices
  std::vector<shapecorr::Spin_contour> some = gsd.geodesic_spin_contours(ids);    // in parallel
  double d = shapecorr::contour_l1_distance(a, some[1]);                          // the Spin Contour's L1

  // or every vertex at once, into a property map (any FaceGraph: Polyhedron_3, OpenMesh, your own)
  auto gsc = mesh.add_property_map<vertex_descriptor, shapecorr::Spin_contour>("v:gsc").first;
  shapecorr::compute_geodesic_spin_contours(mesh, vertices(mesh), gsc,
                                            SP::support_fraction(0.4).agd_radius_fraction(0.15).progress_callback(
                                                [](std::size_t done, std::size_t total) {
                                                  if(done == total || done % 500 == 0) std::cerr << "\rprogress " << done << " / " << total << std::flush;
                                                }));
  //! [gsc]
  std::cerr << "\n";
  std::cout << "L1 distance between the GSCs of vertices " << id << " and 1: " << d << " (D = " << gsd.geodesic_diameter() << ")\n";

  std::vector<double> distance;
  std::size_t points = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    distance.push_back(shapecorr::contour_l1_distance(gsc[v], gsc[source]));
    points += gsc[v].size();
  }
  std::vector<double> sorted = distance;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t alike = static_cast<std::size_t>(std::count(distance.begin(), distance.end(), 0.0));
  std::cout << mesh.number_of_vertices() << " contours, " << points / mesh.number_of_vertices() << " points on average; distance to vertex "
            << id << ": median " << sorted[sorted.size() / 2] << ", largest " << sorted.back() << "; " << alike
            << " vertices (the source among them) have a contour identical to its own\n";
  const std::string output = "gsc_distance.ply";
  shapecorr::write_colored_ply(output, mesh, distance, {static_cast<std::size_t>(id)});
  std::cout << "wrote " << std::filesystem::absolute(output).string() << " (GSC distance to vertex " << id << ", marked red)\n";
}
