// SPDX-License-Identifier: MIT
#include "sandbox/depth_overlay_pass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "sandbox_shaders/depth_overlay.frag.spv.h"
#include "shaders/fullscreen.vert.spv.h"

namespace sg::sandbox {
namespace {
#include "sandbox/shaders/depth_overlay_interface.glsl"

// Depths beyond this many metres all show black; a room or a hall reads well at this scale.
constexpr float shown_distance = 40.0f;
}  // namespace

DepthOverlayPass::DepthOverlayPass(vk::VulkanContext& context, rg::Format color_format)
    : sampler_(vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
      layout_(context.device(),
              {{depth_buffer_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<DepthOverlayLens>(VK_SHADER_STAGE_FRAGMENT_BIT)),
      pipeline_(vk::create_graphics_pipeline(context, {.vertex_spirv = fullscreen_vert,
                                                       .fragment_spirv = depth_overlay_frag,
                                                       .color_formats = {vk::to_vk(color_format)},
                                                       .cull_mode = VK_CULL_MODE_NONE,
                                                       .layout = layout_.get(),
                                                       .name = "depth overlay"})) {}

rg::ImageHandle DepthOverlayPass::add_to(rg::RenderGraph& graph, rg::ImageHandle depth, rg::ImageHandle color,
                                         const scene::Camera& lens) const {
  graph.add_pass(
      "depth overlay",
      [&](rg::PassBuilder& b) {
        b.read(depth, rg::Usage::sampled_fragment);
        color = b.write(color, rg::Usage::color_attachment);  // no clear: draw over the frame
      },
      [this, depth, lens](const vk::PassRecorder& rec) {
        const VkExtent2D full = rec.render_extent();
        const VkExtent2D quarter{full.width / 2, full.height / 2};
        rec.set_viewport(
            {{int32_t(full.width - quarter.width), int32_t(full.height - quarter.height)}, quarter});
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        layout_.bind(rec.cmd(), layout_.write(rec.allocate_set(layout_))
                                    .image(depth_buffer_binding, rec.view(depth), sampler_.get())
                                    .update());
        layout_.push(rec.cmd(), DepthOverlayLens{lens.znear, lens.zfar, shown_distance});
        vkCmdDraw(rec.cmd(), 3, 1, 0, 0);
      });
  return color;
}

}  // namespace sg::sandbox
