#pragma once
// The scene's decoded images on the GPU, as the layers of one sRGB 2D array that the lighting
// pass samples with the material's texture index as the layer (shaders/scene.frag). One array
// needs no descriptor indexing (lavapipe has none) and lets instances of one draw use different
// textures. The layers are square, the largest image's longer side rounded up to a power of
// two and at most max_layer_size; smaller or non-square images are resampled to it, which
// keeps their uv mapping. A scene without textures gets one white layer, so the array exists.
#include <cstdint>

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

 private:
  vk::Image array_;
  vk::UniqueSampler sampler_;
  uint32_t layers_ = 0;
};

}  // namespace sg
