// Rigid descriptors (thesis chapter 3): Spin Contours of every vertex through a property map,
// matched between a shape and a rigidly moved copy; the face-based spin image of one vertex with
// sampled and with exact areas, and its picture beside the Spin Contour (the thesis's Figure 3.3).
// Usage: example_spin_contour_matching [MESH] (default: a generated bumpy sphere).
// Writes spin_descriptors_vertex0.png into the current folder (and says so).
#include <shapecorr/descriptors.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
namespace SP = shapecorr::parameters;

int main(int argc, char** argv) {
  Mesh a;
  if(argc > 1) shapecorr::read_triangle_mesh(argv[1], a); // validates; throws shapecorr::Invalid_input
  else {
    shapecorr::make_icosphere(a, 3); // made asymmetric by a smooth radial bump
    for(vertex_descriptor v : vertices(a)) {
      const K::Point_3 p = a.point(v);
      const double r = 1.0 + 0.15 * std::sin(3 * p.x() + 1) * std::cos(2 * p.y()) + 0.1 * p.z() * p.z() * p.x() + 0.05 * p.y() +
                       0.08 * p.z() * p.z() * p.z() + 0.06 * p.x() * p.z();
      a.point(v) = K::Point_3(r * p.x(), r * p.y(), r * p.z());
    }
  }
  // b: a copy turned by 30 degrees about z and moved
  Mesh b = a;
  const double c = std::cos(CGAL_PI / 6), s = std::sin(CGAL_PI / 6);
  for(vertex_descriptor v : vertices(b)) {
    const K::Point_3 p = b.point(v);
    b.point(v) = K::Point_3(c * p.x() - s * p.y() + 0.3, s * p.x() + c * p.y() - 1.0, p.z() + 2.0);
  }

  // 120 x 60 samples, support = the extent (the default), the central point direction as axis.
  const auto np = SP::spin_axis(shapecorr::Spin_axis::CENTRAL_DIRECTION);
  auto ca = a.add_property_map<vertex_descriptor, shapecorr::Spin_contour>("v:spin_contour").first;
  auto cb = b.add_property_map<vertex_descriptor, shapecorr::Spin_contour>("v:spin_contour").first;
  shapecorr::compute_spin_contours(a, vertices(a), ca, np);
  shapecorr::compute_spin_contours(b, vertices(b), cb, np);

  // Every 10th vertex of a against all of b: nearest contour (L1 distance) and the ratio test.
  std::vector<shapecorr::Spin_contour> sources, targets;
  std::vector<vertex_descriptor> ids;
  for(vertex_descriptor v : vertices(a))
    if(static_cast<std::size_t>(v) % 10 == 0) {
      sources.push_back(ca[v]);
      ids.push_back(v);
    }
  for(vertex_descriptor v : vertices(b)) targets.push_back(cb[v]);
  const auto matches = shapecorr::match_descriptors(sources, targets, shapecorr::Contour_l1_distance());
  std::size_t correct = 0, confident = 0;
  for(const auto& m : matches) {
    correct += m.target == static_cast<std::size_t>(ids[m.source]); // the copy keeps the vertex order
    confident += m.ratio() < 0.8;
  }
  std::cout << correct << " of " << matches.size() << " sampled vertices matched to themselves; " << confident
            << " pass the ratio test at 0.8\n";

  // One vertex: its face-based spin image with sampled areas and with exact areas. Both hold
  // surface area; with the whole surface inside the support they add up to the area of the mesh.
  const shapecorr::Spin_descriptors<Mesh> sd(a, np);
  const shapecorr::Oriented_point op = sd.oriented_point(*vertices(a).begin());
  const shapecorr::Spin_image sampled = sd.face_spin_image(op), exact = sd.exact_face_spin_image(op);
  double sum_sampled = 0, sum_exact = 0;
  for(float x : sampled.values()) sum_sampled += x;
  for(float x : exact.values()) sum_exact += x;
  std::cout << "area " << CGAL::Polygon_mesh_processing::area(a) << "; in the images of vertex 0: " << sum_sampled << " (sampled), "
            << sum_exact << " (exact); correlation of the two " << shapecorr::spin_image_correlation(sampled, exact).first << "\n";
  shapecorr::write_spin_descriptor_plot("spin_descriptors_vertex0.png", exact, sd.spin_contour(op));
  std::cout << "wrote " << std::filesystem::absolute("spin_descriptors_vertex0.png").string() << " (the exact face-based image and the Spin Contour)\n";
}
