// SPDX-License-Identifier: MIT
#include "sandbox/shadow_map_dump.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <system_error>

#include "rendergraph/device/readback.h"
#include "systems/frame/png.h"
#include "systems/renderer/scene_renderer.h"

namespace sg::sandbox {
namespace {

// Names become file names: keep letters, digits, '-' and '_'.
std::string file_stem(const std::string& name) {
  std::string stem;
  for (char c : name) stem += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return stem;
}

uint8_t grey(float value) { return static_cast<uint8_t>(std::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f); }

vk::Rgba8Image grey_image(uint32_t size, auto&& value_at) {
  vk::Rgba8Image image{size, size, std::vector<uint8_t>(size_t{size} * size * 4)};
  for (uint32_t y = 0; y < size; ++y) {
    for (uint32_t x = 0; x < size; ++x) {
      uint8_t* p = &image.pixels[(size_t{y} * size + x) * 4];
      p[0] = p[1] = p[2] = grey(value_at(x, y));
      p[3] = 255;
    }
  }
  return image;
}

}  // namespace

void dump_shadow_maps(vk::VulkanContext& context, const SceneRenderer& renderer,
                      const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw std::runtime_error("cannot create " + directory + ": " + error.message());
  const shadows::FrameLights& lights = renderer.lights();
  const vk::Image& atlas = renderer.shadow_atlas().image();
  constexpr VkImageLayout sampled = VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL;
  int written = 0;
  // Each page is read once, however many tiles it holds.
  std::map<uint32_t, vk::DepthImage> pages;
  const auto page = [&](uint32_t layer) -> const vk::DepthImage& {
    auto found = pages.find(layer);
    if (found == pages.end())
      found = pages.emplace(layer, vk::read_depth_layer(context, atlas, layer, sampled)).first;
    return found->second;
  };

  for (const shadows::ShadowMapView& map : lights.maps) {
    if (map.resolution == 0) continue;  // no shadow in the last frame
    const vk::DepthImage& depth = page(map.tile.page);
    const float near = map.view.near, far = map.view.far;
    const bool orthographic = map.view.orthographic;
    const std::string path = directory + "/" + file_stem(map.name) + ".png";
    write_png(path, grey_image(map.resolution, [&](uint32_t x, uint32_t y) {
                const float d = depth.at(map.tile.x + x, map.tile.y + y);
                if (orthographic) return d;
                // The perspective map's stored depth back to a fraction of near..far.
                const float view_z = near * far / (far - d * (far - near));
                return (view_z - near) / (far - near);
              }));
    ++written;
  }
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    if (cube.resolution == 0) continue;
    for (uint32_t face = 0; face < 6; ++face) {
      const shadows::AtlasTile& tile = cube.tiles[face];
      const vk::DepthImage& depth = page(tile.page);
      const std::string path =
          directory + "/" + file_stem(cube.name) + "_face" + std::to_string(face) + ".png";
      write_png(path, grey_image(tile.size,
                                 [&](uint32_t x, uint32_t y) { return depth.at(tile.x + x, tile.y + y); }));
      ++written;
    }
  }
  std::printf("shadowgraph: wrote %d shadow map images to %s\n", written, directory.c_str());
}

}  // namespace sg::sandbox
