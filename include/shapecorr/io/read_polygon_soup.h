// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file read_polygon_soup.h
#ifndef SHAPECORR_IO_READ_POLYGON_SOUP_H
#define SHAPECORR_IO_READ_POLYGON_SOUP_H

#include <shapecorr/exceptions.h>
#include <shapecorr/io/internal/file_scanner.h>
#include <shapecorr/io/internal/read_obj.h>
#include <shapecorr/io/internal/read_off.h>
#include <shapecorr/io/internal/read_ply.h>
#include <shapecorr/io/internal/read_stl.h>

#include <cctype>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrIO
/// Reads the vertices and faces of an OFF, OBJ, PLY or STL file, chosen by the extension
/// (`.off`, `.obj`, `.ply`, `.stl`, any case). The readers are strict: a file is either read
/// exactly as it declares itself or rejected.
///
/// - **OFF**: ASCII `[ST][C][N]OFF`, counts, one vertex and one face per line, `#` comments.
/// - **OBJ**: `v` and `f` statements (1-based or negative indices, `v/vt/vn` corners); the other
///   OBJ statements are skipped, an unknown one is an error.
/// - **PLY**: `ascii`, `binary_little_endian`, `binary_big_endian` 1.0; `vertex` x, y, z (any scalar
///   type) and `face` `vertex_indices` (an integer list); other elements and properties are read
///   over. ASCII PLY holds one element entry per line.
/// - **STL**: binary when the file size is exactly 84 + 50 × the declared triangle count, else
///   ASCII (`solid` ... `endsolid`); corners with exactly equal coordinates become one vertex.
///
/// Guarantees: counts and indices are parsed as integers and range-checked (no sign, fraction or
/// wrap-around); every face index is below the number of vertices; declared counts are checked
/// against the bytes that remain before anything is allocated; missing and trailing data are
/// errors. Coordinates `nan`/`inf` (and decimal numbers past the double range, which become ±inf)
/// are read as such and left to `validate_polygon_soup()` to report.
///
/// Memory: the file is held in memory while it is read; the output takes at most about 25 times
/// the file size (a 3-byte binary PLY vertex becomes a 24-byte point), so a file of S bytes
/// needs at most about 26·S bytes at the peak, whatever its header declares.
///
/// \throws Invalid_input with defect `unreadable_file` and a message "PATH: WHERE: WHAT" where
///   WHERE is a line (text) or byte offset (binary) when there is one.
///
/// \code
/// std::vector<Kernel::Point_3> points;
/// std::vector<std::vector<std::size_t>> faces;
/// shapecorr::read_polygon_soup("bunny.ply", points, faces);
/// const shapecorr::Mesh_report report = shapecorr::validate_polygon_soup(points, faces);
/// \endcode
template <typename Point>
void read_polygon_soup(const std::string& path, std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons) {
  std::string ext;
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if(dot != std::string::npos && (slash == std::string::npos || dot > slash))
    for(char c : path.substr(dot + 1)) ext += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    internal::malformed(path, "", "unknown mesh file extension " + (ext.empty() ? std::string("(none)") : "'." + ext + "'") +
                                      "; OFF, OBJ, PLY and STL are read");
  const std::string bytes = internal::read_file_bytes(path);
  points.clear();
  polygons.clear();
  if(ext == "off") internal::read_off_soup(path, bytes, points, polygons);
  else if(ext == "obj") internal::read_obj_soup(path, bytes, points, polygons);
  else if(ext == "ply") internal::read_ply_soup(path, bytes, points, polygons);
  else internal::read_stl_soup(path, bytes, points, polygons);
}

} // namespace shapecorr

#endif
