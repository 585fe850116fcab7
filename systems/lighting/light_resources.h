// SPDX-License-Identifier: MIT
#pragma once
// What every pass that shades lights binds (shaders/lights_interface.glsl): the frame's light
// records and the shadow atlas, with the samplers shadow_sampling.glsl expects. Nearest reads,
// and a comparison sampler whose linear filter makes each fetch a hardware 2x2 PCF (nearest
// where the device cannot filter the depth format: shadow_comparisons_filter).
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/lighting/lighting_path.h"

namespace sg {

// The records' texel format where a shader reads them through a texel buffer (LightRecordsIn).
inline constexpr VkFormat light_record_texel_format = VK_FORMAT_R32G32B32A32_UINT;

// The comparison sampler's filter for a depth format with `features` (its optimal tiling's):
// linear, each comparison a bilinear 2x2, where the format can be filtered; nearest, one texel,
// where not (Debian 12's lavapipe cannot filter d32_sfloat; Mesa 25's can).
VkFilter comparison_filter(VkFormatFeatureFlags features);
// Whether `context`'s device filters the shadow atlas's comparisons (ShadowAtlas::depth_format).
bool shadow_comparisons_filter(const vk::VulkanContext& context);

class LightResources {
 public:
  // `records`: automatic reads the storage buffer on GPUs, the texel buffer on CPU devices.
  explicit LightResources(const vk::VulkanContext& context,
                          LightRecordsIn records = LightRecordsIn::texel_buffer);

  LightRecordsIn records() const { return records_; }  // resolved: never automatic

  // A lighting pipeline's specialization `constants` (constant_id i = constants[i]), which must
  // reach LIGHT_TYPES (3), with NEAREST_COMPARISONS (lights_interface.glsl's constant_id 10) set
  // where this device's comparisons read one texel. The ids it adds before 10 are 0, every
  // shader's default for them but the filter floor pass's own constant 6, which it sets itself.
  std::vector<uint32_t> specialized(std::vector<uint32_t> constants) const;

  // The bindings for `records` (not automatic), visible to `stages`, followed by a pass's own `more`.
  static std::vector<VkDescriptorSetLayoutBinding> bindings(LightRecordsIn records, VkShaderStageFlags stages,
                                                            std::vector<VkDescriptorSetLayoutBinding> more);

  // Writes the records (`lights`, the records' buffer; made with a texel view of format
  // light_record_texel_format) and the shadow atlas (`atlas`, a 2D array view of every page).
  vk::DescriptorWriter& write(vk::DescriptorWriter& writer, const vk::Buffer& lights,
                              VkImageView atlas) const;
  // The same inside a pass that declared the shadow atlas `atlas` of its graph.
  vk::DescriptorWriter& write(vk::DescriptorWriter& writer, const vk::Buffer& lights,
                              const vk::PassRecorder& rec, rg::ImageHandle atlas) const;

 private:
  LightRecordsIn records_;
  bool nearest_comparisons_;
  vk::UniqueSampler nearest_;
  vk::UniqueSampler compare_;
};

}  // namespace sg
