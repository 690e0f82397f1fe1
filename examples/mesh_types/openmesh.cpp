// ShapeCorr on a mesh type outside namespace CGAL: OpenMesh's TriMesh, through CGAL's graph traits
// for it. Geodesic distances, a Laplace-Beltrami eigenbasis and Geodesic Spin Contours, with
// results in CGAL's dynamic property maps (which work on every FaceGraph) and the vertex index map
// passed explicitly, as a type without internal indices needs it. Prints a few figures; writes no
// file. doc/concepts.md explains each requirement.
// Usage: example_openmesh [MESH] (default: a generated torus)
#include <shapecorr/descriptors.h>
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/spectral.h>

//! [openmesh]
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
// CGAL's adapters: graph_traits, and property maps (vertex_point, indices, dynamic properties)
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>

typedef OpenMesh::TriMesh_ArrayKernelT<> Mesh; // float coordinates
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
namespace SP = shapecorr::parameters;
//! [openmesh]

#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  Mesh mesh;
  if(argc > 1) shapecorr::read_triangle_mesh(argv[1], mesh); // validates; throws shapecorr::Invalid_input
  else shapecorr::make_torus(mesh, 2.0, 0.7, 48, 16);

  //! [compute]
  // Vertex indices 0..n-1: OpenMesh's own (h.idx()), given explicitly; a type without indices
  // passes any ReadablePropertyMap<vertex_descriptor, std::size_t> here.
  auto vim = get(boost::vertex_index, mesh);

  // Geodesic distances from vertex 0 into a dynamic property map.
  auto distance = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  const vertex_descriptor source = *vertices(mesh).begin();
  shapecorr::compute_geodesic_distances(mesh, source, distance, SP::vertex_index_map(vim));

  // The first 20 eigenpairs of the Laplace-Beltrami operator (rows in the order of vim).
  const shapecorr::Laplace_beltrami_eigenbasis basis =
      shapecorr::compute_laplace_beltrami_eigenbasis(mesh, 20, SP::vertex_index_map(vim));

  // The Geodesic Spin Contour of every vertex, into another dynamic property map.
  auto contours = get(CGAL::dynamic_vertex_property_t<shapecorr::Spin_contour>(), mesh);
  shapecorr::compute_geodesic_spin_contours(mesh, vertices(mesh), contours, SP::support_fraction(0.4).vertex_index_map(vim));
  //! [compute]

  double farthest = 0;
  vertex_descriptor far_vertex = source;
  for(vertex_descriptor v : vertices(mesh))
    if(get(distance, v) > farthest) farthest = get(distance, v), far_vertex = v;
  std::cout << num_vertices(mesh) << " vertices; farthest vertex from " << get(vim, source) << ": " << get(vim, far_vertex)
            << " at " << farthest << "\nlambda_2 = " << basis.eigenvalues()[1] << ", lambda_20 = " << basis.eigenvalues()[19]
            << "\nGSC of vertex 0: " << get(contours, source).size() << " points; L1 distance to the farthest vertex's: "
            << shapecorr::contour_l1_distance(get(contours, source), get(contours, far_vertex)) << "\n";
}
