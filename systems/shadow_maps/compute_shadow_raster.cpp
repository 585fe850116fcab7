// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/compute_shadow_raster.h"

#include <cstdio>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_depth_copy.frag.spv.h"
#include "shaders/shadow_depth_copy.vert.spv.h"
#include "shaders/shadow_raster.comp.spv.h"
#include "shaders/shadow_raster_cut_out.comp.spv.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/shadow_maps/shadow_atlas.h"

namespace sg {
namespace {

using namespace bindings;
using namespace shadow_batch;

// Rectangles of due tiles from this size on are copied into the atlas, the views of smaller ones
// drawn: a copy pays for each rectangle (about 2 us on the H200, docs/PERFORMANCE.md), a draw
// writing depth from its fragment shader pays more than a copy for each texel. H100, 1920x1080,
// the stress hall, GPU frame, ms: 100,000 lights from afar (4,096 views of 16-64 texels a frame)
// 11.84 copying every rectangle, 11.36 drawing every view, 11.39 from 16,384 texels; at eye height
// 25.05, 24.52 and 24.56; 1,024 lights at eye height (tiles of 64-512 texels, cube faces side by
// side) 6.36, 7.24 and 6.35, and 6.51 from 65,536 texels (2026-12-05).
constexpr uint64_t copied_texels = 16384;

}  // namespace

ComputeShadowRaster::ComputeShadowRaster(vk::VulkanContext& context, const GpuTextures& textures,
                                         bool with_pipelines)
    : context_(context),
      textures_(textures),
      layout_(context.device(),
              {{instances_binding, storage, 1, compute},
               {shadow_views_binding, storage, 1, compute},
               {shadow_casters_binding, storage, 1, compute},
               {caster_meshes_binding, storage, 1, compute},
               {culled_pairs_binding, storage, 1, compute},
               {draw_counts_binding, storage, 1, compute},
               {shadow_depths_binding, storage, 1, compute},
               {mesh_vertices_binding, storage, 1, compute},
               {mesh_indices_binding, storage, 1, compute},
               {material_textures_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute}},
              vk::push_constants<BatchConstants>(compute)),
      copy_layout_(context.device(), {{shadow_views_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                      {shadow_depths_binding, storage, 1, VK_SHADER_STAGE_FRAGMENT_BIT}}) {
  if (!with_pipelines) return;
  if (context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
    std::printf(
        "shadowgraph: compute shadow raster on a CPU device: slow, and Debian 12's llvmpipe stops a "
        "shader's loops after 65,535 iterations, which can leave tiles over 512 texels incomplete\n");
  }
  pipeline_ = vk::create_compute_pipeline(context, {shadow_raster_comp, {}, layout_.get(), "shadow raster"});
  vk::GraphicsPipelineDesc copy;
  copy.vertex_spirv = shadow_depth_copy_vert;
  copy.fragment_spirv = shadow_depth_copy_frag;
  copy.depth_format = vk::to_vk(ShadowAtlas::depth_format);
  copy.depth_compare = VK_COMPARE_OP_ALWAYS;  // the view's new depths replace its tile's
  copy.cull_mode = VK_CULL_MODE_NONE;
  copy.layout = copy_layout_.get();
  copy.name = "shadow copy draw";
  copy_pipeline_ = vk::create_graphics_pipeline(context, copy);
  static_layers_.emplace(context);
}

void ComputeShadowRaster::make_cut_out_pipeline() {
  if (!pipeline_ || cut_out_pipeline_) return;
  cut_out_pipeline_ = vk::create_compute_pipeline(
      context_, {shadow_raster_cut_out_comp, material_pass_constants(0, 0, textures_), layout_.get(),
                 "shadow raster cut out"});
}

void ComputeShadowRaster::place_depths(std::span<const shadows::AtlasTile> tiles) {
  if (!placement_.place(tiles, copied_texels)) return;
  copies_.clear();
  for (const shadows::DepthRegion& region : placement_.copied()) {
    VkBufferImageCopy copy{};
    copy.bufferOffset = region.offset * sizeof(float);
    copy.bufferRowLength = region.width;
    copy.bufferImageHeight = region.height;
    copy.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, region.corner.page, 1};
    copy.imageOffset = {int32_t(region.corner.x), int32_t(region.corner.y), 0};
    copy.imageExtent = {region.width, region.height, 1};
    copies_.push_back(copy);
  }
}

void ComputeShadowRaster::add_raster(rg::RenderGraph& graph, const char* name, uint32_t list,
                                     const ShadowBatchFrame& frame, const CulledPairs& culled,
                                     const GpuScene& scene, uint32_t slot, rg::BufferHandle& depths) const {
  BatchConstants constants{frame.casters, frame.caster_groups, static_cast<uint32_t>(culled.capacity[list]),
                           0u};
  constants.list = list;
  const rg::BufferHandle pairs = list == 0 ? culled.pairs : culled.moving_pairs;
  const VkDeviceSize dispatch =
      list == 0 ? shadow_batch::raster_dispatch_offset : shadow_batch::moving_raster_dispatch_offset;
  graph.add_pass(
      name,
      [&](rg::PassBuilder& p) {
        p.read(culled.draws, rg::Usage::indirect);
        p.read(pairs, rg::Usage::storage_compute);
        p.read(culled.counts, rg::Usage::storage_compute);
        depths = p.write(depths, rg::Usage::storage_compute);
      },
      [this, &scene, slot, constants, frame, pairs, counts = culled.counts, draws = culled.draws, depths,
       dispatch](const vk::PassRecorder& rec) {
        const VkDescriptorSet set =
            layout_.write(rec.allocate_set(layout_))
                .buffer(instances_binding, scene.instances(slot).handle())
                .buffer(shadow_views_binding, frame.view_records)
                .buffer(shadow_casters_binding, frame.caster_records)
                .buffer(caster_meshes_binding, frame.mesh_records)
                .buffer(culled_pairs_binding, rec.buffer(pairs))
                .buffer(draw_counts_binding, rec.buffer(counts))
                .buffer(shadow_depths_binding, rec.buffer(depths))
                .buffer(mesh_vertices_binding, scene.vertices().handle())
                .buffer(mesh_indices_binding, scene.indices().handle())
                .image(material_textures_binding, textures_.array().view(), textures_.sampler())
                .update();
        layout_.bind_compute(rec.cmd(), set);
        layout_.push(rec.cmd(), constants);
        // Each variant takes its own casters' pairs (shaders/shadow_raster.comp).
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
        vkCmdDispatchIndirect(rec.cmd(), rec.buffer(draws), dispatch);
        if (frame.first_cut_out_group < frame.caster_groups) {
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, cut_out_pipeline_.get());
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(draws), dispatch);
        }
      });
}

rg::ImageHandle ComputeShadowRaster::add_to(rg::RenderGraph& graph, rg::ImageHandle atlas,
                                            rg::BufferHandle depths, rg::BufferHandle static_layers,
                                            const ShadowBatchFrame& frame, const CulledPairs& culled,
                                            const GpuScene& scene, uint32_t slot) const {
  add_raster(graph, "shadow raster", 0, frame, culled, scene, slot, depths);
  if (frame.layered && frame.full_views > 0) {
    static_layers = static_layers_->add_save(graph, frame, 0, frame.full_views, depths, static_layers);
  }
  // The restored views' squares are not list 0's, so restoring comes late: its wait for the
  // previous frame's save would otherwise come before the frame's culling and rasterizing.
  if (frame.layered && frame.full_views < frame.views) {
    depths = static_layers_->add_restore(graph, frame, frame.full_views, frame.views - frame.full_views,
                                         depths, static_layers);
  }
  if (culled.moving_pairs.valid())
    add_raster(graph, "shadow raster moving", 1, frame, culled, scene, slot, depths);
  if (!copies_.empty()) {
    graph.add_pass(
        "shadow copy",
        [&](rg::PassBuilder& p) {
          p.read(depths, rg::Usage::transfer);
          atlas = p.write(atlas, rg::Usage::transfer);  // the other tiles keep their contents
        },
        [this, depths, atlas](const vk::PassRecorder& rec) {
          vkCmdCopyBufferToImage(rec.cmd(), rec.buffer(depths), rec.image(atlas),
                                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, static_cast<uint32_t>(copies_.size()),
                                 copies_.data());
        });
  }
  if (!placement_.drawn().empty()) {
    graph.add_pass(
        "shadow copy draw",
        [&](rg::PassBuilder& p) {
          p.read(depths, rg::Usage::storage_fragment);
          atlas = p.write(atlas, rg::Usage::depth_attachment);  // the other tiles keep their contents
        },
        [this, depths, views = frame.view_records](const vk::PassRecorder& rec) {
          const VkDescriptorSet set = copy_layout_.write(rec.allocate_set(copy_layout_))
                                          .buffer(shadow_views_binding, views)
                                          .buffer(shadow_depths_binding, rec.buffer(depths))
                                          .update();
          rec.set_full_viewport();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, copy_pipeline_.get());
          copy_layout_.bind(rec.cmd(), set);
          // Two triangles a view (shadow_depth_copy.vert).
          for (const shadows::ViewRun& run : placement_.drawn())
            vkCmdDraw(rec.cmd(), 6, run.count, 0, run.first);
        });
  }
  return atlas;
}

}  // namespace sg
