// SPDX-License-Identifier: MIT
#pragma once
#include <optional>
#include <string>

namespace sg {

// Why a file could not be written at `path`, or nullopt where it can be: its folder is missing,
// not a folder or read-only, or the path names a folder or a read-only file. Outputs written only
// after a run (a screenshot, --stats, an export) are checked when the command line is read, so a
// mistyped folder ends the program before its first frame rather than costing the run.
std::optional<std::string> output_path_problem(const std::string& path);

// As output_path_problem, for an output that may be left out: empty text (no file) is fine.
std::optional<std::string> optional_output_problem(const std::string& path);

}  // namespace sg
