// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Strict reader of PLY (ascii, binary_little_endian, binary_big_endian 1.0): the `vertex` element's
// x, y, z and the `face` element's vertex_indices (or vertex_index) list; other elements and
// properties are read over and dropped.
#ifndef SHAPECORR_IO_INTERNAL_READ_PLY_H
#define SHAPECORR_IO_INTERNAL_READ_PLY_H

#include <shapecorr/io/internal/file_scanner.h>

#include <algorithm>
#include <cstring>

namespace shapecorr {
namespace internal {

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline bool ply_type_from_name(std::string_view n, Ply_type& t) {
  struct Entry { const char* a; const char* b; Ply_type t; };
  static const Entry names[] = {{"char", "int8", Ply_type::int8},       {"uchar", "uint8", Ply_type::uint8},
                                {"short", "int16", Ply_type::int16},    {"ushort", "uint16", Ply_type::uint16},
                                {"int", "int32", Ply_type::int32},      {"uint", "uint32", Ply_type::uint32},
                                {"float", "float32", Ply_type::float32}, {"double", "float64", Ply_type::float64}};
  for(const Entry& e : names)
    if(n == e.a || n == e.b) { t = e.t; return true; }
  return false;
}
inline std::size_t ply_size(Ply_type t) {
  switch(t) {
  case Ply_type::int8: case Ply_type::uint8: return 1;
  case Ply_type::int16: case Ply_type::uint16: return 2;
  case Ply_type::float64: return 8;
  default: return 4;
  }
}
inline bool ply_is_integer(Ply_type t) { return t != Ply_type::float32 && t != Ply_type::float64; }
inline bool ply_is_signed(Ply_type t) { return t == Ply_type::int8 || t == Ply_type::int16 || t == Ply_type::int32; }
inline std::int64_t ply_min(Ply_type t) {
  return t == Ply_type::int8 ? -128 : t == Ply_type::int16 ? -32768 : t == Ply_type::int32 ? std::int64_t(INT32_MIN) : 0;
}
inline std::int64_t ply_max(Ply_type t) {
  switch(t) {
  case Ply_type::int8: return 127;
  case Ply_type::uint8: return 255;
  case Ply_type::int16: return 32767;
  case Ply_type::uint16: return 65535;
  case Ply_type::int32: return INT32_MAX;
  default: return UINT32_MAX;
  }
}

struct Ply_property {
  std::string name;
  Ply_type type = Ply_type::float32;   // of a scalar, or of a list's items
  bool list = false;
  Ply_type count_type = Ply_type::uint8;
};
struct Ply_element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
  std::size_t header_line = 0;
};

/// Reads one binary value of type `t` at `p` (the caller checked the bytes are there).
inline double ply_binary_value(const unsigned char* p, Ply_type t, bool swap) {
  unsigned char b[8];
  const std::size_t n = ply_size(t);
  for(std::size_t i = 0; i < n; ++i) b[i] = swap ? p[n - 1 - i] : p[i];
  switch(t) {
  case Ply_type::int8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
  case Ply_type::uint8: return b[0];
  case Ply_type::int16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
  case Ply_type::uint16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
  case Ply_type::int32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
  case Ply_type::uint32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
  case Ply_type::float32: { float v; std::memcpy(&v, b, 4); return v; }
  default: { double v; std::memcpy(&v, b, 8); return v; }
  }
}

/// An ASCII value of type `t`: integers range-checked against the type, reals as `parse_real`.
/// Returns "" or why not.
inline std::string ply_ascii_value(std::string_view tok, Ply_type t, double& value) {
  if(!ply_is_integer(t)) return parse_real(tok, value) ? "" : "not a number: " + quoted(tok);
  std::string_view body = tok;
  if(!body.empty() && body[0] == '+') body.remove_prefix(1);
  std::int64_t v = 0;
  const auto r = std::from_chars(body.data(), body.data() + body.size(), v, 10);
  if(r.ec == std::errc() && r.ptr == body.data() + body.size()) {
    if(v < ply_min(t) || v > ply_max(t))
      return "value " + quoted(tok) + " outside the range of its type [" + std::to_string(ply_min(t)) + ", " + std::to_string(ply_max(t)) + "]";
    value = static_cast<double>(v);
    return "";
  }
  if(r.ec == std::errc::result_out_of_range) return "value " + quoted(tok) + " outside the range of its integer type";
  double d;
  return parse_real(tok, d) ? "not an integer: " + quoted(tok) + " (the property is an integer type)" : "not a number: " + quoted(tok);
}

template <typename Point>
void read_ply_soup(const std::string& path, std::string_view text, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t>>& polygons) {
  // ---- header: up to and including the line "end_header"
  std::size_t body_start = std::string_view::npos;
  {
    std::size_t p = 0;
    while(p < text.size()) {
      std::size_t e = p;
      while(e < text.size() && text[e] != '\n' && text[e] != '\r') ++e;
      std::string_view line = text.substr(p, e - p);
      while(!line.empty() && is_blank(line.back())) line.remove_suffix(1);
      std::size_t next = e;
      if(next < text.size()) next += text[next] == '\r' && next + 1 < text.size() && text[next + 1] == '\n' ? 2 : 1;
      if(line == "end_header") { body_start = next; break; }
      p = next;
    }
  }
  if(body_start == std::string_view::npos) malformed(path, "", "PLY header without an 'end_header' line (truncated, or not PLY)");
  Line_scanner hs(path, text.substr(0, body_start), 1, 0);
  std::vector<std::string_view> tok;
  if(!hs.next(tok) || tok.size() != 1 || tok[0] != "ply") hs.fail("a PLY file starts with the line 'ply'");
  int format = -1; // 0 ascii, 1 little endian, 2 big endian
  std::vector<Ply_element> elements;
  while(hs.next(tok)) {
    const std::string_view key = tok[0];
    if(key == "comment" || key == "obj_info") continue;
    if(key == "end_header") break;
    if(key == "format") {
      if(format >= 0) hs.fail("a second 'format' line");
      if(tok.size() != 3) hs.fail("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      if(tok[1] == "ascii") format = 0;
      else if(tok[1] == "binary_little_endian") format = 1;
      else if(tok[1] == "binary_big_endian") format = 2;
      else hs.fail("unknown PLY format " + quoted(tok[1]));
      if(tok[2] != "1.0" && tok[2] != "1") hs.fail("PLY version " + quoted(tok[2]) + " (1.0 is read)");
    } else if(key == "element") {
      if(tok.size() != 3) hs.fail("expected 'element <name> <count>'");
      Ply_element e;
      e.name = std::string(tok[1]);
      e.header_line = hs.line();
      const std::string why = parse_unsigned(tok[2], std::numeric_limits<std::uint64_t>::max(), e.count);
      if(!why.empty()) hs.fail("element '" + e.name + "' count is " + why);
      for(const Ply_element& o : elements)
        if(o.name == e.name) hs.fail("element '" + e.name + "' declared twice");
      elements.push_back(e);
    } else if(key == "property") {
      if(elements.empty()) hs.fail("a property before any element");
      Ply_property p;
      if(tok.size() >= 2 && tok[1] == "list") {
        if(tok.size() != 5) hs.fail("expected 'property list <count type> <item type> <name>'");
        if(!ply_type_from_name(tok[2], p.count_type)) hs.fail("unknown PLY type " + quoted(tok[2]));
        if(!ply_is_integer(p.count_type)) hs.fail("a list count of type " + quoted(tok[2]) + " (it must be an integer type)");
        if(!ply_type_from_name(tok[3], p.type)) hs.fail("unknown PLY type " + quoted(tok[3]));
        p.list = true;
        p.name = std::string(tok[4]);
      } else {
        if(tok.size() != 3) hs.fail("expected 'property <type> <name>'");
        if(!ply_type_from_name(tok[1], p.type)) hs.fail("unknown PLY type " + quoted(tok[1]));
        p.name = std::string(tok[2]);
      }
      for(const Ply_property& o : elements.back().properties)
        if(o.name == p.name) hs.fail("property '" + p.name + "' declared twice");
      elements.back().properties.push_back(p);
    } else {
      hs.fail("unknown PLY header keyword " + quoted(key));
    }
  }
  if(format < 0) malformed(path, "header", "no 'format' line");

  // which element and properties carry the geometry
  std::uint64_t nv = 0, nf = 0;
  int vx[3] = {-1, -1, -1};
  int fi = -1;
  for(const Ply_element& e : elements) {
    if(e.count > 0 && e.properties.empty())
      malformed(path, line_place(e.header_line), "element '" + e.name + "' has " + std::to_string(e.count) + " entries but no properties");
    if(e.name == "vertex") {
      nv = e.count;
      for(std::size_t k = 0; k < e.properties.size(); ++k)
        for(int c = 0; c < 3; ++c)
          if(e.properties[k].name == std::string(1, char('x' + c))) {
            if(e.properties[k].list) malformed(path, line_place(e.header_line), "vertex property '" + e.properties[k].name + "' is a list");
            vx[c] = static_cast<int>(k);
          }
      for(int c = 0; c < 3; ++c)
        if(vx[c] < 0) malformed(path, line_place(e.header_line), std::string("the vertex element has no '") + char('x' + c) + "' property");
    } else if(e.name == "face") {
      nf = e.count;
      for(std::size_t k = 0; k < e.properties.size(); ++k)
        if(e.properties[k].name == "vertex_indices" || e.properties[k].name == "vertex_index") {
          if(!e.properties[k].list) malformed(path, line_place(e.header_line), "face property '" + e.properties[k].name + "' is not a list");
          if(!ply_is_integer(e.properties[k].type)) malformed(path, line_place(e.header_line), "face vertex indices of a floating-point type");
          fi = static_cast<int>(k);
        }
      if(fi < 0 && nf > 0) malformed(path, line_place(e.header_line), "the face element has no 'vertex_indices' list");
    }
  }
  if(nv == 0 && std::none_of(elements.begin(), elements.end(), [](const Ply_element& e) { return e.name == "vertex"; }))
    malformed(path, "header", "no 'vertex' element");

  // ---- before allocating: the declared entries must fit in the bytes after the header
  const std::uint64_t body = text.size() - body_start;
  {
    std::uint64_t left = body + 1; // the last ASCII line may lack its newline
    for(const Ply_element& e : elements) {
      std::uint64_t min_bytes = 0;
      for(const Ply_property& p : e.properties) min_bytes += format == 0 ? 2 : ply_size(p.list ? p.count_type : p.type);
      if(e.count > capacity(left, min_bytes))
        malformed(path, line_place(e.header_line), "declares " + std::to_string(e.count) + " " + e.name + " entries, but the " + std::to_string(body) +
                                                      " bytes after the header hold at most " + std::to_string(capacity(left, min_bytes)) +
                                                      (&e == &elements.front() ? "" : " besides the elements before it"));
      left -= e.count * min_bytes;
    }
  }
  points.clear();
  polygons.clear();
  points.reserve(static_cast<std::size_t>(nv));
  polygons.reserve(static_cast<std::size_t>(nf));
  std::vector<double> values; // one entry's scalar values, and the face list

  auto add_face = [&](const std::vector<double>& ids, std::uint64_t face, const std::string& where) {
    std::vector<std::size_t> f(ids.size());
    for(std::size_t k = 0; k < ids.size(); ++k) {
      if(ids[k] < 0 || ids[k] >= static_cast<double>(nv))
        malformed(path, where, "face " + std::to_string(face) + " refers to vertex " + std::to_string(static_cast<long long>(ids[k])) +
                                   (ids[k] < 0 ? " (negative)" : "") + ", but there are " + std::to_string(nv) + " vertices");
      f[k] = static_cast<std::size_t>(ids[k]);
    }
    polygons.push_back(std::move(f));
  };

  if(format == 0) {
    Line_scanner in(path, text.substr(body_start), hs.line() + 1, 0);
    for(const Ply_element& e : elements) {
      const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
      for(std::uint64_t i = 0; i < e.count; ++i) {
        if(!in.next(tok)) in.fail("the file ends after " + std::to_string(i) + " of " + std::to_string(e.count) + " " + e.name + " entries");
        std::size_t t = 0;
        double xyz[3] = {0, 0, 0};
        for(std::size_t k = 0; k < e.properties.size(); ++k) {
          const Ply_property& p = e.properties[k];
          const std::string what = e.name + " " + std::to_string(i) + ", property '" + p.name + "': ";
          if(t >= tok.size()) in.fail(what + "missing (the line has " + std::to_string(tok.size()) + " values; one entry per line)");
          double v = 0;
          std::string why = ply_ascii_value(tok[t++], p.list ? p.count_type : p.type, v);
          if(!why.empty()) in.fail(what + why);
          if(!p.list) {
            if(is_vertex)
              for(int c = 0; c < 3; ++c) if(vx[c] == static_cast<int>(k)) xyz[c] = v;
            continue;
          }
          if(v < 0) in.fail(what + "negative list length");
          const std::uint64_t n = static_cast<std::uint64_t>(v);
          if(n > tok.size() - t) in.fail(what + "a list of " + std::to_string(n) + " items, but the line holds " + std::to_string(tok.size() - t) + " more values");
          const bool indices = is_face && static_cast<int>(k) == fi;
          values.clear();
          for(std::uint64_t j = 0; j < n; ++j) {
            why = ply_ascii_value(tok[t++], p.type, v);
            if(!why.empty()) in.fail(what + "item " + std::to_string(j) + ": " + why);
            if(indices) values.push_back(v);
          }
          if(indices) add_face(values, i, line_place(in.line()));
        }
        if(t != tok.size())
          in.fail(e.name + " " + std::to_string(i) + ": " + std::to_string(tok.size() - t) + " values more than its properties declare (one entry per line)");
        if(is_vertex) points.emplace_back(xyz[0], xyz[1], xyz[2]);
      }
    }
    if(in.next(tok)) in.fail("data after the last declared element: " + quoted(tok[0]));
  } else {
    const std::uint16_t probe = 1;
    unsigned char first_byte;
    std::memcpy(&first_byte, &probe, 1);
    const bool host_little_endian = first_byte == 1;
    const bool swap = (format == 1) != host_little_endian;
    const unsigned char* data = reinterpret_cast<const unsigned char*>(text.data());
    std::size_t pos = body_start;
    auto need = [&](std::uint64_t bytes, const std::string& what) {
      if(bytes > text.size() - pos)
        malformed(path, byte_place(pos), what + ": the file ends " + std::to_string(text.size() - pos) + " bytes short of the " + std::to_string(bytes) + " needed");
    };
    for(const Ply_element& e : elements) {
      const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
      for(std::uint64_t i = 0; i < e.count; ++i) {
        double xyz[3] = {0, 0, 0};
        for(std::size_t k = 0; k < e.properties.size(); ++k) {
          const Ply_property& p = e.properties[k];
          const std::string what = is_vertex || is_face ? e.name + " " + std::to_string(i) + ", property '" + p.name + "'" : std::string();
          const Ply_type t = p.list ? p.count_type : p.type;
          need(ply_size(t), what.empty() ? e.name + " " + std::to_string(i) : what);
          const double v = ply_binary_value(data + pos, t, swap);
          const std::size_t value_pos = pos;
          pos += ply_size(t);
          if(!p.list) {
            if(is_vertex)
              for(int c = 0; c < 3; ++c) if(vx[c] == static_cast<int>(k)) xyz[c] = v;
            continue;
          }
          if(v < 0) malformed(path, byte_place(value_pos), e.name + " " + std::to_string(i) + ": negative list length " + std::to_string(static_cast<long long>(v)));
          const std::uint64_t n = static_cast<std::uint64_t>(v);
          const std::uint64_t isz = ply_size(p.type);
          if(n > (text.size() - pos) / isz)
            malformed(path, byte_place(value_pos), e.name + " " + std::to_string(i) + ": a list of " + std::to_string(n) + " items does not fit in the " +
                                                      std::to_string(text.size() - pos) + " bytes left");
          if(is_face && static_cast<int>(k) == fi) {
            values.resize(static_cast<std::size_t>(n));
            for(std::uint64_t j = 0; j < n; ++j) values[j] = ply_binary_value(data + pos + j * isz, p.type, swap);
            add_face(values, i, byte_place(pos));
          }
          pos += static_cast<std::size_t>(n * isz);
        }
        if(is_vertex) points.emplace_back(xyz[0], xyz[1], xyz[2]);
      }
    }
    if(pos != text.size())
      malformed(path, byte_place(pos), std::to_string(text.size() - pos) + " bytes after the last declared element (the counts disagree with the content)");
  }
}

} // namespace internal
} // namespace shapecorr

#endif
