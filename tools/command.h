// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line program's framework: a command is a row of the command table (name, synopsis,
// description, options, run); its arguments are checked against its own options before it runs.
// Adding a command: one file cmd_NAME.cpp defining `const Command& NAME_command()`, one line in
// commands.cpp.
#ifndef SHAPECORR_TOOLS_COMMAND_H
#define SHAPECORR_TOOLS_COMMAND_H

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace cli {

/// Bad usage: exit code 2, the message and a pointer to the command's help.
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One option of a command: `--name VALUE` (value_name set) or a flag `--name`. An option whose
/// value_name has several words (`--landmarks S T`) takes that many values.
struct Option {
  std::string name;
  std::string value_name; // empty: a flag
  std::string help;
  std::size_t number_of_values() const;
};

/// The parsed arguments of one command (options already checked against its table).
struct Args {
  std::string command;
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;
  bool has(const std::string& k) const { return options.count(k) > 0; }
  std::string get(const std::string& k, const std::string& def = "") const {
    auto it = options.find(k);
    return it == options.end() ? def : it->second;
  }
  /// The values of an option that takes several (`Option::number_of_values()`), in order.
  std::vector<std::string> values(const std::string& k) const;
  std::string require(const std::string& k) const {
    if(!has(k) || get(k).empty()) throw Usage_error(command + ": missing --" + k);
    return get(k);
  }
};

/// A row of the command table.
struct Command {
  std::string name;
  std::string synopsis;    // e.g. "geodesics MESH --source V[,V...] [--method heat|exact|fmm] --output FILE"
  std::string description; // what it does, outputs, defaults (wrapped text)
  std::vector<Option> options;
  std::size_t min_positional = 0, max_positional = 0;
  int (*run)(const Args&) = nullptr;
};

/// Every command, in the order `shapecorr --help` lists them (commands.cpp).
const std::vector<Command>& command_table();

/// `own` followed by the options that every command reading meshes takes.
std::vector<Option> with_mesh_reading_options(std::vector<Option> own);

/// Parses argv[first..] for `c`: unknown options (with the nearest known name suggested), missing
/// values and a wrong number of positional arguments are usage errors.
Args parse_arguments(const Command& c, int argc, char** argv, int first);

/// `shapecorr COMMAND --help`.
std::string command_help(const Command& c);

/// `shapecorr --help`.
std::string program_help();

} // namespace cli

#endif
