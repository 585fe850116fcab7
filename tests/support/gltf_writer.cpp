// SPDX-License-Identifier: MIT
#include "tests/support/gltf_writer.h"

#include <atomic>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

namespace sg::scene::test {

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  root_ = std::filesystem::temp_directory_path() /
          ("sg-scene-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(root_);
  std::filesystem::create_directories(root_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(root_, ignored);
}

GltfWriter::GltfWriter() {
  document = {{"asset", {{"version", "2.0"}}},
              {"scene", 0},
              {"scenes", nlohmann::json::array({{{"nodes", nlohmann::json::array()}}})},
              {"nodes", nlohmann::json::array()},
              {"buffers", nlohmann::json::array()},
              {"bufferViews", nlohmann::json::array()},
              {"accessors", nlohmann::json::array()},
              {"meshes", nlohmann::json::array()}};
}

int GltfWriter::add_view(const void* data, std::size_t bytes, std::size_t stride) {
  while (blob.size() % 4 != 0) blob.push_back(0);
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", blob.size()}, {"byteLength", bytes}};
  if (stride != 0) view["byteStride"] = stride;
  const auto* begin = static_cast<const std::uint8_t*>(data);
  blob.insert(blob.end(), begin, begin + bytes);
  document["bufferViews"].push_back(view);
  return static_cast<int>(document["bufferViews"].size() - 1);
}

int GltfWriter::add_accessor(int view, int component_type, std::size_t count, const char* type,
                             std::size_t byte_offset, bool normalized) {
  nlohmann::json accessor = {{"componentType", component_type}, {"count", count}, {"type", type}};
  if (view >= 0) accessor["bufferView"] = view;
  if (byte_offset != 0) accessor["byteOffset"] = byte_offset;
  if (normalized) accessor["normalized"] = true;
  document["accessors"].push_back(accessor);
  return static_cast<int>(document["accessors"].size() - 1);
}

int GltfWriter::add_mesh(const nlohmann::json& attributes, int indices, int material) {
  nlohmann::json primitive = {{"attributes", attributes}};
  if (indices >= 0) primitive["indices"] = indices;
  if (material >= 0) primitive["material"] = material;
  document["meshes"].push_back({{"primitives", nlohmann::json::array({primitive})}});
  return static_cast<int>(document["meshes"].size() - 1);
}

int GltfWriter::add_node(const nlohmann::json& node) {
  document["nodes"].push_back(node.is_null() ? nlohmann::json::object() : node);
  const int index = static_cast<int>(document["nodes"].size() - 1);
  document["scenes"][0]["nodes"].push_back(index);
  return index;
}

int GltfWriter::add_light(const nlohmann::json& light) {
  nlohmann::json& lights = document["extensions"]["KHR_lights_punctual"]["lights"];
  lights.push_back(light);
  document["extensionsUsed"] = {"KHR_lights_punctual"};
  return static_cast<int>(lights.size() - 1);
}

int GltfWriter::add_triangle_positions() {
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  return add_accessor(add_view(positions), f32, 3, "VEC3");
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t chunk = (std::uint32_t{bytes[i]} << 16) |
                                (i + 1 < bytes.size() ? std::uint32_t{bytes[i + 1]} << 8 : 0) |
                                (i + 2 < bytes.size() ? std::uint32_t{bytes[i + 2]} : 0);
    out += alphabet[(chunk >> 18) & 63];
    out += alphabet[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? alphabet[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[chunk & 63] : '=';
  }
  return out;
}

void write_file(const std::filesystem::path& path, const void* data, std::size_t size) {
  std::ofstream stream(path, std::ios::binary);
  stream.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!stream) throw std::runtime_error("cannot write " + path.string());
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  write_file(path, text.data(), text.size());
}

std::filesystem::path GltfWriter::write_gltf(const TempDir& dir, const std::string& name, Buffer buffer) {
  nlohmann::json out = document;
  if (!blob.empty() && out["buffers"].empty()) {
    nlohmann::json entry = {{"byteLength", blob.size()}};
    if (buffer == Buffer::data_uri) {
      entry["uri"] = "data:application/octet-stream;base64," + base64(blob);
    } else {
      entry["uri"] = name + ".bin";
      write_file(dir.path(name + ".bin"), blob.data(), blob.size());
    }
    out["buffers"].push_back(entry);
  }
  const std::filesystem::path path = dir.path(name + ".gltf");
  write_file(path, out.dump());
  return path;
}

std::vector<std::uint8_t> GltfWriter::glb_bytes() {
  nlohmann::json out = document;
  if (!blob.empty() && out["buffers"].empty()) out["buffers"].push_back({{"byteLength", blob.size()}});
  std::string json = out.dump();
  while (json.size() % 4 != 0) json += ' ';
  std::vector<std::uint8_t> bin = blob;
  while (bin.size() % 4 != 0) bin.push_back(0);
  std::vector<std::uint8_t> bytes;
  auto put_u32 = [&](std::uint32_t value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + 4);
  };
  const std::uint32_t total =
      static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
  put_u32(0x46546C67);
  put_u32(2);
  put_u32(total);
  put_u32(static_cast<std::uint32_t>(json.size()));
  put_u32(0x4E4F534A);
  bytes.insert(bytes.end(), json.begin(), json.end());
  if (!bin.empty()) {
    put_u32(static_cast<std::uint32_t>(bin.size()));
    put_u32(0x004E4942);
    bytes.insert(bytes.end(), bin.begin(), bin.end());
  }
  return bytes;
}

std::filesystem::path GltfWriter::write_glb(const TempDir& dir, const std::string& name) {
  const std::vector<std::uint8_t> bytes = glb_bytes();
  const std::filesystem::path path = dir.path(name + ".glb");
  write_file(path, bytes.data(), bytes.size());
  return path;
}

}  // namespace sg::scene::test
