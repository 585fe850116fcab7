#include "systems/shadow_maps/shadow_view_batch.h"

#include <algorithm>
#include <cstdio>
#include <span>
#include <stdexcept>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_raster.comp.spv.h"
#include "shaders/shadow_raster_cut_out.comp.spv.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {
namespace {

using namespace bindings;
using namespace shadow_batch;
constexpr VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

// shadows::raster_for_views's `large_tile_texels`.
uint64_t large_tile_texels(std::span<const shadows::AtlasTile> tiles) {
  uint64_t texels = 0;
  for (const shadows::AtlasTile& tile : tiles) {
    if (tile.size >= shadows::large_tile) texels += uint64_t{tile.size} * tile.size;
  }
  return texels;
}

// A CPU device runs both rasters on the same cores, and the hardware path measured faster there
// (docs/PERFORMANCE.md); on a GPU automatic stays, to be chosen per frame.
shadows::ShadowRaster resolve(shadows::ShadowRaster raster, const vk::VulkanContext& context) {
  if (raster != shadows::ShadowRaster::automatic) return raster;
  return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? shadows::ShadowRaster::hardware
                                                                        : shadows::ShadowRaster::automatic;
}

}  // namespace

bool ShadowViewBatch::supported(const vk::VulkanContext& context) {
  return context.optional_features().shader_output_layer;
}

bool ShadowViewBatch::may_raster_in_compute(const vk::VulkanContext& context, shadows::ShadowRaster raster) {
  return resolve(raster, context) != shadows::ShadowRaster::hardware;
}

ShadowViewBatch::ShadowViewBatch(vk::VulkanContext& context, uint32_t frames_in_flight,
                                 const GpuTextures& textures, shadows::ShadowRaster raster,
                                 bool static_layers)
    : context_(context),
      textures_(textures),
      setting_(resolve(raster, context)),
      raster_(setting_ == shadows::ShadowRaster::automatic ? shadows::ShadowRaster::compute : setting_),
      has_static_layers_(static_layers),
      compute_raster_layout_(
          context.device(),
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
      records_(context, frames_in_flight),
      cull_(context, frames_in_flight),
      hardware_(context, textures) {
  if (setting_ != shadows::ShadowRaster::hardware) {
    if (context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
      std::printf(
          "shadowgraph: compute shadow raster on a CPU device: slow, and llvmpipe stops a shader's loops "
          "after 65,535 iterations, which can leave tiles over 512 texels incomplete\n");
    }
    compute_raster_pipeline_ = vk::create_compute_pipeline(
        context, {shadow_raster_comp, {}, compute_raster_layout_.get(), "shadow raster"});
    static_layers_.emplace(context);
  }
}

void ShadowViewBatch::make_compute_cut_out_pipeline() {
  if (!compute_raster_pipeline_ || compute_raster_cut_out_pipeline_) return;
  compute_raster_cut_out_pipeline_ = vk::create_compute_pipeline(
      context_, {shadow_raster_cut_out_comp, material_pass_constants(0, 0, textures_),
                 compute_raster_layout_.get(), "shadow raster cut out"});
}

void ShadowViewBatch::set_raster(shadows::ShadowRaster raster) {
  raster = resolve(raster, context_);
  if (raster != shadows::ShadowRaster::hardware && !compute_raster_pipeline_) {
    throw std::logic_error(
        "ShadowViewBatch::set_raster: the compute raster needs a batch made with it (or automatic)");
  }
  setting_ = raster;
  if (raster != shadows::ShadowRaster::automatic) raster_ = raster;
}

bool ShadowViewBatch::rasterizes_in_compute() const {
  return raster_ == shadows::ShadowRaster::compute && records_.frame().casters > 0;
}

void ShadowViewBatch::prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene,
                              uint32_t page_size, jobs::ThreadPool* pool) {
  const ShadowBatchFrame& frame = records_.lay_out(lights, scene, pool);
  if (setting_ == shadows::ShadowRaster::automatic) {
    raster_ = shadows::raster_for_views(frame.views, large_tile_texels(frame.tiles));
  }
  if (frame.first_cut_out_group < frame.caster_groups) {
    hardware_.make_cut_out_pipelines();
    make_compute_cut_out_pipeline();
  }
  // The view records say where the compute raster puts each view's depths.
  if (rasterizes_in_compute()) {
    place_depths(frame.tiles);
  } else {
    depth_placement_.place_nowhere(frame.views);
  }
  const bool layered = has_static_layers_ && frame.views > 0 && rasterizes_in_compute();
  records_.write(slot, lights, scene, page_size, depth_placement_.places(), layered, pool);
  cull_.prepare(slot, frame);
}

void ShadowViewBatch::place_depths(std::span<const shadows::AtlasTile> tiles) {
  if (!depth_placement_.place(tiles)) return;
  copies_.clear();
  for (const shadows::DepthRegion& region : depth_placement_.regions()) {
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

rg::ImageHandle ShadowViewBatch::add_to(rg::RenderGraph& graph, rg::ImageHandle atlas,
                                        rg::BufferHandle static_layers, const GpuScene& scene,
                                        uint32_t slot) const {
  const ShadowBatchFrame& frame = records_.frame();
  if (frame.views == 0) return atlas;
  if (frame.casters == 0) return hardware_.add_to(graph, atlas, frame, {}, scene, slot);
  const bool compute = rasterizes_in_compute();
  const ShadowCullReset reset = add_shadow_cull_reset(graph, frame, compute ? depth_placement_.texels() : 0);
  const CulledPairs culled = cull_.add_to(graph, frame, slot, reset);
  return compute ? add_compute_raster(graph, atlas, scene, slot, culled, reset.depths, static_layers)
                 : hardware_.add_to(graph, atlas, frame, culled, scene, slot);
}

rg::ImageHandle ShadowViewBatch::add_compute_raster(rg::RenderGraph& graph, rg::ImageHandle atlas,
                                                    const GpuScene& scene, uint32_t slot,
                                                    const CulledPairs& culled, rg::BufferHandle depths,
                                                    rg::BufferHandle static_layers) const {
  const ShadowBatchFrame& frame = records_.frame();
  const rg::BufferHandle counts = culled.counts;
  const rg::BufferHandle draws = culled.draws;
  const auto raster = [&](const char* name, rg::BufferHandle list_pairs, uint32_t list) {
    BatchConstants constants{frame.casters, frame.caster_groups, static_cast<uint32_t>(culled.capacity[list]),
                             0u};
    constants.list = list;
    const VkDeviceSize dispatch = list == 0 ? raster_dispatch_offset : moving_raster_dispatch_offset;
    graph.add_pass(
        name,
        [&](rg::PassBuilder& p) {
          p.read(draws, rg::Usage::indirect);
          p.read(list_pairs, rg::Usage::storage_compute);
          p.read(counts, rg::Usage::storage_compute);
          depths = p.write(depths, rg::Usage::storage_compute);
        },
        [this, &scene, slot, constants, frame, list_pairs, counts, draws, depths, dispatch,
         cut_out = frame.first_cut_out_group < frame.caster_groups](const vk::PassRecorder& rec) {
          const VkDescriptorSet set =
              compute_raster_layout_.write(rec.allocate_set(compute_raster_layout_))
                  .buffer(instances_binding, scene.instances(slot).handle())
                  .buffer(shadow_views_binding, frame.view_records)
                  .buffer(shadow_casters_binding, frame.caster_records)
                  .buffer(caster_meshes_binding, frame.mesh_records)
                  .buffer(culled_pairs_binding, rec.buffer(list_pairs))
                  .buffer(draw_counts_binding, rec.buffer(counts))
                  .buffer(shadow_depths_binding, rec.buffer(depths))
                  .buffer(mesh_vertices_binding, scene.vertices().handle())
                  .buffer(mesh_indices_binding, scene.indices().handle())
                  .image(material_textures_binding, textures_.array().view(), textures_.sampler())
                  .update();
          compute_raster_layout_.bind_compute(rec.cmd(), set);
          compute_raster_layout_.push(rec.cmd(), constants);
          // Each variant takes its own casters' pairs (shaders/shadow_raster.comp).
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, compute_raster_pipeline_.get());
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(draws), dispatch);
          if (cut_out) {
            vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE,
                              compute_raster_cut_out_pipeline_.get());
            vkCmdDispatchIndirect(rec.cmd(), rec.buffer(draws), dispatch);
          }
        });
  };
  raster("shadow raster", culled.pairs, 0);
  if (frame.layered && frame.full_views > 0) {
    static_layers = static_layers_->add_save(graph, frame, 0, frame.full_views, depths, static_layers);
  }
  // The restored views' squares are not list 0's, so restoring comes late: its wait for the
  // previous frame's save would otherwise come before the frame's culling and rasterizing.
  if (frame.layered && frame.full_views < frame.views) {
    depths = static_layers_->add_restore(graph, frame, frame.full_views, frame.views - frame.full_views,
                                         depths, static_layers);
  }
  if (culled.moving_pairs.valid()) raster("shadow raster moving", culled.moving_pairs, 1);
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
  return atlas;
}

}  // namespace sg
