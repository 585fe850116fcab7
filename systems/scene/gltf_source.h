// SPDX-License-Identifier: MIT
#pragma once
// Step 1 of import: the file's bytes, its JSON document and (for .glb) its BIN chunk, with the
// container's framing checked. Nothing here trusts a size the file declares before comparing it
// with the bytes that exist.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sg::scene {

struct GltfSource {
  std::string path;                          // as given; prefixes every error and warning
  std::filesystem::path base_dir;            // where relative URIs resolve
  std::vector<unsigned char> bytes;          // the whole file
  bool binary = false;                       // .glb framing (detected by its magic, not the extension)
  std::span<const unsigned char> json_text;  // into bytes
  std::span<const unsigned char> bin_chunk;  // into bytes; empty when the .glb has none
  nlohmann::json document;
};

// Reads and frames the file. Throws SceneError for a missing, unreadable or oversized file, a
// truncated or malformed .glb header or chunk, or JSON that does not parse to an object
// (including numbers that overflow to infinity).
GltfSource read_gltf_source(const std::string& path);

// The size of a regular file, or throws SceneError(`where`, `object`, ...) when it is missing,
// not a regular file or larger than gltf_limits::max_file_bytes.
std::uint64_t checked_file_size(const std::filesystem::path& file, const std::string& where,
                                const std::string& object);

}  // namespace sg::scene
