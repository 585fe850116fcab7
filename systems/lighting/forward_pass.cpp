// SPDX-License-Identifier: MIT
#include "systems/lighting/forward_pass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/scene.frag.spv.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/scene/mesh_library.h"
#include "systems/shadow_maps/shadow_atlas.h"
#include "systems/shadows/gpu_light.h"

namespace sg {
namespace {

using namespace bindings;
constexpr VkShaderStageFlags both_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

}  // namespace

ForwardPass::ForwardPass(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures)
    : context_(context),
      textures_(textures),
      light_resources_(context),
      layout_(context.device(), lit_camera_bindings(), vk::push_constants<FrameConstants>(both_stages)),
      slot_sets_(layout_.allocate_sets(frames_in_flight)) {
  // The textures never change: bind them once in every slot's set.
  for (const VkDescriptorSet set : slot_sets_.sets) {
    layout_.write(set).image(material_textures_binding, textures.array().view(), textures.sampler()).update();
  }
}

void ForwardPass::prepare(uint32_t slot, const GpuScene& scene, const vk::Buffer& lights,
                          const ShadowAtlas& shadow_atlas, LightingView view) {
  view_ = view;
  pipelines_
      .try_emplace(static_cast<uint32_t>(view),
                   [layout = layout_.get(), &textures = textures_, &resources = light_resources_,
                    view](uint32_t draw_class) {
                     vk::GraphicsPipelineDesc desc =
                         camera_pipeline_desc(scene_frag, {vk::to_vk(lit_sum_format)}, layout, "forward");
                     // Constant 0 is unused here, 1 is light_shading.glsl's view, 3 every light type.
                     std::vector<uint32_t> constants =
                         material_pass_constants(0, static_cast<uint32_t>(view), textures);
                     constants.push_back(shadows::all_light_type_bits);
                     desc.fragment_specialization = resources.specialized(std::move(constants));
                     return for_draw_class(std::move(desc), draw_class);
                   })
      .first->second.prepare(context_, scene);
  const vk::Image& atlas = shadow_atlas.image();
  const VkImageView atlas_view =
      atlas.views().get({0, 1, 0, atlas.array_layers(), VK_IMAGE_VIEW_TYPE_2D_ARRAY});
  vk::DescriptorWriter writer = layout_.write(slot_sets_.sets[slot]);
  writer.buffer(instances_binding, scene.instances(slot).handle());
  light_resources_.write(writer, lights, atlas_view).update();
}

ForwardTargets ForwardPass::add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height,
                                   rg::ImageHandle atlas, const GpuScene& scene, uint32_t slot,
                                   const FrameConstants& constants) const {
  ForwardTargets targets;
  graph.add_pass(
      "forward",
      [&](rg::PassBuilder& b) {
        b.read(atlas, rg::Usage::sampled_fragment);
        targets.depth = b.write(b.create_image("depth", {width, height, camera_depth_format}),
                                rg::Usage::depth_attachment, camera_depth_clear);
        targets.lit_sum =
            b.write(b.create_image("lit sum", {width, height, lit_sum_format}), rg::Usage::color_attachment,
                    rg::ClearValue::color_of(background_color.r, background_color.g, background_color.b));
      },
      [this, &scene, slot, constants,
       pipelines = pipelines_.at(static_cast<uint32_t>(view_)).get()](const vk::PassRecorder& rec) {
        scene.draw_camera_pass(rec, pipelines, layout_, slot_sets_.sets[slot], constants, slot);
      });
  return targets;
}

}  // namespace sg
