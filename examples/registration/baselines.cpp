// The baselines of the thesis's chapter 6 beside NICPS: a sphere template deformed onto an
// ellipsoid of another triangulation and similar density (or SOURCE onto TARGET) by each method,
// after one rigid alignment; the l2 surface distance after each and its time.
// Usage: example_baselines [SOURCE TARGET] (default: generated).
#include <shapecorr/evaluation.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iomanip>
#include <iostream>
#include <string>

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
    shapecorr::make_icosphere(target, 3); // turned: other vertices on the same sphere
    shapecorr::Similarity_transform turn;
    turn.rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
    shapecorr::apply_transform(target, turn);
    for(vertex_descriptor v : vertices(target)) {
      const K::Point_3 p = target.point(v);
      target.point(v) = K::Point_3(1.3 * p.x(), 0.9 * p.y(), 0.75 * p.z());
    }
  }
  shapecorr::apply_transform(tmpl, shapecorr::align_rigidly(tmpl, target).transform);
  std::cout << "l2 distance to the target after the rigid alignment: " << shapecorr::surface_distance(tmpl, target).l2 << "\n";

  //! [baselines]
  auto fitted = tmpl.add_property_map<vertex_descriptor, K::Point_3>("v:fitted").first; // the new positions
  // every method: (template, target, output map[, named parameters]); a report with one record per iteration
  auto show = [&](const std::string& method, const shapecorr::Registration_report& r) {
    Mesh result = tmpl;
    for(vertex_descriptor v : vertices(result)) result.point(v) = fitted[v];
    std::cout << std::left << std::setw(9) << method << " l2 " << shapecorr::surface_distance(result, target).l2 << ", " << r.iterations.size()
              << " iterations (" << shapecorr::to_string(r.stop) << "), " << r.seconds << " s\n";
  };
  namespace SP = shapecorr::parameters;
  show("andresen", shapecorr::andresen_registration(tmpl, target, fitted, SP::time_step(0.1)));
  show("pauly", shapecorr::pauly_registration(tmpl, target, fitted));
  show("cpd", shapecorr::cpd_registration(tmpl, target, fitted, SP::kernel_width(2.0).regularization_weight(3.0).outlier_weight(0.1)));
  show("gmm-l2", shapecorr::gmm_l2_registration(tmpl, target, fitted, SP::number_of_control_points(std::size_t(300))));
  //! [baselines]
  const shapecorr::Nicps_report n = shapecorr::nicps(tmpl, target, fitted);
  for(vertex_descriptor v : vertices(tmpl)) tmpl.point(v) = fitted[v];
  std::cout << std::left << std::setw(9) << "nicps" << " l2 " << shapecorr::surface_distance(tmpl, target).l2 << ", " << n.iterations.size() << " iterations ("
            << shapecorr::to_string(n.stop) << "), " << n.seconds << " s\n";
}
