// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Argument checking and help texts of the command table.
#include "command.h"

#include <algorithm>
#include <sstream>

namespace cli {

std::vector<Option> with_mesh_reading_options(std::vector<Option> own) {
  own.push_back({"repair-non-manifold", "", "split non-manifold edges and vertices instead of refusing the mesh"});
  own.push_back({"quiet", "", "no notes and progress on stderr"});
  return own;
}

namespace {

// Levenshtein distance, for "did you mean" suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for(std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for(std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for(std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

const Option* find_option(const Command& c, const std::string& name) {
  for(const Option& o : c.options)
    if(o.name == name) return &o;
  return nullptr;
}

std::string unknown_option_message(const Command& c, const std::string& name) {
  std::string best;
  std::size_t best_d = 3; // suggest only near misses
  for(const Option& o : c.options) {
    const std::size_t d = edit_distance(name, o.name);
    if(d < best_d || (o.name.rfind(name, 0) == 0 && best.empty())) {
      best_d = std::min(d, best_d);
      best = o.name;
    }
  }
  std::string msg = c.name + ": unknown option --" + name;
  if(!best.empty()) msg += " (did you mean --" + best + "?)";
  return msg + "; see shapecorr " + c.name + " --help";
}

// Wraps `text` at 96 columns with `indent` spaces before each line.
std::string wrap(const std::string& text, std::size_t indent) {
  std::ostringstream out;
  std::istringstream words(text);
  std::string w, line;
  const std::string pad(indent, ' ');
  while(words >> w) {
    if(!line.empty() && line.size() + 1 + w.size() + indent > 96) {
      out << pad << line << "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + w;
  }
  if(!line.empty()) out << pad << line << "\n";
  return out.str();
}

} // namespace

std::size_t Option::number_of_values() const {
  if(value_name.empty()) return 0;
  return static_cast<std::size_t>(std::count(value_name.begin(), value_name.end(), ' ')) + 1;
}

std::vector<std::string> Args::values(const std::string& k) const {
  std::vector<std::string> out;
  if(!has(k)) return out;
  std::istringstream in(get(k));
  for(std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

Args parse_arguments(const Command& c, int argc, char** argv, int first) {
  Args a;
  a.command = c.name;
  for(int i = first; i < argc; ++i) {
    const std::string s = argv[i];
    if(s.rfind("--", 0) == 0 && s.size() > 2) {
      std::string key = s.substr(2), value;
      const auto eq = key.find('=');
      const bool inline_value = eq != std::string::npos;
      if(inline_value) {
        value = key.substr(eq + 1);
        key = key.substr(0, eq);
      }
      if(key == "help") {
        a.options["help"] = "";
        continue;
      }
      const Option* o = find_option(c, key);
      if(!o) throw Usage_error(unknown_option_message(c, key));
      if(o->value_name.empty()) {
        if(inline_value) throw Usage_error(c.name + ": option --" + key + " takes no value");
      } else if(o->number_of_values() > 1) {
        if(inline_value) throw Usage_error(c.name + ": option --" + key + " takes " + std::to_string(o->number_of_values()) + " values: --" + key + " " + o->value_name);
        for(std::size_t k = 0; k < o->number_of_values(); ++k) {
          if(i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0)
            throw Usage_error(c.name + ": option --" + key + " needs " + std::to_string(o->number_of_values()) + " values (" + o->value_name + ")");
          value += (k ? "\n" : "") + std::string(argv[++i]);
        }
      } else if(!inline_value) {
        if(i + 1 >= argc) throw Usage_error(c.name + ": option --" + key + " needs a value (" + o->value_name + ")");
        value = argv[++i];
      }
      if(a.has(key)) throw Usage_error(c.name + ": option --" + key + " given twice");
      a.options[key] = value;
    } else {
      a.positional.push_back(s);
    }
  }
  if(a.has("help")) return a;
  if(a.positional.size() < c.min_positional)
    throw Usage_error(c.name + ": missing arguments; usage: shapecorr " + c.synopsis);
  if(a.positional.size() > c.max_positional)
    throw Usage_error(c.name + ": unexpected argument '" + a.positional[c.max_positional] + "'; usage: shapecorr " + c.synopsis);
  return a;
}

std::string command_help(const Command& c) {
  std::ostringstream out;
  out << "usage: shapecorr " << c.synopsis << "\n\n" << wrap(c.description, 2) << "\noptions:\n";
  for(const Option& o : c.options) {
    std::string head = "  --" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
    out << head;
    if(head.size() < 28) out << std::string(28 - head.size(), ' ');
    else out << "\n" << std::string(28, ' ');
    const std::string body = wrap(o.help, 28);
    out << body.substr(std::min<std::size_t>(28, body.size()));
  }
  out << "  --help                    this text\n";
  return out.str();
}

std::string program_help() {
  std::ostringstream out;
  out << "shapecorr - shape correspondences from local descriptors to global registration\n\nusage:\n";
  for(const Command& c : command_table()) {
    out << "  shapecorr " << c.synopsis << "\n";
    const std::string first_sentence = c.description.substr(0, c.description.find(". ") + 1);
    out << wrap(first_sentence, 6);
  }
  out << "  shapecorr --help | --version | COMMAND --help\n\n"
         "Meshes: OFF, OBJ, PLY, STL. Reading removes isolated vertices and triangulates polygons.\n"
         "Errors: one line on stderr, exit code 1 (2 for bad usage). 'shapecorr COMMAND --help' lists\n"
         "a command's options; an option a command does not know is an error.\n";
  return out.str();
}

} // namespace cli
