// SPDX-License-Identifier: MIT
#include "sandbox/light_heatmap_pass.h"

#include <glm/glm.hpp>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "sandbox_shaders/light_heatmap.frag.spv.h"
#include "shaders/fullscreen.vert.spv.h"

namespace sg::sandbox {
namespace {

constexpr uint32_t ranges_binding = 0;
// Lights in a tile at which the color ramp reaches red.
constexpr float full_scale = 32.0f;

// light_heatmap.frag's HeatMap.
struct HeatMap {
  uint32_t tiles_across;
  float full_scale;
  glm::vec2 scene_per_frame;  // scene pixels per frame pixel, each axis (the sizes round apart)
};

}  // namespace

LightHeatmapPass::LightHeatmapPass(vk::VulkanContext& context, rg::Format color_format)
    : layout_(context.device(),
              {{ranges_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<HeatMap>(VK_SHADER_STAGE_FRAGMENT_BIT)),
      pipeline_(vk::create_graphics_pipeline(context, {.vertex_spirv = fullscreen_vert,
                                                       .fragment_spirv = light_heatmap_frag,
                                                       .color_formats = {vk::to_vk(color_format)},
                                                       .cull_mode = VK_CULL_MODE_NONE,
                                                       .blend = vk::Blend::alpha,
                                                       .layout = layout_.get(),
                                                       .name = "light heat map"})) {}

rg::ImageHandle LightHeatmapPass::add_to(rg::RenderGraph& graph, const LightTiles& tiles,
                                         rg::ImageHandle scene, rg::ImageHandle color) const {
  const rg::ImageDesc& culled = graph.resources()[scene.index].image;
  const LightTileGrid grid = LightTileGrid::of(culled.width, culled.height);
  const rg::ImageDesc& frame = graph.resources()[color.index].image;
  const glm::vec2 scene_per_frame(float(culled.width) / float(frame.width),
                                  float(culled.height) / float(frame.height));
  graph.add_pass(
      "light heat map",
      [&](rg::PassBuilder& b) {
        b.read(tiles.ranges, rg::Usage::storage_fragment);
        color = b.write(color, rg::Usage::color_attachment);  // no clear: over the frame
      },
      [this, ranges = tiles.ranges, grid, scene_per_frame](const vk::PassRecorder& rec) {
        rec.set_full_viewport();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        layout_.bind(
            rec.cmd(),
            layout_.write(rec.allocate_set(layout_)).buffer(ranges_binding, rec.buffer(ranges)).update());
        layout_.push(rec.cmd(), HeatMap{grid.across, full_scale, scene_per_frame});
        vkCmdDraw(rec.cmd(), 3, 1, 0, 0);
      });
  return color;
}

}  // namespace sg::sandbox
