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
#include <cmath>
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

inline std::size_t to_count(const std::string& s, const std::string& what) {
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if(s.empty() || *end != '\0' || v < 0) throw Usage_error(what + " must be a non-negative integer, got '" + s + "'");
  return static_cast<std::size_t>(v);
}

inline double to_double(const std::string& s, const std::string& what) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if(s.empty() || *end != '\0' || !std::isfinite(v)) throw Usage_error(what + " must be a number, got '" + s + "'");
  return v;
}

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

inline void write_values(const std::string& path, const Mesh& m, const std::vector<double>& values,
                  const std::vector<std::size_t>& highlight = {}) {
  const std::string ext = extension(path);
  if(ext == "ply") {
    shapecorr::write_colored_ply(path, m, values, highlight);
  } else if(ext == "csv" || ext == "txt") {
    std::ofstream out = open_output(path);
    out.precision(9);
    for(double v : values) out << v << "\n";
  } else {
    throw Usage_error("output must end in .csv or .ply: " + path);
  }
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
    const std::size_t v = to_count(tok, "vertex id");
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
