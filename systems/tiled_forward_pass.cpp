#include "systems/tiled_forward_pass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/scene_tiled.frag.spv.h"
#include "systems/gpu_scene.h"
#include "systems/gpu_textures.h"
#include "systems/shader_bindings.h"

namespace sg {
namespace {

using namespace bindings;
constexpr VkShaderStageFlags both_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;

// Groups take the low light_group_count bits.
uint32_t pipeline_key(uint32_t groups_present, LightingView view) {
  return groups_present | static_cast<uint32_t>(view) << 16;
}

}  // namespace

TiledForwardPass::TiledForwardPass(vk::VulkanContext& context, const GpuTextures& textures)
    : context_(context),
      textures_(textures),
      light_resources_(context),
      layout_(context.device(),
              lit_camera_bindings(
                  {{tile_lights_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, fragment, nullptr},
                   {tile_ranges_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, fragment, nullptr}}),
              vk::push_constants<FrameConstants>(both_stages)) {}

void TiledForwardPass::prepare(const std::array<uint32_t, shadows::light_group_count + 1>& group_begin,
                               LightingView view, const GpuScene& scene) {
  view_ = view;
  groups_present_ = shadows::groups_present(group_begin);
  pipelines_
      .try_emplace(pipeline_key(groups_present_, view),
                   [layout = layout_.get(), &textures = textures_, groups = groups_present_,
                    view](uint32_t draw_class) {
                     vk::GraphicsPipelineDesc desc = camera_pipeline_desc(
                         scene_tiled_frag, {vk::to_vk(ForwardPass::lit_sum_format)}, layout, "tiled forward");
                     desc.fragment_specialization =
                         material_pass_constants(groups, static_cast<uint32_t>(view), textures);
                     return for_draw_class(after_depth_prepass(std::move(desc)), draw_class);
                   })
      .first->second.prepare(context_, scene);
}

ForwardTargets TiledForwardPass::add_to(rg::RenderGraph& graph, rg::ImageHandle depth,
                                        const LightTiles& tiles, rg::ImageHandle atlas,
                                        const vk::Buffer& lights, const GpuScene& scene, uint32_t slot,
                                        const FrameConstants& constants) const {
  const rg::ImageDesc& screen = graph.resources()[depth.index].image;
  ForwardTargets targets{{}, depth};
  graph.add_pass(
      "forward",
      [&](rg::PassBuilder& b) {
        b.read(atlas, rg::Usage::sampled_fragment);
        b.read(tiles.lights, rg::Usage::storage_fragment);
        b.read(tiles.ranges, rg::Usage::storage_fragment);
        targets.depth = b.write(depth, rg::Usage::depth_attachment);  // tested, not written
        targets.lit_sum =
            b.write(b.create_image("lit sum", {screen.width, screen.height, ForwardPass::lit_sum_format}),
                    rg::Usage::color_attachment,
                    rg::ClearValue::color_of(background_color.r, background_color.g, background_color.b));
      },
      [this, &scene, &lights, slot, constants, tiles, atlas,
       pipelines = pipelines_.at(pipeline_key(groups_present_, view_)).get()](const vk::PassRecorder& rec) {
        vk::DescriptorWriter writer = layout_.write(rec.allocate_set(layout_));
        writer.buffer(instances_binding, scene.instances(slot).handle())
            .image(material_textures_binding, textures_.array().view(), textures_.sampler())
            .buffer(tile_lights_binding, rec.buffer(tiles.lights))
            .buffer(tile_ranges_binding, rec.buffer(tiles.ranges));
        const VkDescriptorSet set = light_resources_.write(writer, lights.texel_view(), rec, atlas).update();
        scene.draw_camera_pass(rec, pipelines, layout_, set, constants, slot);
      });
  return targets;
}

}  // namespace sg
