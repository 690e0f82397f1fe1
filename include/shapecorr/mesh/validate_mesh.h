// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file validate_mesh.h
/// Detect and report what can be wrong with an input surface.
#ifndef SHAPECORR_MESH_VALIDATE_MESH_H
#define SHAPECORR_MESH_VALIDATE_MESH_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrMesh
/// The largest coordinate magnitude a valid mesh may have. Beyond it squared lengths and squared
/// areas (products of four coordinates) leave the double range; rescale such a mesh first.
constexpr double max_coordinate_magnitude = 1e38;

/// \ingroup PkgShapeCorrMesh
/// What `validate_polygon_soup()` / `validate_mesh()` found. Counts, plus for each defect the
/// first few places (vertex or face indices, 0-based) in `examples`.
struct Mesh_report {
  std::size_t number_of_vertices = 0;    ///< vertices in the input
  std::size_t number_of_faces = 0;       ///< faces in the input
  std::size_t non_triangle_faces = 0;    ///< faces with other than three vertices
  std::size_t non_finite_vertices = 0;   ///< vertices with a NaN or infinite coordinate
  std::size_t out_of_range_vertices = 0; ///< vertices with a finite coordinate of magnitude > `max_coordinate_magnitude`
  std::size_t degenerate_faces = 0;       ///< repeated vertex or area <= 1e-14 * bbox diagonal^2
  std::size_t non_manifold_edges = 0;     ///< edges with > 2 faces or two faces of equal orientation
  std::size_t non_manifold_vertices = 0;  ///< vertices whose faces form several fans
  std::size_t isolated_vertices = 0;     ///< vertices used by no face
  std::size_t boundary_edges = 0;        ///< edges with one face
  std::size_t connected_components = 0;   ///< of the faces (isolated vertices not counted)
  double area = 0;                       ///< total area of the triangles
  double mean_edge_length = 0;           ///< mean length of the edges
  double bbox_diagonal = 0;              ///< diagonal of the axis-aligned bounding box
  std::map<Mesh_defect, std::string> examples; ///< "face 12 (vertices 3, 3, 7)", ...

  /// No vertex or no face.
  bool is_empty() const { return number_of_vertices == 0 || number_of_faces == 0; }
  /// No boundary edge.
  bool is_closed() const { return boundary_edges == 0; }
  /// True when the surface is a usable triangle mesh: nonempty, triangles only, finite
  /// coordinates, no degenerate face, manifold, no isolated vertex. Boundaries and several
  /// components are allowed (see `Mesh_requirements`).
  bool is_valid() const {
    return !is_empty() && non_triangle_faces == 0 && non_finite_vertices == 0 && out_of_range_vertices == 0 && degenerate_faces == 0 &&
           non_manifold_edges == 0 && non_manifold_vertices == 0 && isolated_vertices == 0;
  }
  /// Multi-line, human-readable summary.
  std::string to_string() const {
    std::ostringstream o;
    o << "vertices: " << number_of_vertices << "\nfaces: " << number_of_faces << "\nconnected components: "
      << connected_components << "\nboundary edges: " << boundary_edges << "\nnon-triangle faces: " << non_triangle_faces
      << "\nnon-finite vertices: " << non_finite_vertices << "\nout-of-range vertices: " << out_of_range_vertices << "\ndegenerate faces: " << degenerate_faces
      << "\nnon-manifold edges: " << non_manifold_edges << "\nnon-manifold vertices: " << non_manifold_vertices
      << "\nisolated vertices: " << isolated_vertices << "\narea: " << area << "\nmean edge length: " << mean_edge_length
      << "\nbounding box diagonal: " << bbox_diagonal << "\nvalid: " << (is_valid() ? "yes" : "no") << "\n";
    for(const auto& e : examples) o << "  " << shapecorr::to_string(e.first) << ": " << e.second << "\n";
    return o.str();
  }
};

/// \ingroup PkgShapeCorrMesh
/// What an algorithm needs of its input beyond `Mesh_report::is_valid()`.
struct Mesh_requirements {
  bool closed = false;    ///< no boundary edge
  bool connected = false; ///< exactly one connected component
};

namespace internal {

/// Area of a polygon (norm of its vector area); 0 when it repeats a vertex.
template <typename PointRange, typename Polygon>
double polygon_area(const PointRange& points, const Polygon& f) {
  std::vector<std::size_t> sorted(f.begin(), f.end());
  std::sort(sorted.begin(), sorted.end());
  if(f.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return 0.0;
  double ax = 0, ay = 0, az = 0;
  for(std::size_t k = 0; k < f.size(); ++k) {
    const auto& a = points[f[k]];
    const auto& b = points[f[(k + 1) % f.size()]];
    const double a0 = CGAL::to_double(a.x()), a1 = CGAL::to_double(a.y()), a2 = CGAL::to_double(a.z());
    const double b0 = CGAL::to_double(b.x()), b1 = CGAL::to_double(b.y()), b2 = CGAL::to_double(b.z());
    ax += a1 * b2 - a2 * b1;
    ay += a2 * b0 - a0 * b2;
    az += a0 * b1 - a1 * b0;
  }
  return 0.5 * std::sqrt(ax * ax + ay * ay + az * az);
}

/// The one degeneracy test: repeated vertex, or area <= 1e-14 * bbox_diagonal^2.
template <typename PointRange, typename Polygon>
bool is_degenerate_polygon(const PointRange& points, const Polygon& f, double bbox_diagonal) {
  const double area = polygon_area(points, f);
  return !(area > 1e-14 * bbox_diagonal * bbox_diagonal);
}

} // namespace internal

/// \ingroup PkgShapeCorrMesh
/// Checks a polygon soup (points, polygons as vertex index lists) for every defect of
/// `Mesh_defect`. Works on data no halfedge structure can hold (non-manifold, non-oriented).
/// \tparam PointRange a random-access range of points with `x()`, `y()`, `z()`
/// \tparam PolygonRange a range of ranges of integer indices
template <typename PointRange, typename PolygonRange>
Mesh_report validate_polygon_soup(const PointRange& points, const PolygonRange& polygons) {
  Mesh_report r;
  r.number_of_vertices = points.size();
  r.number_of_faces = polygons.size();
  const std::size_t n = points.size();
  auto note = [&](Mesh_defect d, const std::string& where) {
    if(r.examples.count(d) == 0) r.examples[d] = where;
  };
  std::vector<std::array<double, 3>> P(n);
  std::vector<char> unusable(n, 0); // a non-finite or out-of-range coordinate: reported once, as such
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(std::size_t i = 0; i < n; ++i) {
    const auto& p = points[i];
    P[i] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if(!(std::isfinite(P[i][0]) && std::isfinite(P[i][1]) && std::isfinite(P[i][2]))) {
      ++r.non_finite_vertices;
      note(Mesh_defect::non_finite_coordinate, "vertex " + std::to_string(i));
      unusable[i] = 1;
      continue;
    }
    if(std::max({std::abs(P[i][0]), std::abs(P[i][1]), std::abs(P[i][2])}) > max_coordinate_magnitude) {
      ++r.out_of_range_vertices;
      note(Mesh_defect::coordinate_out_of_range, "vertex " + std::to_string(i));
      unusable[i] = 1;
      continue;
    }
    for(int k = 0; k < 3; ++k) { lo[k] = std::min(lo[k], P[i][static_cast<std::size_t>(k)]); hi[k] = std::max(hi[k], P[i][static_cast<std::size_t>(k)]); }
  }
  if(n > r.non_finite_vertices + r.out_of_range_vertices)
    r.bbox_diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));

  std::vector<char> used(n, 0);
  // undirected edge -> (number of faces, sum of orientations +1/-1)
  std::map<std::pair<std::size_t, std::size_t>, std::pair<int, int>> edges;
  std::vector<std::vector<std::size_t>> F;
  F.reserve(polygons.size());
  double edge_sum = 0;
  std::size_t edge_count = 0;
  std::size_t fi = 0;
  for(const auto& poly : polygons) {
    std::vector<std::size_t> f;
    for(const auto& idx : poly) f.push_back(static_cast<std::size_t>(idx));
    const std::string where = "face " + std::to_string(fi);
    bool bad_index = false;
    for(std::size_t v : f) if(v >= n) bad_index = true;
    if(bad_index) {
      ++r.degenerate_faces;
      note(Mesh_defect::degenerate_face, where + " refers to a vertex past the end");
      F.emplace_back();
      ++fi;
      continue;
    }
    for(std::size_t v : f) used[v] = 1;
    if(f.size() != 3) {
      ++r.non_triangle_faces;
      note(Mesh_defect::non_triangle_face, where + " has " + std::to_string(f.size()) + " vertices");
    }
    std::vector<std::size_t> sorted = f;
    std::sort(sorted.begin(), sorted.end());
    const bool repeated = f.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    const bool unusable_corner = std::any_of(f.begin(), f.end(), [&](std::size_t v) { return unusable[v] != 0; });
    const double area = unusable_corner ? 0.0 : internal::polygon_area(points, f);
    if(unusable_corner) {
      // the corner is reported as non-finite or out of range; its area and edges would not be finite
    } else if(internal::is_degenerate_polygon(points, f, r.bbox_diagonal)) {
      if(std::isfinite(area) || repeated) {
        ++r.degenerate_faces;
        note(Mesh_defect::degenerate_face, where + (f.size() < 3 ? " has only " + std::to_string(f.size()) + " vertices" : repeated ? " repeats a vertex" : " has zero area"));
      }
    } else {
      r.area += area;
    }
    for(std::size_t k = 0; k < f.size(); ++k) {
      std::size_t a = f[k], b = f[(k + 1) % f.size()];
      if(a == b) continue;
      const double len = std::sqrt((P[a][0] - P[b][0]) * (P[a][0] - P[b][0]) + (P[a][1] - P[b][1]) * (P[a][1] - P[b][1]) +
                                   (P[a][2] - P[b][2]) * (P[a][2] - P[b][2]));
      if(!unusable[a] && !unusable[b] && std::isfinite(len)) { edge_sum += len; ++edge_count; }
      const int orient = a < b ? 1 : -1;
      auto& e = edges[std::make_pair(std::min(a, b), std::max(a, b))];
      e.first += 1;
      e.second += orient;
    }
    F.push_back(std::move(f));
    ++fi;
  }
  r.mean_edge_length = edge_count ? edge_sum / static_cast<double>(edge_count) : 0.0;
  for(const auto& e : edges) {
    if(e.second.first == 1) ++r.boundary_edges;
    else if(e.second.first > 2 || e.second.second != 0) {
      ++r.non_manifold_edges;
      note(Mesh_defect::non_manifold_edge, "edge (" + std::to_string(e.first.first) + ", " + std::to_string(e.first.second) + ") has " +
                                               std::to_string(e.second.first) + " faces" +
                                               (e.second.first == 2 ? " of inconsistent orientation" : ""));
    }
  }
  if(r.boundary_edges) note(Mesh_defect::boundary, std::to_string(r.boundary_edges) + " boundary edges");
  for(std::size_t v = 0; v < n; ++v)
    if(!used[v]) { ++r.isolated_vertices; note(Mesh_defect::isolated_vertex, "vertex " + std::to_string(v)); }

  // vertex fans: union the faces around each vertex that share an edge through it
  std::vector<std::vector<std::size_t>> star(n);
  for(std::size_t f = 0; f < F.size(); ++f)
    for(std::size_t v : F[f]) star[v].push_back(f);
  std::vector<std::size_t> parent(F.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; }
    return x;
  };
  std::map<std::size_t, std::size_t> local;
  for(std::size_t v = 0; v < n; ++v) {
    if(star[v].size() < 2) continue;
    // faces around v: link them through their other vertex on a shared edge
    std::map<std::size_t, std::vector<std::size_t>> by_neighbor;
    for(std::size_t f : star[v]) {
      const auto& fv = F[f];
      for(std::size_t k = 0; k < fv.size(); ++k)
        if(fv[k] == v) {
          by_neighbor[fv[(k + 1) % fv.size()]].push_back(f);
          by_neighbor[fv[(k + fv.size() - 1) % fv.size()]].push_back(f);
        }
    }
    local.clear();
    std::vector<std::size_t> lp(star[v].size());
    std::iota(lp.begin(), lp.end(), std::size_t(0));
    for(std::size_t i = 0; i < star[v].size(); ++i) local[star[v][i]] = i;
    auto lfind = [&](std::size_t x) { while(lp[x] != x) { lp[x] = lp[lp[x]]; x = lp[x]; } return x; };
    for(const auto& nb : by_neighbor) {
      if(nb.second.size() > 2) continue; // non-manifold edge: reported already, does not join fans
      for(std::size_t i = 1; i < nb.second.size(); ++i) {
        const std::size_t a = lfind(local[nb.second[0]]), b = lfind(local[nb.second[i]]);
        if(a != b) lp[a] = b;
      }
    }
    std::size_t fans = 0;
    for(std::size_t i = 0; i < lp.size(); ++i) if(lfind(i) == i) ++fans;
    if(fans > 1) {
      ++r.non_manifold_vertices;
      note(Mesh_defect::non_manifold_vertex, "vertex " + std::to_string(v) + " joins " + std::to_string(fans) + " fans of faces");
    }
    // global face components
    for(std::size_t i = 1; i < star[v].size(); ++i) {
      const std::size_t a = find(star[v][0]), b = find(star[v][i]);
      if(a != b) parent[a] = b;
    }
  }
  for(std::size_t f = 0; f < F.size(); ++f) if(!F[f].empty() && find(f) == f) ++r.connected_components;
  if(r.connected_components > 1) note(Mesh_defect::several_components, std::to_string(r.connected_components) + " components");
  if(r.is_empty()) note(Mesh_defect::empty_mesh, std::to_string(r.number_of_vertices) + " vertices, " + std::to_string(r.number_of_faces) + " faces");
  return r;
}

/// \ingroup PkgShapeCorrMesh
/// Checks a mesh (any `FaceListGraph`) for the defects of `validate_polygon_soup()`; non-manifold
/// vertices are those a halfedge structure can still hold (several fans around one vertex).
/// \param np `vertex_point_map`, `vertex_index_map`
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Mesh_report validate_mesh(const PolygonMesh& pm, const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), CGAL::get_const_property_map(CGAL::vertex_point, pm));
  auto vim = CGAL::get_initialized_vertex_index_map(pm, np);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  std::vector<Point> points(num_vertices(pm));
  for(auto v : vertices(pm)) points[static_cast<std::size_t>(get(vim, v))] = get(vpm, v);
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(num_faces(pm));
  for(auto f : faces(pm)) {
    polygons.emplace_back();
    for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm)) polygons.back().push_back(static_cast<std::size_t>(get(vim, v)));
  }
  return validate_polygon_soup(points, polygons);
}

/// \ingroup PkgShapeCorrMesh
/// Throws `Invalid_input` naming the first defect of `report` that `requirements` forbid, with
/// `context` (a file name, an algorithm) in front of the message. Checked in this order: empty,
/// non-finite, out-of-range coordinate, non-triangle, degenerate, non-manifold edge, non-manifold vertex, isolated vertex,
/// boundary (if `closed`), several components (if `connected`).
inline void require_valid(const Mesh_report& r, const Mesh_requirements& req = Mesh_requirements(),
                          const std::string& context = "mesh") {
  auto fail = [&](Mesh_defect d, std::size_t count, const char* what) {
    std::string ex;
    auto it = r.examples.find(d);
    if(it != r.examples.end()) ex = " (first: " + it->second + ")";
    throw Invalid_input(d, context + ": " + std::to_string(count) + " " + what + ex);
  };
  if(r.is_empty())
    throw Invalid_input(Mesh_defect::empty_mesh, context + ": empty mesh (" + std::to_string(r.number_of_vertices) +
                                                     " vertices, " + std::to_string(r.number_of_faces) + " faces)");
  if(r.non_finite_vertices) fail(Mesh_defect::non_finite_coordinate, r.non_finite_vertices, "vertices with NaN or infinite coordinates");
  if(r.out_of_range_vertices)
    fail(Mesh_defect::coordinate_out_of_range, r.out_of_range_vertices, "vertices with a coordinate beyond 1e38 in magnitude (rescale the mesh)");
  if(r.non_triangle_faces) fail(Mesh_defect::non_triangle_face, r.non_triangle_faces, "faces are not triangles");
  if(r.degenerate_faces) fail(Mesh_defect::degenerate_face, r.degenerate_faces, "degenerate faces");
  if(r.non_manifold_edges) fail(Mesh_defect::non_manifold_edge, r.non_manifold_edges, "non-manifold edges");
  if(r.non_manifold_vertices) fail(Mesh_defect::non_manifold_vertex, r.non_manifold_vertices, "non-manifold vertices");
  if(r.isolated_vertices) fail(Mesh_defect::isolated_vertex, r.isolated_vertices, "isolated vertices");
  if(req.closed && r.boundary_edges) fail(Mesh_defect::boundary, r.boundary_edges, "boundary edges (a closed surface is required)");
  if(req.connected && r.connected_components > 1)
    fail(Mesh_defect::several_components, r.connected_components, "connected components (one is required)");
}

} // namespace shapecorr

#endif
