// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_view_batch.h"

#include <stdexcept>

#include "rendergraph/device/context.h"

namespace sg {
namespace {

// A CPU device runs both rasters on the same cores, and the hardware path measured faster there
// (docs/PERFORMANCE.md); on a GPU automatic stays, to be chosen per frame.
shadows::ShadowRaster resolve(shadows::ShadowRaster raster, const vk::VulkanContext& context) {
  if (raster != shadows::ShadowRaster::automatic) return raster;
  return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? shadows::ShadowRaster::hardware
                                                                        : shadows::ShadowRaster::automatic;
}

// shadows::RasterChoice::choose's `large_tile_texels`.
uint64_t large_tile_texels(std::span<const shadows::AtlasTile> tiles) {
  uint64_t texels = 0;
  for (const shadows::AtlasTile& tile : tiles) {
    if (tile.size >= shadows::large_tile) texels += uint64_t{tile.size} * tile.size;
  }
  return texels;
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
      setting_(resolve(raster, context)),
      raster_(setting_ == shadows::ShadowRaster::automatic ? shadows::ShadowRaster::compute : setting_),
      has_static_layers_(static_layers),
      records_(context, frames_in_flight),
      cull_(context, frames_in_flight),
      hardware_(context, textures),
      compute_(context, textures, setting_ != shadows::ShadowRaster::hardware) {}

void ShadowViewBatch::set_raster(shadows::ShadowRaster raster) {
  raster = resolve(raster, context_);
  if (raster != shadows::ShadowRaster::hardware && !compute_.has_pipelines()) {
    throw std::logic_error(
        "ShadowViewBatch::set_raster: the compute raster needs a batch made with it (or automatic)");
  }
  setting_ = raster;
  if (raster != shadows::ShadowRaster::automatic) raster_ = raster;
}

void ShadowViewBatch::measured(const ShadowPassTimes& times, uint32_t views) {
  if (times.raster) choice_.measured(*times.raster, views, times.ms);
}

bool ShadowViewBatch::rasterizes_in_compute() const {
  return raster_ == shadows::ShadowRaster::compute && records_.frame().casters > 0;
}

void ShadowViewBatch::prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene,
                              uint32_t page_size, jobs::ThreadPool* pool) {
  const ShadowBatchFrame& frame = records_.lay_out(lights, scene, pool);
  if (setting_ == shadows::ShadowRaster::automatic) {
    raster_ = choice_.choose(frame.views, large_tile_texels(frame.tiles));
  }
  if (frame.first_cut_out_group < frame.caster_groups) {
    hardware_.make_cut_out_pipelines();
    compute_.make_cut_out_pipeline();
  }
  // The view records say where the compute raster puts each view's depths.
  if (rasterizes_in_compute()) {
    compute_.place_depths(frame.tiles);
  } else {
    compute_.place_nowhere(frame.views);
    hardware_.prepare(frame);
  }
  const bool layered = has_static_layers_ && frame.views > 0 && rasterizes_in_compute();
  records_.write(slot, lights, scene, page_size, compute_.depth_places(), layered, pool);
  cull_.prepare(slot, frame);
}

rg::ImageHandle ShadowViewBatch::add_to(rg::RenderGraph& graph, rg::ImageHandle atlas,
                                        rg::BufferHandle static_layers, const GpuScene& scene,
                                        uint32_t slot) const {
  const ShadowBatchFrame& frame = records_.frame();
  if (frame.views == 0) return atlas;
  if (frame.casters == 0) return hardware_.add_to(graph, atlas, frame, {}, scene, slot);
  const bool compute = rasterizes_in_compute();
  const ShadowCullReset reset = add_shadow_cull_reset(graph, frame, compute ? compute_.depth_texels() : 0);
  const CulledPairs culled = cull_.add_to(graph, frame, slot, reset);
  return compute ? compute_.add_to(graph, atlas, reset.depths, static_layers, frame, culled, scene, slot)
                 : hardware_.add_to(graph, atlas, frame, culled, scene, slot);
}

}  // namespace sg
