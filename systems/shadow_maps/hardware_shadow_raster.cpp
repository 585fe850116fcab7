// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/hardware_shadow_raster.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_batch.vert.spv.h"
#include "shaders/shadow_batch_cut_out.vert.spv.h"
#include "shaders/shadow_cube.frag.spv.h"
#include "shaders/shadow_cube_cut_out.frag.spv.h"
#include "shaders/shadow_cut_out.frag.spv.h"
#include "shaders/shadow_scatter.comp.spv.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/shadow_maps/shadow_atlas.h"

namespace sg {
namespace {

using namespace bindings;
using namespace shadow_batch;

VkClearRect tile_clear(const shadows::AtlasTile& tile) {
  return {{{int32_t(tile.x), int32_t(tile.y)}, {tile.size, tile.size}}, tile.page, 1};
}

}  // namespace

void HardwareShadowRaster::prepare(const ShadowBatchFrame& frame) {
  clears_.resize(frame.tiles.size());
  std::transform(frame.tiles.begin(), frame.tiles.end(), clears_.begin(), tile_clear);
}

HardwareShadowRaster::HardwareShadowRaster(vk::VulkanContext& context, const GpuTextures& textures)
    : context_(context),
      textures_(textures),
      scatter_layout_(context.device(),
                      {{shadow_views_binding, storage, 1, compute},
                       {shadow_casters_binding, storage, 1, compute},
                       {culled_pairs_binding, storage, 1, compute},
                       {draw_counts_binding, storage, 1, compute},
                       {view_instances_binding, storage, 1, compute}},
                      vk::push_constants<BatchConstants>(compute)),
      raster_layout_(context.device(), {{instances_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                        {shadow_views_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                        {view_instances_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                        {material_textures_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                         1, VK_SHADER_STAGE_FRAGMENT_BIT}}),
      scatter_pipeline_(vk::create_compute_pipeline(
          context, {shadow_scatter_comp, {}, scatter_layout_.get(), "shadow scatter"})),
      opaque_(make_pipelines(false)) {}

HardwareShadowRaster::Pipelines HardwareShadowRaster::make_pipelines(bool cut_out) const {
  using Spirv = std::span<const uint32_t>;
  vk::GraphicsPipelineDesc desc = cut_out ? shadow_cut_out_pipeline_desc(raster_layout_.get(), textures_)
                                          : shadow_pipeline_desc(raster_layout_.get());
  const std::string suffix = cut_out ? " cut out" : "";
  Pipelines made;
  desc.vertex_spirv = cut_out ? Spirv(shadow_batch_cut_out_vert) : Spirv(shadow_batch_vert);
  if (cut_out) desc.fragment_spirv = shadow_cut_out_frag;  // 2D maps need none otherwise
  desc.name = "shadow batch maps" + suffix;
  made.map = vk::create_graphics_pipeline(context_, desc);
  desc.fragment_spirv = cut_out ? Spirv(shadow_cube_cut_out_frag) : Spirv(shadow_cube_frag);
  desc.name = "shadow batch cube faces" + suffix;
  made.face = vk::create_graphics_pipeline(context_, desc);
  return made;
}

void HardwareShadowRaster::make_cut_out_pipelines() {
  if (!cut_out_.map) cut_out_ = make_pipelines(true);
}

rg::ImageHandle HardwareShadowRaster::add_to(rg::RenderGraph& graph, rg::ImageHandle atlas,
                                             const ShadowBatchFrame& frame, const CulledPairs& culled,
                                             const GpuScene& scene, uint32_t slot) const {
  const BatchConstants constants{frame.casters, frame.caster_groups,
                                 static_cast<uint32_t>(culled.capacity[0]), 0u};
  rg::BufferHandle counts = culled.counts;
  rg::BufferHandle sorted;
  if (culled.draws.valid()) {
    // Execute gets the sorted pairs from setup: they do not exist before it runs.
    graph.add_pass(
        "shadow scatter",
        [&](rg::PassBuilder& p) {
          p.read(culled.draws, rg::Usage::indirect);
          p.read(culled.pairs, rg::Usage::storage_compute);
          counts = p.write(counts, rg::Usage::storage_compute);
          sorted = p.write(
              p.create_buffer("shadow sorted pairs",
                              {shadow_batch::frame_steady(culled.capacity[0] * shadow_batch::pair_bytes)}),
              rg::Usage::storage_compute);
          return sorted;
        },
        [this, constants, frame, culled, counts](rg::BufferHandle sorted, const vk::PassRecorder& rec) {
          const VkDescriptorSet set = scatter_layout_.write(rec.allocate_set(scatter_layout_))
                                          .buffer(shadow_views_binding, frame.view_records)
                                          .buffer(shadow_casters_binding, frame.caster_records)
                                          .buffer(culled_pairs_binding, rec.buffer(culled.pairs))
                                          .buffer(draw_counts_binding, rec.buffer(counts))
                                          .buffer(view_instances_binding, rec.buffer(sorted))
                                          .update();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, scatter_pipeline_.get());
          scatter_layout_.bind_compute(rec.cmd(), set);
          scatter_layout_.push(rec.cmd(), constants);
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(culled.draws), shadow_batch::scatter_dispatch_offset);
        });
  }
  graph.add_pass(
      "shadow views",
      [&](rg::PassBuilder& p) {
        if (culled.draws.valid()) {
          p.read(culled.draws, rg::Usage::indirect);
          p.read(sorted, rg::Usage::storage_vertex);
        }
        atlas = p.write(atlas, rg::Usage::depth_attachment);  // kept: cached tiles stay
      },
      [this, &scene, slot, frame, draws = culled.draws, sorted](const vk::PassRecorder& rec) {
        const VkClearAttachment far{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {.depthStencil = {1.0f, 0}}};
        vkCmdClearAttachments(rec.cmd(), 1, &far, static_cast<uint32_t>(clears_.size()), clears_.data());
        if (!draws.valid() || !scene.bind_geometry(rec.cmd())) return;
        rec.set_full_viewport();
        const VkDescriptorSet set =
            raster_layout_.write(rec.allocate_set(raster_layout_))
                .buffer(instances_binding, scene.instances(slot).handle())
                .buffer(shadow_views_binding, frame.view_records)
                .buffer(view_instances_binding, rec.buffer(sorted))
                .image(material_textures_binding, textures_.array().view(), textures_.sampler())
                .update();
        raster_layout_.bind(rec.cmd(), set);
        // Per view kind, its draws by caster group: the opaque groups', then the cut-out ones'.
        const VkBuffer commands = rec.buffer(draws);
        constexpr VkDeviceSize stride = sizeof(VkDrawIndexedIndirectCommand);
        const uint32_t groups = frame.caster_groups;
        const uint32_t opaque = frame.first_cut_out_group;
        const auto draw = [&](VkPipeline pipeline, uint32_t first, uint32_t count) {
          if (count == 0) return;
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
          vkCmdDrawIndexedIndirect(rec.cmd(), commands, shadow_batch::draws_header_bytes + first * stride,
                                   count, stride);
        };
        draw(opaque_.map.get(), 0, opaque);
        draw(cut_out_.map.get(), opaque, groups - opaque);
        draw(opaque_.face.get(), groups, opaque);
        draw(cut_out_.face.get(), groups + opaque, groups - opaque);
      });
  return atlas;
}

}  // namespace sg
