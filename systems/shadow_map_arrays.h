#pragma once
// The persistent shadow storage every light shares: a D32 2D array (one layer per spot,
// directional or cylinder shadow) and a D32 cube-map array (one cube per point-light shadow).
// Both outlive frames and are imported into each frame's graph.
//
// Contract: fit() recreates an image only when shadows::fit_shadow_storage asks for a size other
// than the one it has (it grows, never shrinks while running); recreating waits for the GPU to
// go idle first, because frames in flight may still sample the old image. Both images always
// exist (at least one layer and one cube), so the lighting pass's descriptors are always valid.
#include <cstdint>

#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/resources.h"
#include "systems/shadows/shadow_storage_size.h"

namespace sg {

class ShadowMapArrays {
 public:
  static constexpr rg::Format depth_format = rg::Format::d32_sfloat;

  explicit ShadowMapArrays(vk::VulkanContext& context);

  // Makes room for `needed` (shadows::needed_storage of the frame's lights).
  void fit(const shadows::ShadowStorageSize& needed);

  const vk::Image& maps() const { return maps_; }
  const vk::Image& cubes() const { return cubes_; }
  const shadows::ShadowStorageSize& size() const { return size_; }
  // Memory of both images, for --stats' shadow_map_bytes.
  uint64_t bytes() const;

 private:
  vk::VulkanContext& context_;
  shadows::ShadowStorageSize size_{};
  vk::Image maps_;
  vk::Image cubes_;
};

}  // namespace sg
