// SPDX-License-Identifier: MIT
#pragma once
// Decoded images for materials: always 8-bit RGBA, rows top to bottom, as the renderer uploads
// them. Color data is sRGB-encoded as stored in the file (upload as an sRGB format).
#include <cstdint>
#include <string>
#include <vector>

namespace sg::scene {

struct Texture {
  std::string name;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4 bytes
};

struct TextureLibrary {
  std::vector<Texture> textures;
};

}  // namespace sg::scene
