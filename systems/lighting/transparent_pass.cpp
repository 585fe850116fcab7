// SPDX-License-Identifier: MIT
#include "systems/lighting/transparent_pass.h"

#include <optional>
#include <span>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/scene_fused_transparent.frag.spv.h"
#include "shaders/scene_fused_transparent_groups_1.frag.spv.h"
#include "shaders/scene_fused_transparent_groups_2.frag.spv.h"
#include "shaders/scene_fused_transparent_groups_3.frag.spv.h"
#include "shaders/scene_fused_transparent_groups_4.frag.spv.h"
#include "shaders/transparent_tiled.frag.spv.h"
#include "shaders/transparent_tiled_groups_1.frag.spv.h"
#include "shaders/transparent_tiled_groups_2.frag.spv.h"
#include "shaders/transparent_tiled_groups_3.frag.spv.h"
#include "shaders/transparent_tiled_groups_4.frag.spv.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/lighting/transparent_tile_bounds.h"

namespace sg {
namespace {

using namespace bindings;
constexpr VkShaderStageFlags both_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;

// The groups take GroupsPresent::key_bits, the view the next bit, tiled the next, the format the rest.
uint64_t pipeline_key(rg::Format format, bool tiled, const shadows::GroupsPresent& groups,
                      LightingView view) {
  constexpr uint32_t bits = shadows::GroupsPresent::key_bits;
  return groups.key() | static_cast<uint64_t>(view) << bits | static_cast<uint64_t>(tiled) << (bits + 1) |
         static_cast<uint64_t>(format) << (bits + 2);
}

}  // namespace

TransparentPass::TransparentPass(vk::VulkanContext& context, uint32_t frames_in_flight,
                                 const GpuTextures& textures)
    : context_(context),
      textures_(textures),
      light_resources_(context),
      light_tiles_(context, frames_in_flight, LightCullingShape::automatic, true),
      tile_bounds_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "transparent tile bounds"),
      tiled_layout_(context.device(),
                    lit_camera_bindings(
                        {{tile_lights_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, fragment, nullptr},
                         {tile_ranges_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, fragment, nullptr}}),
                    vk::push_constants<FrameConstants>(both_stages)),
      every_light_layout_(context.device(), lit_camera_bindings(),
                          vk::push_constants<FrameConstants>(both_stages)) {}

void TransparentPass::prepare(rg::Format format, bool tiled, const shadows::GroupsPresent& groups,
                              LightingView view, const GpuScene& scene, uint32_t slot,
                              const glm::mat4& view_projection, glm::uvec2 screen) {
  tiled_ = tiled;
  if (tiled) {
    boxes_.clear();
    const std::span<const scene::Aabb> bounds = scene.instance_bounds();
    for (const uint32_t i : scene.transparent_order()) boxes_.push_back(bounds[i]);
    transparent_tile_bounds(view_projection, LightTileGrid::of(screen.x, screen.y), screen, boxes_, bounds_);
    tile_bounds_.write(slot, std::span<const glm::vec2>(bounds_));
  }
  key_ = pipeline_key(format, tiled, groups, view);
  const VkPipelineLayout layout = (tiled ? tiled_layout_ : every_light_layout_).get();
  const std::span<const uint32_t> fragment_shader =
      tiled ? for_groups(groups.present, transparent_tiled_frag,
                         {transparent_tiled_groups_1_frag, transparent_tiled_groups_2_frag,
                          transparent_tiled_groups_3_frag, transparent_tiled_groups_4_frag})
            : for_groups(groups.present, scene_fused_transparent_frag,
                         {scene_fused_transparent_groups_1_frag, scene_fused_transparent_groups_2_frag,
                          scene_fused_transparent_groups_3_frag, scene_fused_transparent_groups_4_frag});
  pipelines_
      .try_emplace(
          key_,
          [layout, fragment_shader, &textures = textures_, &resources = light_resources_, format, groups,
           view](uint32_t draw_class) {
            vk::GraphicsPipelineDesc desc =
                camera_pipeline_desc(fragment_shader, {vk::to_vk(format)}, layout, "transparent");
            desc.fragment_specialization =
                resources.specialized(all_groups_pass_constants(groups, view, textures));
            desc.depth_write = false;  // sorted, not depth-tested among themselves
            desc.blend = vk::Blend::alpha;
            return for_draw_class(std::move(desc), draw_class);
          },
          true)
      .first->second.prepare(context_, scene);
}

rg::ImageHandle TransparentPass::add_to(rg::RenderGraph& graph, rg::ImageHandle target, rg::ImageHandle depth,
                                        rg::ImageHandle atlas, const vk::Buffer& lights, uint32_t light_count,
                                        const GpuScene& scene, uint32_t slot,
                                        const FrameConstants& constants) const {
  std::optional<LightTiles> tiles;
  if (tiled_) {
    tiles = light_tiles_.add_to(graph, slot, depth, lights, light_count, constants.view_projection, nullptr,
                                &tile_bounds_.buffer(slot));
  }
  graph.add_pass(
      "transparent",
      [&](rg::PassBuilder& b) {
        b.read(atlas, rg::Usage::sampled_fragment);
        if (tiles) {
          b.read(tiles->lights, rg::Usage::storage_fragment);
          b.read(tiles->ranges, rg::Usage::storage_fragment);
        }
        b.read(depth, rg::Usage::depth_attachment);  // tested, not written
        target = b.write(target, rg::Usage::color_attachment);
      },
      [this, &scene, &lights, slot, constants, tiles, atlas,
       pipelines = pipelines_.at(key_).get()](const vk::PassRecorder& rec) {
        const vk::PipelineLayout& layout = tiles ? tiled_layout_ : every_light_layout_;
        vk::DescriptorWriter writer = layout.write(rec.allocate_set(layout));
        writer.buffer(instances_binding, scene.instances(slot).handle())
            .image(material_textures_binding, textures_.array().view(), textures_.sampler());
        if (tiles) {
          writer.buffer(tile_lights_binding, rec.buffer(tiles->lights))
              .buffer(tile_ranges_binding, rec.buffer(tiles->ranges));
        }
        const VkDescriptorSet set = light_resources_.write(writer, lights, rec, atlas).update();
        scene.draw_transparent(rec, pipelines, layout, set, constants);
      });
  return target;
}

}  // namespace sg
