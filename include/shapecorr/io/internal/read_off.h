// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Strict reader of ASCII OFF (Princeton / Geomview): [ST][C][N]OFF header, counts, one vertex and
// one face per line, '#' comments.
#ifndef SHAPECORR_IO_INTERNAL_READ_OFF_H
#define SHAPECORR_IO_INTERNAL_READ_OFF_H

#include <shapecorr/io/internal/file_scanner.h>

namespace shapecorr {
namespace internal {

template <typename Point>
void read_off_soup(const std::string& path, std::string_view text, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t>>& polygons) {
  Line_scanner in(path, text);
  std::vector<std::string_view> tok;
  if(!in.next(tok)) in.fail("no OFF header (the file holds only blanks and comments)");
  // header keyword: [ST][C][N]OFF; the counts may follow on the same line
  std::string_view key = tok[0];
  std::size_t extra_min = 0, extra_max = 0; // values after x y z on a vertex line
  bool texture = false, color = false, normal = false;
  if(key.size() >= 2 && key.substr(0, 2) == "ST") { texture = true; key.remove_prefix(2); }
  if(!key.empty() && key[0] == 'C') { color = true; key.remove_prefix(1); }
  if(!key.empty() && key[0] == 'N') { normal = true; key.remove_prefix(1); }
  if(key != "OFF") {
    if(key == "4OFF" || key == "nOFF" || key == "4nOFF") in.fail("header " + quoted(tok[0]) + ": only 3-D OFF is read");
    in.fail("expected the OFF header, found " + quoted(tok[0]));
  }
  if(tok.size() >= 2 && tok[1] == "BINARY") in.fail("binary OFF is not read (write it as ASCII OFF, PLY or STL)");
  if(normal) { extra_min += 3; extra_max += 3; }
  if(color) { extra_min += 1; extra_max += 4; } // a colour map index, RGB or RGBA
  if(texture) { extra_min += 2; extra_max += 2; }
  std::vector<std::string_view> counts(tok.begin() + 1, tok.end());
  if(counts.empty()) {
    if(!in.next(tok)) in.fail("the header ends before the vertex and face counts");
    counts = tok;
  }
  if(counts.size() != 3) in.fail("expected 3 counts (vertices faces edges), found " + std::to_string(counts.size()) + " values");
  std::uint64_t nv = 0, nf = 0, ne = 0;
  const std::uint64_t big = std::numeric_limits<std::uint32_t>::max();
  for(int i = 0; i < 3; ++i) {
    const std::string why = parse_unsigned(counts[static_cast<std::size_t>(i)], big, i == 0 ? nv : i == 1 ? nf : ne);
    if(!why.empty()) in.fail(std::string(i == 0 ? "vertex" : i == 1 ? "face" : "edge") + " count is " + why);
  }
  // before allocating: a vertex line takes at least 6 bytes ("0 0 0\n"), a face line 2 ("0\n")
  const std::uint64_t room = in.remaining() + 1; // the last line may lack its newline
  if(nv > capacity(room, 6))
    in.fail("declares " + std::to_string(nv) + " vertices, but the " + std::to_string(in.remaining()) + " bytes after the header hold at most " +
            std::to_string(capacity(room, 6)));
  if(nf > capacity(room - 6 * nv, 2))
    in.fail("declares " + std::to_string(nf) + " faces, but the bytes after the header hold at most " + std::to_string(capacity(room - 6 * nv, 2)) +
            " besides " + std::to_string(nv) + " vertices");
  points.clear();
  polygons.clear();
  points.reserve(static_cast<std::size_t>(nv));
  polygons.reserve(static_cast<std::size_t>(nf));
  for(std::uint64_t i = 0; i < nv; ++i) {
    if(!in.next(tok)) in.fail("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if(tok.size() < 3 + extra_min || tok.size() > 3 + extra_max)
      in.fail("vertex " + std::to_string(i) + " has " + std::to_string(tok.size()) + " values, this OFF variant has " +
              std::to_string(3 + extra_min) + (extra_max > extra_min ? " to " + std::to_string(3 + extra_max) : std::string()) +
              (tok.size() > 3 && extra_max == 0 ? " (per-vertex colours or normals need a COFF or NOFF header)" : ""));
    double xyz[3];
    for(std::size_t k = 0; k < tok.size(); ++k) {
      double v;
      if(!parse_real(tok[k], v)) in.fail("vertex " + std::to_string(i) + ": not a number: " + quoted(tok[k]));
      if(k < 3) xyz[k] = v;
    }
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  for(std::uint64_t i = 0; i < nf; ++i) {
    if(!in.next(tok)) in.fail("the file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    std::uint64_t n = 0;
    std::string why = parse_unsigned(tok[0], big, n);
    if(!why.empty()) in.fail("face " + std::to_string(i) + ": its vertex count is " + why);
    if(tok.size() < 1 + n) in.fail("face " + std::to_string(i) + " declares " + std::to_string(n) + " vertices but lists " + std::to_string(tok.size() - 1));
    if(tok.size() > 1 + n + 4)
      in.fail("face " + std::to_string(i) + " has " + std::to_string(tok.size() - 1 - n) + " values after its " + std::to_string(n) +
              " vertices (at most a colour: 4)");
    std::vector<std::size_t> f(static_cast<std::size_t>(n));
    for(std::size_t k = 0; k < n; ++k) {
      std::uint64_t v = 0;
      why = parse_unsigned(tok[1 + k], std::numeric_limits<std::uint64_t>::max(), v);
      if(!why.empty()) in.fail("face " + std::to_string(i) + ": vertex index is " + why);
      if(v >= nv) in.fail("face " + std::to_string(i) + " refers to vertex " + std::to_string(v) + ", but there are " + std::to_string(nv) + " vertices");
      f[k] = static_cast<std::size_t>(v);
    }
    for(std::size_t k = 1 + n; k < tok.size(); ++k) {
      double c;
      if(!parse_real(tok[k], c)) in.fail("face " + std::to_string(i) + ": colour value is not a number: " + quoted(tok[k]));
    }
    polygons.push_back(std::move(f));
  }
  if(in.next(tok)) in.fail("data after the last of the " + std::to_string(nf) + " declared faces: " + quoted(tok[0]) + " (the counts disagree with the content)");
}

} // namespace internal
} // namespace shapecorr

#endif
