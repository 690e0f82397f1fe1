// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line program's shared pieces: values from arguments, mesh reading, value output.
#ifndef SHAPECORR_TOOLS_CLI_COMMON_H
#define SHAPECORR_TOOLS_CLI_COMMON_H

#include "command.h"

#include <shapecorr/exceptions.h>
#include <shapecorr/io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <charconv>
#include <cmath>
#include <cctype>
#include <limits>
#include <sstream>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cli {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

// An integer option value in [lo, hi]: digits only (no sign, point, exponent or spaces); the
// usage error names the option and the range.
inline std::size_t to_count(const std::string& s, const std::string& what, std::size_t lo, std::size_t hi) {
  const std::string range = " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + s + "'";
  unsigned long long v = 0;
  const char* end = s.data() + s.size();
  const auto r = std::from_chars(s.data(), end, v, 10);
  if(s.empty() || r.ptr != end || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range)) throw Usage_error(what + range);
  if(r.ec == std::errc::result_out_of_range || v < lo || v > hi) throw Usage_error(what + range);
  return static_cast<std::size_t>(v);
}

// A real option value, finite, in [lo, hi] (in (lo, hi] when `above_lo`); the usage error names
// the option and the range.
inline double to_double(const std::string& s, const std::string& what, double lo, double hi, bool above_lo = false) {
  char* end = nullptr;
  const double v = s.empty() || std::isspace(static_cast<unsigned char>(s[0])) ? std::nan("") : std::strtod(s.c_str(), &end);
  std::ostringstream range;
  range << " must be a number in " << (above_lo ? "(" : "[") << lo << ", " << hi << "], got '" << s << "'";
  if(s.empty() || end == nullptr || *end != '\0' || !std::isfinite(v) || v < lo || v > hi || (above_lo && v == lo)) throw Usage_error(what + range.str());
  return v;
}

// Ranges of the options several commands share.
constexpr std::size_t max_count = 1000000000; // sample counts, points, sources
constexpr std::size_t max_seed = 4294967295u;
constexpr std::size_t max_bins = 4096;        // image rows and columns

inline std::string extension(const std::string& path) {
  const auto dot = path.rfind('.');
  std::string e = dot == std::string::npos ? "" : path.substr(dot + 1);
  for(char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

inline Mesh read_mesh(const Args& a, std::size_t index = 0) {
  if(a.positional.size() <= index) throw Usage_error(a.command + ": missing MESH argument");
  Mesh m;
  shapecorr::Read_options opt;
  opt.repair_non_manifold = a.has("repair-non-manifold");
  const auto r = shapecorr::read_triangle_mesh(a.positional[index], m, opt);
  if(!a.has("quiet"))
    for(const auto& rep : r.repairs) std::cerr << "note: " << a.positional[index] << ": " << rep << "\n";
  return m;
}

// A file opened for writing, or an Output_error naming it.
inline std::ofstream open_output(const std::string& path) {
  std::ofstream out(path);
  if(!out) throw shapecorr::Output_error(path + ": cannot open for writing");
  return out;
}

// One value per vertex: FILE.csv one per line, an undefined (non-finite) value as an empty line;
// FILE.ply the mesh coloured, undefined values grey. Returns the number of undefined values.
inline std::size_t write_values(const std::string& path, const Mesh& m, const std::vector<double>& values,
                                const std::vector<std::size_t>& highlight = {}) {
  const std::string ext = extension(path);
  if(ext == "ply") {
    shapecorr::write_colored_ply(path, m, values, highlight);
  } else if(ext == "csv" || ext == "txt") {
    std::ofstream out = open_output(path);
    out.precision(9);
    for(double v : values) {
      if(std::isfinite(v)) out << v;
      out << "\n";
    }
  } else {
    throw Usage_error("output must end in .csv or .ply: " + path);
  }
  return static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }));
}

inline std::string json_escape(const std::string& s) {
  std::string o;
  for(char c : s) {
    if(c == '"' || c == '\\') o += '\\';
    o += c;
  }
  return o;
}

inline std::vector<std::size_t> parse_ids(const std::string& s, std::size_t n) {
  std::vector<std::size_t> ids;
  std::stringstream ss(s);
  std::string tok;
  while(std::getline(ss, tok, ',')) {
    const std::size_t v = to_count(tok, "vertex id", 0, std::numeric_limits<std::size_t>::max());
    if(v >= n) throw shapecorr::Invalid_argument("vertex id " + tok + " out of range (mesh has " + std::to_string(n) + " vertices)");
    ids.push_back(v);
  }
  if(ids.empty()) throw Usage_error("a list of vertex ids needs at least one id");
  return ids;
}

// Seconds of wall time since t0.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Whether notes and progress go to stderr (no --quiet).
inline bool verbose(const Args& a) { return !a.has("quiet"); }

} // namespace cli

#endif
