// Rigid alignment (the pre-alignment of thesis chapter 6): principal axes with every proper sign
// choice, then trimmed point-to-plane ICP; the surface distances before and after.
// Usage: example_rigid_alignment [SOURCE TARGET] (default: a bumpy ellipsoid and a resampled,
// rotated, moved and scaled copy of it, generated). Writes aligned.off into the current folder
// (and says so).
#include <shapecorr/evaluation.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <filesystem>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// A bumpy ellipsoid (axes 1, 0.7, 0.5) from an icosphere of `subdivisions`.
void make_shape(Mesh& m, int subdivisions) {
  shapecorr::make_icosphere(m, subdivisions);
  for(auto v : vertices(m)) {
    const K::Point_3 p = m.point(v);
    const double r = 1.0 + 0.1 * std::sin(3 * p.x() + 1) * std::cos(2 * p.y() + 0.5);
    m.point(v) = K::Point_3(r * p.x(), 0.7 * r * p.y(), 0.5 * r * p.z());
  }
}

int main(int argc, char** argv) {
  Mesh source, target;
  if(argc > 2) {
    shapecorr::read_triangle_mesh(argv[1], source); // validates; throws shapecorr::Invalid_input
    shapecorr::read_triangle_mesh(argv[2], target);
  } else {
    make_shape(source, 3);
    make_shape(target, 4); // the same surface, another triangulation
    shapecorr::Similarity_transform M;
    M.rotation = Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    M.scale = 1.25;
    M.translation = Eigen::Vector3d(3, -1, 2);
    shapecorr::apply_transform(target, M);
  }

  //! [align]
  namespace SP = shapecorr::parameters;
  const shapecorr::Rigid_alignment_report r = shapecorr::align_rigidly(
      source, target, SP::rigid_initialization(shapecorr::Rigid_initialization::PRINCIPAL_AXES).allow_scaling(true));
  std::cout << "start " << r.winning_start + 1 << " of " << r.starts_tried << " won; " << r.iterations.size() << " ICP iterations ("
            << shapecorr::to_string(r.stop) << "), trimmed RMS " << r.initial_rms << " -> " << r.final_rms << ", scale "
            << r.transform.scale << "\n";
  const double before = shapecorr::surface_distance(source, target).l2;
  shapecorr::apply_transform(source, r.transform); // move the source onto the target
  const double after = shapecorr::surface_distance(source, target).l2;
  std::cout << "l2 distance to the target: " << before << " -> " << after << "\n";
  //! [align]

  CGAL::IO::write_polygon_mesh("aligned.off", source, CGAL::parameters::stream_precision(17));
  std::cout << "wrote " << std::filesystem::absolute("aligned.off").string() << " (the aligned source)\n";
  return after <= before ? 0 : 1;
}
