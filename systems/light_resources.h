#pragma once
// What every pass that shades lights binds (shaders/lights_interface.glsl): the frame's light
// records and the shadow atlas, with the samplers shadow_sampling.glsl expects. Nearest reads,
// and a comparison sampler whose linear filter makes each fetch a hardware 2x2 PCF (nearest
// where the device cannot filter the depth format).
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/unique_handle.h"

namespace sg::vk {
class PassRecorder;
class VulkanContext;
}  // namespace sg::vk

namespace sg {

class LightResources {
 public:
  explicit LightResources(const vk::VulkanContext& context);

  // The bindings, visible to `stages`, followed by a pass's own `more`.
  static std::vector<VkDescriptorSetLayoutBinding> bindings(VkShaderStageFlags stages,
                                                            std::vector<VkDescriptorSetLayoutBinding> more);

  // Writes the records and the shadow atlas (`atlas`, a 2D array view of every page).
  vk::DescriptorWriter& write(vk::DescriptorWriter& writer, VkBuffer lights, VkImageView atlas) const;
  // The same inside a pass that declared the shadow atlas `atlas` of its graph.
  vk::DescriptorWriter& write(vk::DescriptorWriter& writer, VkBuffer lights, const vk::PassRecorder& rec,
                              rg::ImageHandle atlas) const;

 private:
  vk::UniqueSampler nearest_;
  vk::UniqueSampler compare_;
};

}  // namespace sg
