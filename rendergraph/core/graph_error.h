// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace sg::rg {

enum class ErrorKind : std::uint8_t {
  cycle,                // a pass reads a version it produces itself
  read_before_write,    // a transient is read before any pass writes it
  stale_version,        // a version is read or written after a newer one exists
  conflicting_usage,    // one pass uses overlapping subresources in incompatible ways
  missing_final_state,  // an imported resource is written but was imported without a final state
  invalid_usage,        // the usage does not exist in that direction or for that kind of resource
  invalid_range,        // a subresource range lies outside the resource
  invalid_handle,       // the handle does not name a resource version of this graph
};

// Messages name the pass and the resource (and the other pass, when one is involved), so the
// error reads on its own in a log.
struct GraphError {
  ErrorKind kind;
  std::string message;
};

std::string_view error_kind_name(ErrorKind kind);

}  // namespace sg::rg
