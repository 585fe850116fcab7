// SPDX-License-Identifier: MIT
#include "fog_pass.h"

#include <cstdint>

#include "custom_pass/fog.frag.spv.h"
#include "custom_pass/fog.vert.spv.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"

namespace custom_pass {
namespace {

#include "shaders/fog_interface.glsl"

// Fog at its thickest from this many metres on: a room fades, a hall's far end is grey.
constexpr float thickest_at = 30.0f;

}  // namespace

FogPass::FogPass(sg::vk::VulkanContext& context, sg::rg::Format color_format)
    : sampler_(sg::vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
      layout_(
          context.device(),
          {{fog_depth_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}},
          sg::vk::push_constants<FogConstants>(VK_SHADER_STAGE_FRAGMENT_BIT)),
      pipeline_(sg::vk::create_graphics_pipeline(context, {.vertex_spirv = fog_vert,
                                                           .fragment_spirv = fog_frag,
                                                           .color_formats = {sg::vk::to_vk(color_format)},
                                                           .cull_mode = VK_CULL_MODE_NONE,
                                                           .blend = sg::vk::Blend::alpha,
                                                           .layout = layout_.get(),
                                                           .name = "fog"})) {}

sg::rg::ImageHandle FogPass::add_to(sg::rg::RenderGraph& graph, sg::rg::ImageHandle depth,
                                    sg::rg::ImageHandle color, const sg::scene::Camera& lens) const {
  graph.add_pass(
      "fog",
      [&](sg::rg::PassBuilder& b) {
        b.read(depth, sg::rg::Usage::sampled_fragment);
        color = b.write(color, sg::rg::Usage::color_attachment);  // no clear: blend over the frame
      },
      [this, depth, lens](const sg::vk::PassRecorder& rec) {
        const VkExtent2D full = rec.render_extent();
        rec.set_viewport({{0, 0}, {full.width / 2, full.height}});
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        layout_.bind(rec.cmd(), layout_.write(rec.allocate_set(layout_))
                                    .image(fog_depth_binding, rec.view(depth), sampler_.get())
                                    .update());
        layout_.push(rec.cmd(), FogConstants{lens.znear, lens.zfar, thickest_at, 0.8f, 0.7f, 0.75f, 0.8f});
        vkCmdDraw(rec.cmd(), 3, 1, 0, 0);
      });
  return color;
}

}  // namespace custom_pass
