// NICPS (thesis chapter 6): a sphere template deformed onto an ellipsoid of another triangulation
// (or SOURCE onto TARGET), after a rigid alignment; a progress line per iteration, the surface
// distances before and after.
// Usage: example_nicps [SOURCE TARGET] (default: generated). Writes fitted.off into the current
// folder (and says so).
#include <shapecorr/evaluation.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <filesystem>
#include <functional>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

int main(int argc, char** argv) {
  Mesh tmpl, target;
  if(argc > 2) {
    shapecorr::read_triangle_mesh(argv[1], tmpl); // validates; throws shapecorr::Invalid_input
    shapecorr::read_triangle_mesh(argv[2], target);
  } else {
    shapecorr::make_icosphere(tmpl, 3);   // 642 vertices
    shapecorr::make_icosphere(target, 4); // 2562 vertices, turned: other vertices on the same sphere
    shapecorr::Similarity_transform turn;
    turn.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
    shapecorr::apply_transform(target, turn);
    for(vertex_descriptor v : vertices(target)) {
      const K::Point_3 p = target.point(v);
      target.point(v) = K::Point_3(1.3 * p.x(), 0.9 * p.y(), 0.75 * p.z());
    }
  }

  //! [nicps]
  namespace SP = shapecorr::parameters;
  // rigid pre-alignment, then NICPS from the aligned template
  shapecorr::apply_transform(tmpl, shapecorr::align_rigidly(tmpl, target).transform);
  const double before = shapecorr::surface_distance(tmpl, target).l2;
  auto fitted = tmpl.add_property_map<vertex_descriptor, K::Point_3>("v:fitted").first; // the new positions
  const std::function<bool(const shapecorr::Nicps_iteration_record&)> progress = [](const shapecorr::Nicps_iteration_record& it) {
    std::cerr << "\riteration " << it.iteration + 1 << ", alpha " << it.alpha << ", pairs " << it.pairs << ", rms distance " << it.rms_distance
              << "   " << std::flush;
    return true; // false would stop here
  };
  const shapecorr::Nicps_report r = shapecorr::nicps(
      tmpl, target, fitted, SP::nicps_regularizer(shapecorr::Nicps_regularizer::COMBINATORIAL_LAPLACIAN).iteration_callback(progress));
  for(vertex_descriptor v : vertices(tmpl)) tmpl.point(v) = fitted[v]; // the template's connectivity, the fitted shape
  std::cerr << "\n" << r.iterations.size() << " iterations (" << shapecorr::to_string(r.stop) << "), " << r.seconds << " s\n";
  std::cout << "l2 distance to the target: " << before << " -> " << shapecorr::surface_distance(tmpl, target).l2 << "\n";
  //! [nicps]

  CGAL::IO::write_polygon_mesh("fitted.off", tmpl, CGAL::parameters::stream_precision(17));
  std::cout << "wrote " << std::filesystem::absolute("fitted.off").string() << " (the fitted template)\n";
}
