// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// A value per vertex as a coloured mesh (PLY, for MeshLab) and as a picture (PNG, both sides and a
// colour bar): here the geodesic distance from vertex 0 of a mesh (a generated torus without one).
// Usage: example_colored_mesh_picture [MESH]. Writes distance.ply and distance.png.
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

int main(int argc, char** argv) {
  Mesh mesh;
  if(argc > 1) shapecorr::read_triangle_mesh(argv[1], mesh);
  else shapecorr::make_torus(mesh, 1.0, 0.4, 64, 24);
  auto dist = mesh.add_property_map<Mesh::Vertex_index, double>("v:dist", 0).first;
  shapecorr::compute_geodesic_distances(mesh, std::vector<Mesh::Vertex_index>{Mesh::Vertex_index(0)}, dist);
  //! [picture]
  std::vector<double> values; // one per vertex, in the order of the vertex index map
  for(Mesh::Vertex_index v : vertices(mesh)) values.push_back(dist[v]);
  shapecorr::write_colored_ply("distance.ply", mesh, values, {0}); // vertex 0 painted red
  shapecorr::Mesh_picture_options options;                         // 400 px per view, front and back,
  options.title = "geodesic distance from vertex 0";               // views from the principal axes
  shapecorr::write_colored_mesh_png("distance.png", mesh, values, options);
  //! [picture]
  std::cout << mesh.number_of_vertices() << " vertices -> distance.ply, distance.png\n";
}
