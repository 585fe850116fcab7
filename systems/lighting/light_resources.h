// SPDX-License-Identifier: MIT
#pragma once
// What every pass that shades lights binds (shaders/lights_interface.glsl): the frame's light
// records and the shadow atlas, with the samplers shadow_sampling.glsl expects. Nearest reads,
// and a comparison sampler whose linear filter makes each fetch a hardware 2x2 PCF (nearest
// where the device cannot filter the depth format).
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"

namespace sg {

// The lighting shaders read the records through a uniform texel buffer, a record being 16-byte
// texels (lights_interface.glsl): llvmpipe fetches texels for all lanes at once, where it loads
// storage-buffer words lane by lane, one loop per load.
inline constexpr VkFormat light_record_texel_format = VK_FORMAT_R32G32B32A32_UINT;

class LightResources {
 public:
  explicit LightResources(const vk::VulkanContext& context);

  // The bindings, visible to `stages`, followed by a pass's own `more`.
  static std::vector<VkDescriptorSetLayoutBinding> bindings(VkShaderStageFlags stages,
                                                            std::vector<VkDescriptorSetLayoutBinding> more);

  // Writes the records (`lights`, the texel view of the records' buffer, texel format
  // light_record_texel_format) and the shadow atlas (`atlas`, a 2D array view of every page).
  vk::DescriptorWriter& write(vk::DescriptorWriter& writer, VkBufferView lights, VkImageView atlas) const;
  // The same inside a pass that declared the shadow atlas `atlas` of its graph.
  vk::DescriptorWriter& write(vk::DescriptorWriter& writer, VkBufferView lights, const vk::PassRecorder& rec,
                              rg::ImageHandle atlas) const;

 private:
  vk::UniqueSampler nearest_;
  vk::UniqueSampler compare_;
};

}  // namespace sg
