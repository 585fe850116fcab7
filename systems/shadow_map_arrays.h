#pragma once
// The persistent shadow storage every light shares: a D32 2D array (one layer per spot,
// directional or cylinder shadow) and a D32 cube-map array (one cube per point-light shadow).
// Both outlive frames and are imported into each frame's graph.
//
// Contract: fit() recreates an image only when the lights need more layers or cubes or a larger
// size than it has (it grows, never shrinks while running, and adds half again the layers or
// cubes it had, so that lights added one by one recreate it rarely); recreating waits for the
// GPU to go idle first, because frames in flight may still sample the old image. Both images always
// exist (at least one layer and one cube), so the lighting pass's descriptors are always valid.
#include <cstdint>

#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/resources.h"

namespace sg {

class ShadowAtlas {
 public:
  static constexpr rg::Format depth_format = rg::Format::d32_sfloat;

  explicit ShadowAtlas(vk::VulkanContext& context);

  struct Changes {
    bool maps = false;   // the 2D array was recreated: its contents and layout are gone
    bool cubes = false;  // the cube array was recreated
  };
  Changes fit(uint32_t map_layers, uint32_t map_size, uint32_t cubes, uint32_t cube_size);

  const vk::Image& maps() const { return maps_; }
  const vk::Image& cubes() const { return cubes_; }
  rg::ImageDesc maps_desc() const { return maps_desc_; }
  rg::ImageDesc cubes_desc() const { return cubes_desc_; }
  // Memory of both images, for --stats' shadow_map_bytes.
  uint64_t bytes() const;

 private:
  vk::VulkanContext& context_;
  rg::ImageDesc maps_desc_{};
  rg::ImageDesc cubes_desc_{};
  vk::Image maps_;
  vk::Image cubes_;
};

}  // namespace sg
