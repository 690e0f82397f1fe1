// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The shapecorr command-line program: finds the command in the table, checks its arguments, runs
// it, and turns errors into one line on stderr and an exit code (1: error, 2: bad usage).
#include "command.h"

#include <shapecorr/exceptions.h>

#include <iostream>
#include <string>

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
    for(const Command& c : command_table()) {
      if(c.name != first) continue;
      const Args a = parse_arguments(c, argc, argv, 2);
      if(a.has("help")) {
        std::cout << command_help(c);
        return 0;
      }
      return c.run(a);
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
