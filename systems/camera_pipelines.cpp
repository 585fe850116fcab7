#include "systems/camera_pipelines.h"

#include <string>

#include "systems/gpu_textures.h"

namespace sg {

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

}  // namespace sg
