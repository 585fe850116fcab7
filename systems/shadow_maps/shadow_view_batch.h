// SPDX-License-Identifier: MIT
#pragma once
// Every shadow view due this frame drawn by a handful of passes, driven by the GPU: shadow views
// are data, not passes. The CPU writes one record per view (a 2D map, or one face of a point
// light's cube) and one per shadow caster (shadow_batch_records.h); then
//
//   shadow cull      (compute)  every caster against every view's frustum -> (caster, view) pairs
//   shadow draws     (compute)  counts -> one indirect draw per (view kind, mesh), and dispatches
//                               (shadow_cull_pass.h)
// then, rasterizing with the hardware (shadows::ShadowRaster::hardware, hardware_shadow_raster.h):
//   shadow scatter   (compute)  the pairs sorted into those draws' instance ranges
//   shadow views     (raster)   clears the views' tiles, then two multi-draw indirect calls
//                               (2D maps depth only; cube faces with shadow_cube.frag) draw
//                               every pair into its tile of its atlas layer
// or in compute (shadows::ShadowRaster::compute, compute_shadow_raster.h):
//   shadow raster    (compute)  a workgroup per pair writes its triangles' depths into the
//                               views' squares of a depth buffer (shaders/shadow_raster.comp)
//   shadow copy      (transfer) the squares into their atlas tiles, large rectangles of them
//   shadow copy draw (raster)   the others, two triangles a view writing its depths
//
// With static layers (the atlas's, ShadowAtlas), the compute raster draws moving casters apart
// ("shadow raster moving"), over each view's static layer of its still casters ("shadow static
// save", "shadow static restore"; compute_shadow_raster.h, shadow_static_layers.h): a frame whose
// views are mostly redrawn for a few moving casters then draws those casters, not the scene.
// The hardware raster draws every caster into every view and keeps no layers
// (static_layers_kept()).
//
// so CPU time grows with views and casters, not with their product, and the number of passes is
// fixed. Casters of masked or transparent materials (GpuScene::first_cut_out_group) are drawn with
// the shaders' cut_out variants (shaders/shadow_cut_out.glsl); a transparent caster holding a
// view's light is culled from that view. Both rasters need shaderOutputLayer (gl_Layer from the
// vertex stage: shaders/shadow_batch.vert, shaders/shadow_depth_copy.vert); supported() says
// whether the device has it.
//
// ShadowViewBatch owns the parts and chooses each frame's raster.
#include <cstdint>

#include "ecs/fwd.h"
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/fwd.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/shadow_maps/compute_shadow_raster.h"
#include "systems/shadow_maps/hardware_shadow_raster.h"
#include "systems/shadow_maps/shadow_batch_records.h"
#include "systems/shadow_maps/shadow_cull_pass.h"
#include "systems/shadow_maps/shadow_pass_times.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/raster_choice.h"
#include "systems/shadows/shadow_view_path.h"

namespace sg {

class GpuTextures;

class ShadowViewBatch {
 public:
  // `raster` automatic: the hardware on CPU devices; on GPUs, each frame's choice of
  // shadows::RasterChoice, from the times measured_raster_time reports. `static_layers`: the atlas has them
  // (may_raster_in_compute). `textures`: the materials' (cut-out casters read their alpha), kept by
  // reference.
  ShadowViewBatch(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures,
                  shadows::ShadowRaster raster, bool static_layers);

  static bool supported(const vk::VulkanContext& context);
  // Whether frames may rasterize in compute with `raster` on this device, and so keep static
  // layers.
  static bool may_raster_in_compute(const vk::VulkanContext& context, shadows::ShadowRaster raster);
  // The raster of the last prepared frame (never automatic).
  shadows::ShadowRaster raster() const { return raster_; }
  // The raster of the frames prepared from now on. Compute or automatic (on a GPU) only on a
  // batch made with one of them, else std::logic_error.
  void set_raster(shadows::ShadowRaster raster);
  // A timed frame's shadow passes (shadow_pass_times), which drew `views` views: the automatic
  // choice learns the time of the raster that drew them.
  void measured(const ShadowPassTimes& times, uint32_t views);

  // After FrameRing::begin_frame returned `slot`, before prepare: false when the frame that last
  // used the slot kept more pairs than it could store, so some of its views missed casters and
  // must be rendered again (the capacity has grown since; shadow_cull_pass.h).
  bool all_casters_kept(uint32_t slot) { return cull_.all_casters_kept(slot); }
  // CPU side of a frame: the records of the views of `lights` that render this frame (`render`),
  // in an atlas of `page_size` texels a page, and of `scene`'s casters. With `pool`, the view
  // and caster records are written on its threads, straight into the slot's buffers.
  void prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene, uint32_t page_size,
               jobs::ThreadPool* pool = nullptr);
  // Whether the prepared frame keeps the static layers of the views it draws with every caster
  // (compute raster with static layers); when not, moving_casters_only views are drawn with
  // every caster too.
  bool static_layers_kept() const { return records_.frame().layered; }

  // Adds the passes (none when no view renders) and returns the atlas's newest version. `scene`
  // is read when the passes record. `static_layers`: the atlas's, imported, when it has them.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle atlas, rg::BufferHandle static_layers,
                         const GpuScene& scene, uint32_t slot) const;

  // Whether the prepared frame's raster costs what the frames to come will: not a probe of the
  // other raster, nor the first frame after a change (RasterChoice::steady); a raster set by hand
  // counts as steady.
  bool raster_steady() const { return setting_ != shadows::ShadowRaster::automatic || choice_.steady(); }
  uint32_t views() const { return records_.frame().views; }
  // Pairs (caster, view) the GPU kept in the last frame read back: instances drawn into views.
  uint64_t kept_pairs() const { return cull_.kept_pairs(); }

 private:
  // Whether the prepared frame rasterizes in compute: a frame without casters only clears its
  // tiles, which the hardware raster's pass does whatever the raster.
  bool rasterizes_in_compute() const;

  vk::VulkanContext& context_;
  shadows::ShadowRaster setting_;  // hardware, compute, or automatic: chosen per frame
  shadows::ShadowRaster raster_;   // this frame's
  bool has_static_layers_;
  shadows::RasterChoice choice_;
  ShadowBatchRecords records_;
  ShadowCullPass cull_;
  HardwareShadowRaster hardware_;
  ComputeShadowRaster compute_;
};

}  // namespace sg
