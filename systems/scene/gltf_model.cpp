// SPDX-License-Identifier: MIT
#include "systems/scene/gltf_model.h"

#include <cctype>
#include <sstream>

#include <stb_image.h>

#include "systems/scene/gltf_limits.h"
#include "systems/scene/scene_error.h"

namespace sg::scene {
namespace {

// tinygltf's LoadImageDataFunction. Checks the header's dimensions before stb allocates.
bool decode_rgba8(tinygltf::Image* image, const int index, std::string* error, std::string*, int, int,
                  const unsigned char* bytes, int size, void*) {
  const std::string object = "images[" + std::to_string(index) + "]";
  int width = 0;
  int height = 0;
  int channels = 0;
  if (stbi_info_from_memory(bytes, size, &width, &height, &channels) == 0) {
    *error += object + ": cannot decode: " + stbi_failure_reason();
    return false;
  }
  const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  if (width < 1 || height < 1 || static_cast<std::uint32_t>(width) > gltf_limits::max_image_side ||
      static_cast<std::uint32_t>(height) > gltf_limits::max_image_side ||
      pixels > gltf_limits::max_image_pixels) {
    *error += object + ": " + std::to_string(width) + "x" + std::to_string(height) +
              " pixels is outside the supported size (at most " +
              std::to_string(gltf_limits::max_image_side) + " per side, " +
              std::to_string(gltf_limits::max_image_pixels) + " pixels)";
    return false;
  }
  unsigned char* decoded = stbi_load_from_memory(bytes, size, &width, &height, &channels, 4);
  if (decoded == nullptr) {
    *error += object + ": cannot decode: " + stbi_failure_reason();
    return false;
  }
  image->width = width;
  image->height = height;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(decoded, decoded + pixels * 4);
  stbi_image_free(decoded);
  return true;
}

}  // namespace

tinygltf::Model parse_gltf_model(const GltfSource& source, Scene& scene) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&decode_rgba8, nullptr);
  tinygltf::Model model;
  std::string error;
  std::string warnings;
  const std::string base_dir = source.base_dir.string();
  const bool loaded =
      source.binary ? loader.LoadBinaryFromMemory(&model, &error, &warnings, source.bytes.data(),
                                                  static_cast<unsigned int>(source.bytes.size()), base_dir)
                    : loader.LoadASCIIFromString(
                          &model, &error, &warnings, reinterpret_cast<const char*>(source.json_text.data()),
                          static_cast<unsigned int>(source.json_text.size()), base_dir);
  std::istringstream lines(warnings);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) warn(scene, "tinygltf: " + line);
  }
  if (!loaded || !error.empty()) {
    while (!error.empty() && std::isspace(static_cast<unsigned char>(error.back()))) error.pop_back();
    throw SceneError(source.path, "glTF", error.empty() ? "tinygltf could not load it" : error);
  }
  return model;
}

}  // namespace sg::scene
