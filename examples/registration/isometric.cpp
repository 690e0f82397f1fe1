// Fully automatic near-isometric correspondence (thesis chapter 5): the generated creature and a
// copy with its longest limb bent by 30 degrees (or SOURCE onto TARGET); stage times, the matches
// per level and, for the creature, the error of the dense map (vertex i of one is vertex i of the
// other).
// Usage: example_isometric [SOURCE TARGET] (default: generated).
#include <shapecorr/io.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/registration.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <functional>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv) {
  Mesh source, target;
  const bool generated = argc <= 2;
  if(!generated) {
    shapecorr::read_triangle_mesh(argv[1], source); // validates; throws shapecorr::Invalid_input
    shapecorr::read_triangle_mesh(argv[2], target);
  } else {
    shapecorr::make_creature(source, 3);       // 642 vertices: a round body with five limbs
    shapecorr::make_creature(target, 3, 30.0); // the same vertices, the longest limb bent
  }

  //! [isometric]
  namespace SP = shapecorr::parameters;
  const std::function<void(std::size_t, std::size_t)> progress = [](std::size_t done, std::size_t total) {
    std::cerr << "\rstage " << done << "/" << total << std::flush;
  };
  shapecorr::Isometric_correspondence<Mesh> method(source, target,
                                                   SP::number_of_features(10).number_of_levels(3).random_seed(0).progress_callback(progress));
  const shapecorr::Isometric_correspondence_report& report = method.run();
  std::cerr << "\n";
  for(const shapecorr::Isometric_level_record& level : report.levels)
    std::cout << "level " << level.level << ": " << level.new_matches << " new matches of " << level.candidates << " candidate pairs, energy "
              << level.energies.front() << " -> " << level.energies.back() << " after local optimization, "
              << level.matching_seconds + level.local_seconds << " s\n";
  const std::vector<std::size_t>& map = method.dense_map(); // target vertex of each source vertex
  //! [isometric]

  if(generated) {
    // the creature's ground truth: vertex i goes to vertex i; error in mean edge lengths (Euclidean)
    double error = 0, edge = 0;
    for(auto e : edges(source)) edge += std::sqrt(CGAL::squared_distance(source.point(source.vertex(e, 0)), source.point(source.vertex(e, 1))));
    edge /= double(num_edges(source));
    for(Mesh::Vertex_index v : vertices(source))
      error += std::sqrt(CGAL::squared_distance(target.point(Mesh::Vertex_index(Mesh::size_type(map[v.idx()]))), target.point(v)));
    std::cout << "dense map: mean distance to the true match " << error / double(num_vertices(source)) / edge << " edge lengths\n";
  }
  std::cout << report.matches.size() << " sparse matches (start " << report.chosen_seed << " of " << report.starts << " kept)\n";
}
