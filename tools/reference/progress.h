// SPDX-License-Identifier: MIT
#pragma once
// Where the reference runs report their progress: a line at a time, or nowhere.
#include <functional>
#include <string>

namespace sg::reference {

using Progress = std::function<void(const std::string&)>;

inline void say(const Progress& progress, const std::string& line) {
  if (progress) progress(line);
}

}  // namespace sg::reference
