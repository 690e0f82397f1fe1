// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Evaluation helper: what the evaluation programs share besides plots: their "--key value" command
// lines, the check for the data, numbers in the JSON summaries.
#ifndef SHAPECORR_EVALUATION_PROGRAM_H
#define SHAPECORR_EVALUATION_PROGRAM_H

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace eval {

// Reads "--key value" pairs into `set(key, value)`, which returns false for an unknown key. Returns
// -1 to go on, else the exit code after printing `usage`: 0 for --help, 2 for an option without
// its value or an unknown one.
template <typename Set>
int parse_options(int argc, char** argv, const std::string& program, const std::string& usage, Set&& set) {
  if(argc % 2 == 0) {
    std::cerr << "usage: " << program << " " << usage << "\n";
    return std::string(argv[argc - 1]) == "--help" ? 0 : 2;
  }
  for(int i = 1; i + 1 < argc; i += 2)
    if(!set(std::string(argv[i]), std::string(argv[i + 1]))) {
      std::cerr << program << ": unknown option " << argv[i] << "\nusage: " << program << " " << usage << "\n";
      return 2;
    }
  return -1;
}

// Whether `data` holds the evaluation data (its README.md); says so on stderr when not.
inline bool has_evaluation_data(const std::string& program, const std::string& data) {
  if(std::ifstream(data + "/README.md")) return true;
  std::cerr << program << ": no evaluation data at " << data << " (give --data DIR)\n";
  return false;
}

// The non-empty fields of s between separators c ("a,b,,c" -> a, b, c).
inline std::vector<std::string> split(const std::string& s, char c) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string field;
  while(std::getline(in, field, c))
    if(!field.empty()) out.push_back(field);
  return out;
}

// A number for a JSON file: 6 significant digits, 0 for NaN and infinities (not JSON).
inline std::string json_number(double x) {
  std::ostringstream o;
  o.precision(6);
  o << (std::isfinite(x) ? x : 0.0);
  return o.str();
}

} // namespace eval

#endif
