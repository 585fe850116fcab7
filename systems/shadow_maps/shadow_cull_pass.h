// SPDX-License-Identifier: MIT
#pragma once
// The batch's culling (ShadowViewBatch), before either raster:
//
//   shadow cull reset (transfer) zeroes the draws' counts (and sets the compute raster's depths
//                                to the far plane)
//   shadow cull       (compute)  every caster against every view's frustum -> (caster, view) pairs
//   shadow draws      (compute)  counts -> one indirect draw per (view kind, mesh), and dispatches
//
// Pairs come in two lists: list 0, the views drawn with every caster against every caster (the
// still ones alone on layered frames), and on layered frames list 1, every view against the
// moving casters (shaders/shadow_batch_compute.glsl).
//
// Culled pairs live in a buffer of a fixed capacity per list. The GPU reports how many pairs it
// kept (read back when the frame slot comes round again); when they did not fit, capacity grows
// and all_casters_kept() says so, so that the caller re-renders the views that lost casters.
#include <array>
#include <cstdint>
#include <vector>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/shadow_maps/shadow_batch_records.h"

namespace sg {

// What "shadow cull reset" starts a frame's buffers with, in one transfer pass.
struct ShadowCullReset {
  rg::BufferHandle counts;  // zeroed: shaders/shadow_batch_compute.glsl's Counts
  rg::BufferHandle depths;  // at the far plane: the compute raster's depths, when asked for
};

// The cull's outputs, the rasters' inputs (shaders/shadow_batch_compute.glsl).
struct CulledPairs {
  rg::BufferHandle counts;             // per draw its pairs, then the scatter's cursors
  rg::BufferHandle pairs;              // list 0
  rg::BufferHandle moving_pairs;       // list 1: layered frames with moving casters only
  rg::BufferHandle draws;              // shaders/shadow_draws.comp's Draws (shadow_batch::*_offset)
  std::array<uint64_t, 2> capacity{};  // per list: the pairs its buffer holds
};

// Adds "shadow cull reset" for `frame`: with `depth_texels`, the compute raster's depth buffer is
// made there too, so that both are reset by one pass.
ShadowCullReset add_shadow_cull_reset(rg::RenderGraph& graph, const ShadowBatchFrame& frame,
                                      uint64_t depth_texels);

class ShadowCullPass {
 public:
  ShadowCullPass(vk::VulkanContext& context, uint32_t frames_in_flight);

  // After FrameRing::begin_frame returned `slot`, before prepare: false when the frame that last
  // used the slot kept more pairs than it could store, so some of its views missed casters and
  // must be rendered again (the capacity has grown since).
  bool all_casters_kept(uint32_t slot);
  // Pairs (caster, view) the GPU kept in the last frame read back.
  uint64_t kept_pairs() const { return kept_pairs_; }

  // This frame's capacities for `frame`'s pairs, in `slot`.
  void prepare(uint32_t slot, const ShadowBatchFrame& frame);
  // Adds "shadow cull" and "shadow draws" for `frame`, prepared in `slot`, after `reset`.
  CulledPairs add_to(rg::RenderGraph& graph, const ShadowBatchFrame& frame, uint32_t slot,
                     const ShadowCullReset& reset) const;

 private:
  vk::PipelineLayout cull_layout_;
  vk::PipelineLayout draws_layout_;
  vk::UniquePipeline cull_pipeline_;
  vk::UniquePipeline draws_pipeline_;
  uint32_t max_views_per_dispatch_ = 0;
  vk::FrameBuffers feedback_;  // per slot: the pairs each list kept, stored or not
  // Per pair list: the capacity each slot's last frame had, the limit it may grow to, this
  // frame's.
  struct PairCapacity {
    std::vector<uint64_t> in_slot;
    uint64_t limit = uint64_t{1} << 22;
    uint64_t now = 0;
  };
  std::array<PairCapacity, 2> capacity_;
  uint64_t kept_pairs_ = 0;
};

}  // namespace sg
