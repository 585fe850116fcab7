// SPDX-License-Identifier: MIT
#include "systems/lighting/camera_pipelines.h"

#include <bit>
#include <string>

#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/scene.vert.spv.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/lighting/light_resources.h"

namespace sg {

std::vector<VkDescriptorSetLayoutBinding> lit_camera_bindings(
    std::vector<VkDescriptorSetLayoutBinding> more) {
  constexpr VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;
  more.insert(more.begin(), {{bindings::instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                              VK_SHADER_STAGE_VERTEX_BIT | fragment, nullptr},
                             {bindings::material_textures_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                              1, fragment, nullptr}});
  return LightResources::bindings(LightRecordsIn::texel_buffer, fragment, std::move(more));
}

vk::GraphicsPipelineDesc camera_pipeline_desc(std::span<const uint32_t> fragment,
                                              std::vector<VkFormat> color_formats, VkPipelineLayout layout,
                                              std::string name) {
  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = scene_vert;
  desc.fragment_spirv = fragment;
  scene_vertex_input(desc, VertexInput::surface);
  desc.color_formats = std::move(color_formats);
  desc.depth_format = vk::to_vk(camera_depth_format);
  desc.depth_compare = camera_depth_test;
  desc.layout = layout;
  desc.name = std::move(name);
  return desc;
}

void CameraPipelines::prepare(vk::VulkanContext& context, const GpuScene& scene) {
  for (uint32_t draw_class = 0; draw_class < draw_class_count; ++draw_class) {
    const bool of_its_kind = ((draw_class & draw_blended) != 0) == transparent_;
    if (of_its_kind && !pipelines_[draw_class] && scene.has_draw_class(draw_class)) {
      pipelines_[draw_class] = vk::create_graphics_pipeline(context, desc_of_(draw_class));
    }
  }
}

std::array<VkPipeline, draw_class_count> CameraPipelines::get() const {
  std::array<VkPipeline, draw_class_count> out{};
  for (uint32_t draw_class = 0; draw_class < draw_class_count; ++draw_class) {
    out[draw_class] = pipelines_[draw_class].get();
  }
  return out;
}

vk::GraphicsPipelineDesc for_draw_class(vk::GraphicsPipelineDesc desc, uint32_t draw_class) {
  if (draw_class & draw_double_sided) {
    desc.cull_mode = VK_CULL_MODE_NONE;
    desc.name += " double-sided";
  }
  if (draw_class & draw_masked) {
    desc.fragment_specialization.at(material_features_constant) |= material_cut_out;
    desc.name += " masked";
  }
  return desc;
}

vk::GraphicsPipelineDesc after_depth_prepass(vk::GraphicsPipelineDesc desc) {
  desc.depth_compare = camera_depth_retest;
  desc.depth_write = false;
  return desc;
}

std::span<const uint32_t> for_groups(uint32_t groups, std::span<const uint32_t> every,
                                     const std::array<std::span<const uint32_t>, 4>& few) {
  const auto present = static_cast<size_t>(std::popcount(groups));
  return present >= 1 && present <= few.size() ? few[present - 1] : every;
}

std::vector<uint32_t> all_groups_pass_constants(const shadows::GroupsPresent& groups, LightingView view,
                                                const GpuTextures& textures) {
  std::vector<uint32_t> constants =
      material_pass_constants(groups.present, static_cast<uint32_t>(view), textures);
  constants.push_back(groups.light_types);
  constants.push_back(groups.single);
  constants.push_back(groups.group_types);
  constants.push_back(shadows::group_slot_list(groups.present));
  return constants;
}

}  // namespace sg
