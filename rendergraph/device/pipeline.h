// SPDX-License-Identifier: MIT
#pragma once
// Graphics pipelines for dynamic rendering (no render pass objects), built from a plain
// description. Viewport and scissor are dynamic so pipelines survive window resizes.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/unique_handle.h"

namespace sg::vk {

class VulkanContext;

UniqueShaderModule create_shader_module(VulkanContext& context, std::span<const uint32_t> spirv);

// How a fragment's color meets the attachment's.
enum class Blend {
  none,   // replaces it
  alpha,  // color = src * src alpha + dst * (1 - src alpha), for overlays
  add,    // color = src + dst, for sums built pass by pass
};

struct GraphicsPipelineDesc {
  std::span<const uint32_t> vertex_spirv;
  std::span<const uint32_t> fragment_spirv;  // empty for depth-only pipelines
  // fragment_specialization[i] is the fragment shader's `constant_id = i` (32-bit values).
  std::vector<uint32_t> fragment_specialization;
  std::vector<VkVertexInputBindingDescription> vertex_bindings;
  std::vector<VkVertexInputAttributeDescription> vertex_attributes;
  std::vector<VkFormat> color_formats;
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
  bool depth_write = true;
  VkCullModeFlags cull_mode = VK_CULL_MODE_BACK_BIT;
  VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  Blend blend = Blend::none;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  std::string name;
};

UniquePipeline create_graphics_pipeline(VulkanContext& context, const GraphicsPipelineDesc& desc);

// A compute pipeline. `specialization[i]` is the value of the shader's `constant_id = i` (32-bit
// integers or bools), so one shader serves variants whose branches are resolved at compile time.
struct ComputePipelineDesc {
  std::span<const uint32_t> spirv;
  std::vector<uint32_t> specialization;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  std::string name;
};

UniquePipeline create_compute_pipeline(VulkanContext& context, const ComputePipelineDesc& desc);

}  // namespace sg::vk
