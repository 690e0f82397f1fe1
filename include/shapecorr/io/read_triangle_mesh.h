// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_triangle_mesh.h
#ifndef SHAPECORR_IO_READ_TRIANGLE_MESH_H
#define SHAPECORR_IO_READ_TRIANGLE_MESH_H

#include <shapecorr/exceptions.h>
#include <shapecorr/io/read_polygon_soup.h>
#include <shapecorr/mesh/validate_mesh.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrIO
/// The documented repairs `read_triangle_mesh()` may apply. Each repair that fires is listed in
/// `Read_result::repairs`.
struct Read_options {
  bool triangulate = true;              ///< split non-triangle faces (CGAL PMP `triangulate_faces`)
  bool remove_isolated_vertices = true; ///< drop vertices used by no face (indices are compacted)
  bool remove_degenerate_faces = false; ///< drop faces with a repeated vertex or zero area
  bool repair_non_manifold = false;     ///< duplicate non-manifold vertices/edges and reorient (PMP `orient_polygon_soup`)
  Mesh_requirements requirements;       ///< what the caller needs beyond a valid triangle mesh
};

/// \ingroup PkgShapeCorrIO
/// What `read_triangle_mesh` found in the file and what it repaired.
struct Read_result {
  Mesh_report report;                ///< validation of the file's content as read, before repairs
  std::vector<std::string> repairs;  ///< the repairs applied, in words
};

/// \ingroup PkgShapeCorrIO
/// Reads OFF, OBJ, PLY or STL (the strict readers of `read_polygon_soup()`), validates the content, applies the
/// repairs `options` allow, and builds `tm`. Anything left wrong raises `Invalid_input` whose
/// message names the file, the defect and its first place. Vertex order of the file is kept
/// (except where `remove_isolated_vertices` compacts it).
/// \tparam TriangleMesh a model of `MutableFaceGraph` (`CGAL::Surface_mesh`, `CGAL::Polyhedron_3`...)
/// \throws Invalid_input (`unreadable_file`, `empty_mesh`, `non_finite_coordinate`, ...)
template <typename TriangleMesh>
Read_result read_triangle_mesh(const std::string& path, TriangleMesh& tm, const Read_options& options = Read_options()) {
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;
  Read_result result;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  shapecorr::read_polygon_soup(path, points, polygons);
  result.report = validate_polygon_soup(points, polygons);
  const Mesh_report& r = result.report;
  const std::string ctx = path;
  if(r.is_empty() || r.non_finite_vertices || r.out_of_range_vertices) require_valid(r, Mesh_requirements(), ctx);

  if(options.remove_degenerate_faces && r.degenerate_faces) {
    std::vector<std::vector<std::size_t>> kept;
    for(auto& f : polygons)
      if(!internal::is_degenerate_polygon(points, f, r.bbox_diagonal)) kept.push_back(f);
    result.repairs.push_back("removed " + std::to_string(polygons.size() - kept.size()) + " degenerate faces");
    polygons.swap(kept);
  }
  if(options.remove_isolated_vertices) {
    std::vector<char> used(points.size(), 0);
    for(const auto& f : polygons) for(std::size_t v : f) used[v] = 1; // indices are below points.size(): validated
    std::vector<std::size_t> remap(points.size(), std::size_t(-1));
    std::vector<Point> kept;
    for(std::size_t i = 0; i < points.size(); ++i) if(used[i]) { remap[i] = kept.size(); kept.push_back(points[i]); }
    if(kept.size() != points.size()) {
      result.repairs.push_back("removed " + std::to_string(points.size() - kept.size()) + " isolated vertices");
      for(auto& f : polygons)
        for(auto& v : f) v = remap[v];
      points.swap(kept);
    }
  }
  if(options.repair_non_manifold && (r.non_manifold_edges || r.non_manifold_vertices)) {
    const std::size_t before = points.size();
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
    result.repairs.push_back("split non-manifold edges/vertices (" + std::to_string(points.size() - before) + " vertices duplicated)");
  }
  // what the repairs left (polygons are triangulated later, once they form a mesh)
  Mesh_report check = validate_polygon_soup(points, polygons);
  if(options.triangulate) check.non_triangle_faces = 0;
  require_valid(check, Mesh_requirements(), ctx);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw Invalid_input(Mesh_defect::non_manifold_edge, path + ": the faces do not form an oriented manifold surface");
  CGAL::clear(tm);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, tm);
  if(options.triangulate && check.number_of_faces && r.non_triangle_faces) {
    CGAL::Polygon_mesh_processing::triangulate_faces(tm);
    result.repairs.push_back("triangulated " + std::to_string(r.non_triangle_faces) + " non-triangle faces");
  }
  // requirements on the final surface (boundaries, components)
  const Mesh_report final_report = validate_mesh(tm);
  require_valid(final_report, options.requirements, ctx);
  return result;
}

} // namespace shapecorr

#endif
