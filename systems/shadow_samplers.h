#pragma once
// The samplers every lighting pass reads shadow maps with (shaders/shadow_sampling.glsl): plain
// nearest reads, and a comparison sampler whose linear filter makes each fetch a hardware 2x2
// PCF (nearest where the device cannot filter the depth format).
#include "rendergraph/device/unique_handle.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

struct ShadowSamplers {
  vk::UniqueSampler nearest;
  vk::UniqueSampler compare;
};

ShadowSamplers create_shadow_samplers(const vk::VulkanContext& context);

}  // namespace sg
