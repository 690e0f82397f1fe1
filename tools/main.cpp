// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The shapecorr command-line program: finds the command in the table, checks its arguments, runs
// it, and turns errors into one line on stderr and an exit code (1: error, 2: bad usage).
#include "command.h"

#include <shapecorr/exceptions.h>

#include <iostream>
#include <string>
#include <vector>

namespace {
// The kind of a library error as printed after its message: the defect of bad input, else the
// error's class.
std::string error_kind(const shapecorr::Error& e) {
  if(const auto* in = dynamic_cast<const shapecorr::Invalid_input*>(&e)) return shapecorr::to_string(in->defect());
  if(dynamic_cast<const shapecorr::Invalid_argument*>(&e)) return "invalid_argument";
  if(dynamic_cast<const shapecorr::Output_error*>(&e)) return "output_error";
  if(dynamic_cast<const shapecorr::Solver_failure*>(&e)) return "solver_failure";
  return "error";
}
} // namespace

int main(int argc, char** argv) {
  using namespace cli;
  const std::string first = argc < 2 ? "" : argv[1];
  if(argc < 2) { // bad usage: one line on stderr, like every other usage error
    std::cerr << "shapecorr: missing COMMAND; 'shapecorr --help' lists the commands\n";
    return 2;
  }
  if(first == "--help" || first == "-h" || first == "help") {
    std::cout << program_help();
    return 0;
  }
  if(first == "--version") {
    std::cout << "shapecorr 0.1.0\n";
    return 0;
  }
  try {
    // a command of two words ("ssm build"): the first word names a group of commands
    const std::string second = argc > 2 ? argv[2] : "";
    std::vector<std::string> group;
    for(const Command& c : command_table())
      if(c.name.rfind(first + " ", 0) == 0) group.push_back(c.name.substr(first.size() + 1));
    for(const Command& c : command_table()) {
      const bool two_words = !group.empty();
      if(c.name != (two_words ? first + " " + second : first)) continue;
      const Args a = parse_arguments(c, argc, argv, two_words ? 3 : 2);
      if(a.has("help")) {
        std::cout << command_help(c);
        return 0;
      }
      return c.run(a);
    }
    if(!group.empty()) {
      std::string list;
      for(const std::string& g : group) list += (list.empty() ? "" : ", ") + g;
      throw Usage_error(first + ": " + (second.empty() ? "missing" : "unknown") + " subcommand" + (second.empty() ? "" : " '" + second + "'") +
                        " (one of: " + list + "; see shapecorr --help)");
    }
    throw Usage_error("unknown command '" + first + "' (see shapecorr --help)");
  } catch(const Usage_error& e) {
    std::cerr << "shapecorr: " << e.what() << "\n";
    return 2;
  } catch(const shapecorr::Error& e) {
    std::cerr << "shapecorr: error: " << e.what() << " [" << error_kind(e) << "]\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "shapecorr: error: " << e.what() << "\n";
    return 1;
  }
}
