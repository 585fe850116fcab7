// SPDX-License-Identifier: MIT
#pragma once
// Builds small glTF files for the tests: a JSON document plus one binary blob, written as a
// .gltf with a data URI or an external .bin, or as a .glb.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sg::scene::test {

// A fresh, empty directory under the system temp dir, removed on destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path path(const std::string& file) const { return root_ / file; }

 private:
  std::filesystem::path root_;
};

inline constexpr int u8 = 5121;
inline constexpr int u16 = 5123;
inline constexpr int u32 = 5125;
inline constexpr int f32 = 5126;

class GltfWriter {
 public:
  GltfWriter();

  nlohmann::json document;
  std::vector<std::uint8_t> blob;  // buffers[0]'s bytes

  // Appends raw bytes (4-byte aligned) as a new bufferView; returns its index.
  int add_view(const void* data, std::size_t bytes, std::size_t stride = 0);
  template <typename T>
  int add_view(const std::vector<T>& values, std::size_t stride = 0) {
    return add_view(values.data(), values.size() * sizeof(T), stride);
  }
  int add_accessor(int view, int component_type, std::size_t count, const char* type,
                   std::size_t byte_offset = 0, bool normalized = false);
  // A mesh with one triangle primitive; `attributes` maps names to accessors; indices < 0: none.
  int add_mesh(const nlohmann::json& attributes, int indices = -1, int material = -1);
  int add_node(const nlohmann::json& node);    // also listed as a root of scene 0
  int add_light(const nlohmann::json& light);  // into KHR_lights_punctual.lights

  // The unit right triangle (0,0,0), (1,0,0), (0,1,0) with normals +Z: positions accessor.
  int add_triangle_positions();

  enum class Buffer { data_uri, bin_file };
  std::filesystem::path write_gltf(const TempDir& dir, const std::string& name,
                                   Buffer buffer = Buffer::data_uri);
  std::filesystem::path write_glb(const TempDir& dir, const std::string& name);
  // The .glb bytes, for tests that damage them.
  std::vector<std::uint8_t> glb_bytes();
};

std::string base64(const std::vector<std::uint8_t>& bytes);
void write_file(const std::filesystem::path& path, const void* data, std::size_t size);
void write_file(const std::filesystem::path& path, const std::string& text);

}  // namespace sg::scene::test
