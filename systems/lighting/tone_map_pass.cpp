// SPDX-License-Identifier: MIT
#include "systems/lighting/tone_map_pass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/fullscreen.vert.spv.h"
#include "shaders/tone_map.frag.spv.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {

ToneMapPass::ToneMapPass(vk::VulkanContext& context, rg::Format output_format)
    : layout_(context.device(),
              {{bindings::hdr_binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<float>(VK_SHADER_STAGE_FRAGMENT_BIT)),
      pipeline_(vk::create_graphics_pipeline(context, {.vertex_spirv = fullscreen_vert,
                                                       .fragment_spirv = tone_map_frag,
                                                       .color_formats = {vk::to_vk(output_format)},
                                                       .cull_mode = VK_CULL_MODE_NONE,
                                                       .layout = layout_.get(),
                                                       .name = "tone map"})) {}

rg::ImageHandle ToneMapPass::add_to(rg::RenderGraph& graph, rg::ImageHandle lit_sum, rg::ImageHandle output,
                                    float exposure) const {
  graph.add_pass(
      "tone map",
      [&](rg::PassBuilder& b) {
        b.read(lit_sum, rg::Usage::storage_fragment);
        output = b.write(output, rg::Usage::color_attachment);  // every pixel is written
      },
      [this, lit_sum, exposure](const vk::PassRecorder& rec) {
        rec.set_full_viewport();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        layout_.bind(rec.cmd(), layout_.write(rec.allocate_set(layout_))
                                    .image(bindings::hdr_binding, rec.view(lit_sum), VK_NULL_HANDLE,
                                           VK_IMAGE_LAYOUT_GENERAL)
                                    .update());
        layout_.push(rec.cmd(), exposure);
        vkCmdDraw(rec.cmd(), 3, 1, 0, 0);
      });
  return output;
}

}  // namespace sg
