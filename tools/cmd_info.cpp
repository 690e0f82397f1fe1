// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// shapecorr info: validation report of a mesh file.
#include "cli_common.h"

#include <shapecorr/io.h>
#include <shapecorr/mesh.h>

namespace cli {
namespace {

int run_info(const Args& a) {
  const std::string path = a.positional[0];
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  shapecorr::read_polygon_soup(path, points, polygons);
  const shapecorr::Mesh_report r = shapecorr::validate_polygon_soup(points, polygons);
  if(a.has("json")) {
    std::cout << "{\"file\": \"" << json_escape(path) << "\", \"vertices\": " << r.number_of_vertices
              << ", \"faces\": " << r.number_of_faces << ", \"connected_components\": " << r.connected_components
              << ", \"boundary_edges\": " << r.boundary_edges << ", \"non_triangle_faces\": " << r.non_triangle_faces
              << ", \"non_finite_vertices\": " << r.non_finite_vertices << ", \"out_of_range_vertices\": " << r.out_of_range_vertices
              << ", \"degenerate_faces\": " << r.degenerate_faces
              << ", \"non_manifold_edges\": " << r.non_manifold_edges << ", \"non_manifold_vertices\": " << r.non_manifold_vertices
              << ", \"isolated_vertices\": " << r.isolated_vertices << ", \"area\": " << r.area
              << ", \"mean_edge_length\": " << r.mean_edge_length << ", \"bbox_diagonal\": " << r.bbox_diagonal
              << ", \"valid\": " << (r.is_valid() ? "true" : "false") << ", \"closed\": " << (r.is_closed() ? "true" : "false")
              << ", \"examples\": {";
    bool first = true;
    for(const auto& e : r.examples) {
      std::cout << (first ? "" : ", ") << "\"" << shapecorr::to_string(e.first) << "\": \"" << json_escape(e.second) << "\"";
      first = false;
    }
    std::cout << "}}\n";
  } else {
    std::cout << "file: " << path << "\n" << r.to_string();
  }
  return 0;
}

} // namespace

const Command& info_command() {
  static const Command c{"info", "info MESH [--json]",
                         "Validate MESH (OFF, OBJ, PLY, STL): size, components, boundaries, degenerate and non-manifold "
                         "elements, isolated vertices, area, mean edge length. Exit 0 when the file could be read, "
                         "whatever it holds.",
                         {{"json", "", "one JSON object on stdout instead of text"}},
                         1, 1, run_info};
  return c;
}

} // namespace cli
