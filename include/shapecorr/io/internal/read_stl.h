// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Strict reader of STL, binary (80-byte header, count, 50 bytes per triangle) or ASCII
// (solid / facet normal / outer loop / 3 vertex / endloop / endfacet / endsolid). STL stores
// triangles, not shared vertices: corners with exactly equal coordinates are merged.
#ifndef SHAPECORR_IO_INTERNAL_READ_STL_H
#define SHAPECORR_IO_INTERNAL_READ_STL_H

#include <shapecorr/io/internal/file_scanner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numeric>

namespace shapecorr {
namespace internal {

/// Merges exactly equal corners (a corner with a NaN coordinate equals nothing) into vertices
/// numbered in the order of their first appearance.
template <typename Point>
void stl_corners_to_soup(const std::vector<std::array<double, 3>>& corners, std::vector<Point>& points,
                         std::vector<std::vector<std::size_t>>& polygons) {
  const std::size_t n = corners.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  auto has_nan = [&](std::size_t i) { return std::isnan(corners[i][0]) || std::isnan(corners[i][1]) || std::isnan(corners[i][2]); };
  // NaN corners last (each its own vertex); the rest by coordinates, ties by position
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const bool na = has_nan(a), nb = has_nan(b);
    if(na != nb) return nb;
    if(!na && corners[a] != corners[b]) return corners[a] < corners[b];
    return a < b;
  });
  std::vector<std::size_t> representative(n); // the first corner of each class of equal corners
  for(std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    representative[i] = k > 0 && !has_nan(i) && !has_nan(order[k - 1]) && corners[order[k - 1]] == corners[i] ? representative[order[k - 1]] : i;
  }
  std::vector<std::size_t> id(n, std::size_t(-1));
  points.clear();
  polygons.clear();
  polygons.reserve(n / 3);
  for(std::size_t i = 0; i < n; ++i) {
    std::size_t& v = id[representative[i]];
    if(v == std::size_t(-1)) { v = points.size(); points.emplace_back(corners[i][0], corners[i][1], corners[i][2]); }
    if(i % 3 == 0) polygons.emplace_back();
    polygons.back().push_back(v);
  }
}

template <typename Point>
void read_stl_soup(const std::string& path, std::string_view text, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::array<double, 3>> corners;
  std::uint32_t count = 0;
  if(text.size() >= 84) {
    const unsigned char* c = reinterpret_cast<const unsigned char*>(text.data()) + 80;
    count = std::uint32_t(c[0]) | std::uint32_t(c[1]) << 8 | std::uint32_t(c[2]) << 16 | std::uint32_t(c[3]) << 24;
  }
  const bool binary = text.size() >= 84 && 84 + 50 * std::uint64_t(count) == text.size();
  // a binary STL's 80-byte header may start with "solid" too: binary bytes in the file tell
  const bool solid = text.size() >= 5 && text.substr(0, 5) == "solid" &&
                     std::none_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 9; });
  if(binary) {
    corners.reserve(3 * std::size_t(count));
    for(std::uint32_t t = 0; t < count; ++t) {
      const unsigned char* p = reinterpret_cast<const unsigned char*>(text.data()) + 84 + 50 * std::size_t(t) + 12; // past the normal
      for(int k = 0; k < 3; ++k) {
        std::array<double, 3> x;
        for(int d = 0; d < 3; ++d) {
          const unsigned char* q = p + 12 * k + 4 * d;
          const std::uint32_t bits = std::uint32_t(q[0]) | std::uint32_t(q[1]) << 8 | std::uint32_t(q[2]) << 16 | std::uint32_t(q[3]) << 24;
          float f;
          std::memcpy(&f, &bits, 4);
          x[static_cast<std::size_t>(d)] = f;
        }
        corners.push_back(x);
      }
    }
  } else if(solid) {
    Line_scanner in(path, text, 1, 0);
    std::vector<std::string_view> tok;
    enum State { outside, in_solid, in_facet, in_loop, after_loop } state = outside;
    int vertices = 0;
    std::size_t facets = 0;
    auto expect = [&](bool ok, const char* what) {
      if(!ok) in.fail(std::string("expected ") + what + ", found " + quoted(tok[0]) + " (ASCII STL)");
    };
    while(in.next(tok)) {
      const std::string_view k = tok[0];
      switch(state) {
      case outside:
        expect(k == "solid", "'solid'");
        state = in_solid;
        break;
      case in_solid:
        if(k == "endsolid") { state = outside; break; }
        expect(k == "facet" && tok.size() == 5 && tok[1] == "normal", "'facet normal nx ny nz' or 'endsolid'");
        for(std::size_t i = 2; i < 5; ++i) {
          double v;
          if(!parse_real(tok[i], v)) in.fail("facet normal: not a number: " + quoted(tok[i]));
        }
        state = in_facet;
        break;
      case in_facet:
        expect(k == "outer" && tok.size() == 2 && tok[1] == "loop", "'outer loop'");
        state = in_loop;
        vertices = 0;
        break;
      case in_loop:
        if(k == "endloop") {
          if(vertices != 3) in.fail("facet " + std::to_string(facets) + " has " + std::to_string(vertices) + " vertices (STL facets are triangles)");
          state = after_loop;
          break;
        }
        expect(k == "vertex" && tok.size() == 4, "'vertex x y z' or 'endloop'");
        if(++vertices > 3) in.fail("facet " + std::to_string(facets) + " has more than 3 vertices (STL facets are triangles)");
        {
          std::array<double, 3> x;
          for(std::size_t i = 0; i < 3; ++i)
            if(!parse_real(tok[1 + i], x[i])) in.fail("facet " + std::to_string(facets) + ": not a number: " + quoted(tok[1 + i]));
          corners.push_back(x);
        }
        break;
      case after_loop:
        expect(k == "endfacet", "'endfacet'");
        ++facets;
        state = in_solid;
        break;
      }
    }
    if(state != outside) in.fail("the file ends inside a solid (no 'endsolid'; truncated?)");
  } else if(text.size() >= 84) {
    malformed(path, "", "not ASCII STL and not binary STL: the header declares " + std::to_string(count) + " triangles, which take " +
                            std::to_string(84 + 50 * std::uint64_t(count)) + " bytes, but the file has " + std::to_string(text.size()));
  } else {
    malformed(path, "", "not STL: " + std::to_string(text.size()) + " bytes, shorter than a binary STL header (84) and not starting with 'solid'");
  }
  stl_corners_to_soup(corners, points, polygons);
}

} // namespace internal
} // namespace shapecorr

#endif
