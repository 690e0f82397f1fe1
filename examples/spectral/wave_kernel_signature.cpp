// Laplace-Beltrami eigenbasis, WKS, HKS and intrinsic shape contexts of a mesh; the WKS distance of every vertex to one vertex,
// written as a coloured PLY (the view of the thesis's Figure 4.6).
// Usage: example_wave_kernel_signature [MESH [VERTEX]] (default: a generated torus, vertex 0).
// Writes basis.eig and wks_distance.ply into the current folder (and says so).
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/spectral.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

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
  const vertex_descriptor source(argc > 2 ? static_cast<Mesh::size_type>(std::atoi(argv[2])) : 0);

  // One eigen-solve (Spectra, shift-invert), shared by every descriptor.
  const std::size_t k = std::min<std::size_t>(300, mesh.number_of_vertices() / 2);
  //! [eigenbasis]
  shapecorr::Laplace_beltrami_eigenbasis basis =
      shapecorr::compute_laplace_beltrami_eigenbasis(mesh, k);   // k smallest pairs of L phi = lambda M phi
  const Eigen::VectorXd& lambda = basis.eigenvalues();          // k, ascending
  const Eigen::MatrixXd& phi = basis.eigenvectors();            // n x k, M-orthonormal: Phi^T M Phi = I
  basis.save("basis.eig");                                      // binary, checked when read back
  const auto again = shapecorr::Laplace_beltrami_eigenbasis::load("basis.eig");
  //! [eigenbasis]
  std::cout << k << " eigenpairs, lambda_2 = " << lambda[1] << ", lambda_k = " << lambda[static_cast<Eigen::Index>(k - 1)]
            << "; Phi is " << phi.rows() << " x " << phi.cols() << "; wrote " << std::filesystem::absolute("basis.eig").string()
            << " and read it back (" << again.number_of_eigenpairs() << " pairs)\n";

  auto wks = mesh.add_property_map<vertex_descriptor, std::vector<double>>("v:wks").first;
  auto hks = mesh.add_property_map<vertex_descriptor, std::vector<double>>("v:hks").first;
  shapecorr::compute_wave_kernel_signature(mesh, wks, shapecorr::parameters::eigenbasis(&basis));
  shapecorr::compute_heat_kernel_signature(mesh, hks, shapecorr::parameters::eigenbasis(&basis));

  std::vector<double> distance;
  std::size_t closer = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    distance.push_back(shapecorr::spectral_descriptor_distance(wks[v], wks[source]));
    if(v != source && shapecorr::spectral_descriptor_distance(hks[v], hks[source]) < 1e-3) ++closer;
  }
  std::cout << closer << " vertices have an HKS within 1e-3 of vertex " << static_cast<std::size_t>(source) << "'s"
            << (argc > 1 ? "\n" : " (on the default torus: the vertices of its ring, by its 64-fold rotational symmetry)\n");
  // the intrinsic shape context: a geodesic polar histogram of the SI-HKS around each vertex
  //! [isc]
  const shapecorr::Intrinsic_shape_context<Mesh> isc(mesh, shapecorr::parameters::eigenbasis(&basis));
  const Eigen::MatrixXd contexts = isc.descriptors({0, 1, 100});   // one row per vertex
  const double d01 = shapecorr::spectral_descriptor_distance(contexts.row(0), contexts.row(1));
  //! [isc]
  std::cout << "ISC: " << isc.size() << " values per vertex (radius " << isc.radius() << "); distance of vertices 0 and 1: " << d01
            << ", of 0 and 100: " << shapecorr::spectral_descriptor_distance(contexts.row(0), contexts.row(2)) << "\n";
  shapecorr::write_colored_ply("wks_distance.ply", mesh, distance, {static_cast<std::size_t>(source)});
  std::cout << "wrote " << std::filesystem::absolute("wks_distance.ply").string() << " (WKS distance to vertex "
            << static_cast<std::size_t>(source) << ", marked red; open it in MeshLab)\n";
}
