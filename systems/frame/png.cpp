// SPDX-License-Identifier: MIT
#include "systems/frame/png.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <stb_image_write.h>

namespace sg {

// Through a stream rather than stbi_write_png, which does not check its writes: a full disk left
// a truncated file and reported success.
void write_png(const std::string& path, const vk::Rgba8Image& image) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw std::runtime_error("cannot write PNG file '" + path + "': " + std::strerror(errno));
  const auto append = [](void* stream, void* data, int size) {
    static_cast<std::ofstream*>(stream)->write(static_cast<const char*>(data), size);
  };
  const int stride = static_cast<int>(image.width * 4);
  const bool encoded = stbi_write_png_to_func(append, &file, static_cast<int>(image.width),
                                              static_cast<int>(image.height), 4, image.pixels.data(), stride);
  file.close();
  if (!encoded) throw std::runtime_error("cannot write PNG file '" + path + "': encoding failed");
  if (!file) {
    throw std::runtime_error("cannot write PNG file '" + path + "': writing failed (" + std::strerror(errno) +
                             ")");
  }
}

}  // namespace sg
