// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Evaluation helper: the shapes of the chapter 4 and 5 evaluations: meshes read with the
// non-manifold repair that keeps the file's vertex ids, and partial shapes (kept faces, a cut
// extremity) that remember the id of each vertex in the original shape.
#ifndef SHAPECORR_EVALUATION_SHAPES_H
#define SHAPECORR_EVALUATION_SHAPES_H

#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace eval {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
const std::size_t none = std::numeric_limits<std::size_t>::max();

// A source shape with, per vertex, the id of the vertex of the original shape it comes from.
struct Shape {
  Mesh mesh;
  std::vector<std::size_t> original;
};

Shape whole(const Mesh& m) {
  Shape s{m, {}};
  for(std::size_t i = 0; i < m.number_of_vertices(); ++i) s.original.push_back(i);
  return s;
}

// The faces of m whose corners all satisfy keep(v), compacted (isolated vertices dropped).
template <typename Keep>
Shape keep_faces(const Mesh& m, Keep&& keep) {
  Shape s;
  std::vector<std::size_t> id(m.number_of_vertices(), none);
  std::vector<K::Point_3> P;
  std::vector<std::vector<std::size_t>> T;
  for(auto f : m.faces()) {
    std::vector<std::size_t> t(3);
    int k = 0;
    bool ok = true;
    for(auto v : vertices_around_face(m.halfedge(f), m)) {
      ok = ok && keep(v.idx());
      t[static_cast<std::size_t>(k++)] = v.idx();
    }
    if(!ok) continue;
    for(auto& v : t) {
      if(id[v] == none) {
        id[v] = P.size();
        const auto& p = m.point(Vertex(static_cast<Mesh::size_type>(v)));
        P.push_back(p);
        s.original.push_back(v);
      }
      v = id[v];
    }
    T.push_back(t);
  }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(P, T, s.mesh);
  return s;
}

// A cut extremity: the geodesic ball of radius 0.15 D around the vertex of largest agd (the tip of
// a tail or a limb) removed.
Shape cut_extremity(const Mesh& m) {
  Mesh copy = m;
  auto map = copy.add_property_map<Vertex, double>("v:eval_agd", 0.0).first;
  shapecorr::compute_average_geodesic_distance(copy, map, shapecorr::parameters::number_of_sources(50));
  std::size_t tip = 0;
  for(auto v : copy.vertices())
    if(map[v] > map[Vertex(static_cast<Mesh::size_type>(tip))]) tip = v.idx();
  const double D = shapecorr::geodesic_diameter(m, shapecorr::parameters::geodesic_method(shapecorr::Geodesic_method::FAST_MARCHING));
  shapecorr::Fast_marching_geodesics<Mesh> fm(m);
  const Eigen::VectorXd d = fm.distances_from(tip);
  return keep_faces(m, [&](std::size_t v) { return d[static_cast<Eigen::Index>(v)] > 0.15 * D; });
}

// Non-manifold edges (camel-gallop-01 has 5) are split: the repair appends the duplicated vertices,
// so the ids of the file's vertices, which the ground truth refers to, stay valid (checked).
Mesh read(const std::string& path) {
  Mesh m;
  shapecorr::Read_options o;
  o.repair_non_manifold = true;
  const auto r = shapecorr::read_triangle_mesh(path, m, o);
  std::ifstream in(path);
  std::string magic;
  std::size_t n = 0;
  in >> magic >> n;
  if(magic == "OFF" && m.number_of_vertices() < n) throw std::runtime_error(path + ": the repair removed vertices; the ground truth ids would shift");
  if(!r.repairs.empty()) std::cerr << path << ": " << r.repairs.size() << " repair(s), " << m.number_of_vertices() << " vertices (file: " << n << ")\n";
  return m;
}

} // namespace eval

#endif
