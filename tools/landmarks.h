// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Landmark files of the commands that take them (register, fit): reading and pairing.
#ifndef SHAPECORR_TOOLS_LANDMARKS_H
#define SHAPECORR_TOOLS_LANDMARKS_H

#include "cli_common.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cli {

// Landmarks of a file: the JSON of ../shared/data/vertebrae (a list of {"id", "coordinates"}), or
// plain text (one "x y z" per line; '#' starts a comment). Ids are empty for text files.
struct Landmarks {
  std::vector<std::string> ids;
  std::vector<K::Point_3> points;
};

inline Landmarks read_landmarks(const std::string& path) {
  std::ifstream in(path);
  if(!in) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, path + ": cannot open the landmark file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  Landmarks L;
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if(first != std::string::npos && text[first] == '[') {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text);
    } catch(const std::exception& e) {
      throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, path + ": not valid JSON (" + e.what() + ")");
    }
    std::size_t i = 0;
    for(const auto& e : j) {
      const std::string where = path + ": landmark " + std::to_string(i++);
      if(!e.is_object() || !e.contains("coordinates") || !e["coordinates"].is_array() || e["coordinates"].size() != 3)
        throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, where + " has no \"coordinates\": [x, y, z]");
      double c[3];
      for(int k = 0; k < 3; ++k) {
        const auto& v = e["coordinates"][static_cast<std::size_t>(k)];
        if(!v.is_number()) throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, where + ": a coordinate is not a number");
        c[k] = v.get<double>();
      }
      L.ids.push_back(e.contains("id") && e["id"].is_string() ? e["id"].get<std::string>() : std::to_string(i - 1));
      L.points.emplace_back(c[0], c[1], c[2]);
    }
  } else {
    std::istringstream lines(text);
    std::string line;
    std::size_t no = 0;
    while(std::getline(lines, line)) {
      ++no;
      line = line.substr(0, line.find('#'));
      if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
      std::istringstream ls(line);
      double x, y, z;
      std::string rest;
      if(!(ls >> x >> y >> z) || (ls >> rest))
        throw shapecorr::Invalid_input(shapecorr::Mesh_defect::unreadable_file, path + ": line " + std::to_string(no) + " is not 'x y z'");
      L.ids.push_back(std::to_string(L.points.size()));
      L.points.emplace_back(x, y, z);
    }
  }
  for(std::size_t i = 0; i < L.points.size(); ++i)
    if(!std::isfinite(L.points[i].x()) || !std::isfinite(L.points[i].y()) || !std::isfinite(L.points[i].z()))
      throw shapecorr::Invalid_input(shapecorr::Mesh_defect::non_finite_coordinate, path + ": landmark " + L.ids[i] + " is not finite");
  return L;
}

// The pairs of two landmark files: by id where both files have the same ids (in any order), else
// by position (the counts must agree).
inline void pair_landmarks(Landmarks& s, Landmarks& t) {
  Landmarks ps, pt;
  for(std::size_t i = 0; i < s.ids.size(); ++i)
    for(std::size_t j = 0; j < t.ids.size(); ++j)
      if(s.ids[i] == t.ids[j]) {
        ps.ids.push_back(s.ids[i]);
        ps.points.push_back(s.points[i]);
        pt.ids.push_back(t.ids[j]);
        pt.points.push_back(t.points[j]);
      }
  if(ps.points.size() == s.points.size() && ps.points.size() == t.points.size()) {
    s = ps;
    t = pt;
    return;
  }
  if(s.points.size() != t.points.size())
    throw shapecorr::Invalid_argument("landmarks: " + std::to_string(s.points.size()) + " source landmarks against " +
                                      std::to_string(t.points.size()) + " target landmarks (and their ids differ)");
}

} // namespace cli

#endif
