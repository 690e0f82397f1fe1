// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The command table: one line per command (each defined in its cmd_*.cpp), in help order.
#include "command.h"

namespace cli {

const Command& info_command();
const Command& generate_command();
const Command& geodesics_command();
const Command& sample_command();
const Command& agd_command();
const Command& descriptors_command();
const Command& match_command();
const Command& register_command();
const Command& distance_command();
const Command& correspond_command();
const Command& fit_command();
const Command& ssm_build_command();
const Command& ssm_report_command();
const Command& ssm_sample_command();

const std::vector<Command>& command_table() {
  static const std::vector<Command> table = {info_command(),   generate_command(),    geodesics_command(), sample_command(),
                                             agd_command(),    descriptors_command(), match_command(),     register_command(),
                                             distance_command(), correspond_command(), fit_command(),
                                             ssm_build_command(), ssm_report_command(), ssm_sample_command()};
  return table;
}

} // namespace cli
