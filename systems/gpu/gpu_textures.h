// SPDX-License-Identifier: MIT
#pragma once
// The scene's decoded images on the GPU, as the layers of one sRGB 2D array that the lighting
// pass samples with the material's texture index as the layer (shaders/scene.frag). One array
// needs no descriptor indexing (lavapipe has none) and lets instances of one draw use different
// textures. The layers are square, the largest image's longer side rounded up to a power of
// two and at most max_layer_size; smaller or non-square images are resampled to it, which
// keeps their uv mapping. A scene without textures gets one white layer, so the array exists.
#include <cstdint>
#include <vector>

#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/resources.h"
#include "systems/scene/texture_library.h"

namespace sg {

class GpuTextures {
 public:
  static constexpr uint32_t max_layer_size = 1024;

  GpuTextures(vk::VulkanContext& context, const scene::TextureLibrary& textures);

  const vk::Image& array() const { return array_; }
  // Linear filtering with glTF's default wrapping (repeat).
  VkSampler sampler() const { return sampler_.get(); }
  uint32_t layers() const { return layers_; }
  // Whether the scene has any image (else the array is the one white layer): the
  // MATERIAL_TEXTURES specialization constant of shaders/material.glsl.
  bool has_images() const { return has_images_; }

 private:
  vk::Image array_;
  vk::UniqueSampler sampler_;
  uint32_t layers_ = 0;
  bool has_images_ = false;
};

// shaders/material.glsl's MATERIAL_FEATURES: its constant_id and bits.
inline constexpr size_t material_features_constant = 2;
inline constexpr uint32_t material_textures = 1;
inline constexpr uint32_t material_cut_out = 2;

// The fragment specialization of a pass that draws materials: the shader's own constants 0 and
// 1, then MATERIAL_FEATURES, with textures where `textures` has images (masks' cut-outs are
// added per draw class, for_draw_class in camera_pipelines.h).
inline std::vector<uint32_t> material_pass_constants(uint32_t constant0, uint32_t constant1,
                                                     const GpuTextures& textures) {
  return {constant0, constant1, textures.has_images() ? material_textures : 0u};
}

}  // namespace sg
