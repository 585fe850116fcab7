// SPDX-License-Identifier: MIT
#include "rendergraph/core/graph_error.h"

namespace sg::rg {

std::string_view error_kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::cycle: return "cycle";
    case ErrorKind::read_before_write: return "read_before_write";
    case ErrorKind::stale_version: return "stale_version";
    case ErrorKind::conflicting_usage: return "conflicting_usage";
    case ErrorKind::missing_final_state: return "missing_final_state";
    case ErrorKind::invalid_usage: return "invalid_usage";
    case ErrorKind::invalid_range: return "invalid_range";
    case ErrorKind::invalid_handle: return "invalid_handle";
  }
  return "unknown";
}

}  // namespace sg::rg
