// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_source.h"

#include <cstring>
#include <fstream>

#include "systems/scene/gltf_limits.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

constexpr std::uint32_t glb_magic = 0x46546C67;        // "glTF"
constexpr std::uint32_t chunk_type_json = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t chunk_type_bin = 0x004E4942;   // "BIN\0"
constexpr std::size_t glb_header_bytes = 12;
constexpr std::size_t chunk_header_bytes = 8;

std::uint32_t read_u32(const std::vector<unsigned char>& bytes, std::size_t offset) {
  std::uint32_t value = 0;  // glb is little-endian, as every platform we build for
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  return value;
}

// Checks the .glb framing (spec section "Binary glTF Layout") and points json_text/bin_chunk
// into the bytes. Chunk lengths are compared against what is left of the file before use.
void frame_glb(GltfSource& source) {
  const std::vector<unsigned char>& bytes = source.bytes;
  const std::size_t size = bytes.size();
  if (size < glb_header_bytes + chunk_header_bytes) {
    throw SceneError(source.path, "glb header",
                     "truncated: " + std::to_string(size) + " bytes, a .glb needs at least 20");
  }
  const std::uint32_t version = read_u32(bytes, 4);
  const std::uint32_t length = read_u32(bytes, 8);
  if (version != 2) {
    throw SceneError(source.path, "glb header", "version " + std::to_string(version) + ", not 2");
  }
  if (length != size) {
    throw SceneError(source.path, "glb header",
                     (length > size ? "truncated: the header declares " : "the header declares ") +
                         std::to_string(length) + " bytes but the file has " + std::to_string(size));
  }
  const std::uint64_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != chunk_type_json) {
    throw SceneError(source.path, "glb chunk 0", "is not a JSON chunk");
  }
  const std::uint64_t json_end = glb_header_bytes + chunk_header_bytes + json_length;
  if (json_length == 0 || json_end > size) {
    throw SceneError(source.path, "glb chunk 0",
                     "truncated: declares " + std::to_string(json_length) +
                         " bytes of JSON, the file holds " +
                         std::to_string(size - glb_header_bytes - chunk_header_bytes));
  }
  source.json_text = std::span(bytes).subspan(glb_header_bytes + chunk_header_bytes, json_length);
  const std::uint64_t rest = size - json_end;
  if (rest == 0) return;
  if (rest < chunk_header_bytes) {
    throw SceneError(source.path, "glb chunk 1", "truncated chunk header");
  }
  const std::uint64_t bin_length = read_u32(bytes, json_end);
  if (read_u32(bytes, json_end + 4) != chunk_type_bin) {
    throw SceneError(source.path, "glb chunk 1", "is not a BIN chunk");
  }
  if (bin_length > rest - chunk_header_bytes) {
    throw SceneError(source.path, "glb chunk 1",
                     "truncated: declares " + std::to_string(bin_length) + " bytes, the file holds " +
                         std::to_string(rest - chunk_header_bytes));
  }
  source.bin_chunk = std::span(bytes).subspan(json_end + chunk_header_bytes, bin_length);
}

}  // namespace

std::uint64_t checked_file_size(const std::filesystem::path& file, const std::string& where,
                                const std::string& object) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (error || !std::filesystem::exists(status)) {
    throw SceneError(where, object, "file not found: " + file.string());
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw SceneError(where, object, "not a regular file: " + file.string());
  }
  const std::uint64_t size = std::filesystem::file_size(file, error);
  if (error) throw SceneError(where, object, "cannot read " + file.string() + ": " + error.message());
  if (size > gltf_limits::max_file_bytes) {
    throw SceneError(where, object,
                     file.string() + " is " + std::to_string(size) + " bytes, over the limit of " +
                         std::to_string(gltf_limits::max_file_bytes));
  }
  return size;
}

GltfSource read_gltf_source(const std::string& path) {
  GltfSource source;
  source.path = path;
  source.base_dir = std::filesystem::path(path).parent_path();
  const std::uint64_t size = checked_file_size(path, path, "file");
  source.bytes.resize(size);
  std::ifstream stream(path, std::ios::binary);
  if (!stream.read(reinterpret_cast<char*>(source.bytes.data()), static_cast<std::streamsize>(size))) {
    throw SceneError(path, "file", "read error");
  }
  source.binary = size >= 4 && read_u32(source.bytes, 0) == glb_magic;
  if (source.binary) {
    frame_glb(source);
  } else {
    source.json_text = source.bytes;
  }
  try {
    source.document = nlohmann::json::parse(source.json_text.begin(), source.json_text.end());
  } catch (const nlohmann::json::exception& error) {
    throw SceneError(path, "JSON", std::string("does not parse: ") + error.what());
  }
  if (!source.document.is_object()) throw SceneError(path, "JSON", "the root is not an object");
  return source;
}

}  // namespace sg::scene
