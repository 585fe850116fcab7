// SPDX-License-Identifier: MIT
#include "systems/lighting/fused_forward_pass.h"

#include <bit>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/scene_fused.frag.spv.h"
#include "shaders/scene_fused_groups_1.frag.spv.h"
#include "shaders/scene_fused_groups_2.frag.spv.h"
#include "shaders/scene_fused_groups_3.frag.spv.h"
#include "shaders/scene_fused_groups_4.frag.spv.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {
namespace {

// The tone curve of shaders/tone_map.glsl, compiled here as C++, for the background's clear color.
namespace glsl {
using namespace glm;
#include "shaders/tone_map.glsl"
}  // namespace glsl

using namespace bindings;
constexpr VkShaderStageFlags both_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

}  // namespace

FusedForwardPass::FusedForwardPass(vk::VulkanContext& context, const GpuTextures& textures,
                                   rg::Format frame_format)
    : context_(context),
      textures_(textures),
      frame_format_(frame_format),
      light_resources_(context),
      layout_(context.device(), lit_camera_bindings(), vk::push_constants<FrameConstants>(both_stages)) {}

void FusedForwardPass::prepare(const shadows::GroupsPresent& groups, LightingView view,
                               const GpuScene& scene) {
  key_ = groups.key() | uint64_t{static_cast<uint32_t>(view)} << shadows::GroupsPresent::key_bits;
  pipelines_
      .try_emplace(key_,
                   [layout = layout_.get(), &textures = textures_, &resources = light_resources_,
                    format = frame_format_, groups, view](uint32_t draw_class) {
                     vk::GraphicsPipelineDesc desc = camera_pipeline_desc(
                         for_groups(groups.present, scene_fused_frag,
                                    {scene_fused_groups_1_frag, scene_fused_groups_2_frag,
                                     scene_fused_groups_3_frag, scene_fused_groups_4_frag}),
                         {vk::to_vk(format)}, layout, "fused forward");
                     desc.fragment_specialization =
                         resources.specialized(all_groups_pass_constants(groups, view, textures));
                     return for_draw_class(after_depth_prepass(std::move(desc)), draw_class);
                   })
      .first->second.prepare(context_, scene);
}

FusedTargets FusedForwardPass::add_to(rg::RenderGraph& graph, rg::ImageHandle depth, rg::ImageHandle frame,
                                      rg::ImageHandle atlas, const vk::Buffer& lights, const GpuScene& scene,
                                      uint32_t slot, FrameConstants constants, float exposure) const {
  constants = tone_mapping(constants, exposure);
  const glm::vec3 background = glsl::tone_map(background_color, exposure);
  FusedTargets targets;
  graph.add_pass(
      "fused forward",
      [&](rg::PassBuilder& b) {
        b.read(atlas, rg::Usage::sampled_fragment);
        targets.depth = b.write(depth, rg::Usage::depth_attachment);  // tested, not written
        targets.frame = b.write(frame, rg::Usage::color_attachment,
                                rg::ClearValue::color_of(background.r, background.g, background.b));
      },
      [this, &scene, &lights, slot, constants, atlas,
       pipelines = pipelines_.at(key_).get()](const vk::PassRecorder& rec) {
        vk::DescriptorWriter writer = layout_.write(rec.allocate_set(layout_));
        writer.buffer(instances_binding, scene.instances(slot).handle())
            .image(material_textures_binding, textures_.array().view(), textures_.sampler());
        const VkDescriptorSet set = light_resources_.write(writer, lights, rec, atlas).update();
        scene.draw_camera_pass(rec, pipelines, layout_, set, constants, slot);
      });
  return targets;
}

}  // namespace sg
