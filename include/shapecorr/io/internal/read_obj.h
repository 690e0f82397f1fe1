// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Strict reader of Wavefront OBJ geometry: `v` and `f` statements (indices 1-based or negative,
// i.e. relative, with optional /texture/normal parts); the other statements of the format are
// skipped, anything else is an error.
#ifndef SHAPECORR_IO_INTERNAL_READ_OBJ_H
#define SHAPECORR_IO_INTERNAL_READ_OBJ_H

#include <shapecorr/io/internal/file_scanner.h>

#include <algorithm>

namespace shapecorr {
namespace internal {

inline bool is_skipped_obj_statement(std::string_view key) {
  static const char* skipped[] = {"vt", "vn", "vp", "l", "p", "g", "o", "s", "mg", "usemtl", "mtllib", "usemap", "maplib", "cstype",
                                  "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end",
                                  "con", "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh"};
  return std::any_of(std::begin(skipped), std::end(skipped), [&](const char* s) { return key == s; });
}

template <typename Point>
void read_obj_soup(const std::string& path, std::string_view text, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t>>& polygons) {
  Line_scanner in(path, text);
  std::vector<std::string_view> tok;
  points.clear();
  polygons.clear();
  // positive indices may refer to vertices defined later: checked at the end, first offender named
  std::uint64_t max_index = 0;
  std::size_t max_index_line = 0;
  while(in.next(tok)) {
    const std::string_view key = tok[0];
    if(key == "v") {
      if(tok.size() != 4 && tok.size() != 5 && tok.size() != 7 && tok.size() != 8)
        in.fail("a vertex has 3 coordinates (and an optional w, or r g b colours), found " + std::to_string(tok.size() - 1) + " values");
      double xyz[3];
      for(std::size_t k = 1; k < tok.size(); ++k) {
        double v;
        if(!parse_real(tok[k], v)) in.fail("vertex " + std::to_string(points.size() + 1) + ": not a number: " + quoted(tok[k]));
        if(k <= 3) xyz[k - 1] = v;
      }
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if(key == "f") {
      std::vector<std::size_t> f;
      f.reserve(tok.size() - 1);
      for(std::size_t k = 1; k < tok.size(); ++k) {
        std::string_view t = tok[k].substr(0, tok[k].find('/'));
        const bool relative = !t.empty() && t[0] == '-';
        if(relative) t.remove_prefix(1);
        std::uint64_t v = 0;
        const std::string why = parse_unsigned(t, std::numeric_limits<std::uint64_t>::max() / 2, v);
        if(!why.empty()) in.fail("face " + std::to_string(polygons.size()) + ": vertex index " + quoted(tok[k]) + " is " + why);
        if(v == 0) in.fail("face " + std::to_string(polygons.size()) + ": vertex index 0 (OBJ indices start at 1, or are negative)");
        if(relative) {
          if(v > points.size())
            in.fail("face " + std::to_string(polygons.size()) + ": relative index -" + std::to_string(v) + " reaches before the first vertex (" +
                    std::to_string(points.size()) + " vertices so far)");
          f.push_back(points.size() - static_cast<std::size_t>(v));
        } else {
          if(v > max_index) { max_index = v; max_index_line = in.line(); }
          f.push_back(static_cast<std::size_t>(v - 1));
        }
      }
      polygons.push_back(std::move(f));
    } else if(!is_skipped_obj_statement(key)) {
      in.fail("unknown OBJ statement " + quoted(key));
    }
  }
  if(max_index > points.size())
    malformed(path, line_place(max_index_line), "a face refers to vertex " + std::to_string(max_index) + ", but the file has " + std::to_string(points.size()) + " vertices");
}

} // namespace internal
} // namespace shapecorr

#endif
