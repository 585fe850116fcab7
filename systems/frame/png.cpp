// SPDX-License-Identifier: MIT
#include "systems/frame/png.h"

#include <stdexcept>

#include <stb_image_write.h>

namespace sg {

void write_png(const std::string& path, const vk::Rgba8Image& image) {
  const int stride = static_cast<int>(image.width * 4);
  if (!stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height), 4,
                      image.pixels.data(), stride)) {
    throw std::runtime_error("cannot write PNG file '" + path +
                             "' (does the folder exist, and is it writable?)");
  }
}

}  // namespace sg
