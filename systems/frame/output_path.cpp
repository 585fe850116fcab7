// SPDX-License-Identifier: MIT
#include "systems/frame/output_path.h"

#include <filesystem>
#include <string_view>

#include <unistd.h>

namespace sg {
namespace {

// `before` "path" `after`, appended in turn (GCC 12 warns of a false overlap in "..." + path).
std::string about(std::string_view before, const std::string& path, std::string_view after) {
  std::string text(before);
  text += '"';
  text += path;
  text += '"';
  text += after;
  return text;
}

}  // namespace

std::optional<std::string> output_path_problem(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) return "the path is empty";
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status)) return about("", path, " is a folder, not a file");
  if (fs::exists(status)) {
    if (access(path.c_str(), W_OK) != 0) return about("", path, " is not writable");
    return std::nullopt;
  }
  const fs::path file(path);
  const std::string folder = file.has_parent_path() ? file.parent_path().string() : ".";
  const fs::file_status folder_status = fs::status(folder, error);
  if (!fs::exists(folder_status)) return about("the folder ", folder, " does not exist");
  if (!fs::is_directory(folder_status)) return about("", folder, " is not a folder");
  if (access(folder.c_str(), W_OK | X_OK) != 0) return about("the folder ", folder, " is not writable");
  return std::nullopt;
}

std::optional<std::string> optional_output_problem(const std::string& path) {
  return path.empty() ? std::nullopt : output_path_problem(path);
}

}  // namespace sg
