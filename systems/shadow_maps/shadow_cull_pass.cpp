// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_cull_pass.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <span>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_cull.comp.spv.h"
#include "shaders/shadow_draws.comp.spv.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {
namespace {

using namespace bindings;
using namespace shadow_batch;

// shaders/shadow_batch_compute.glsl's Counts: the two lists' totals and padding, then per draw
// its pairs and the scatter's cursor.
constexpr VkDeviceSize counts_header_bytes = 16;

uint32_t draw_count(const ShadowBatchFrame& frame) { return shadow_batch::view_kinds * frame.caster_groups; }

}  // namespace

ShadowCullReset add_shadow_cull_reset(rg::RenderGraph& graph, const ShadowBatchFrame& frame,
                                      uint64_t depth_texels) {
  ShadowCullReset reset;
  graph.add_pass(
      "shadow cull reset",
      [&](rg::PassBuilder& p) {
        reset.counts =
            p.write(p.create_buffer("shadow draw counts", {counts_header_bytes + 2 * draw_count(frame) * 4}),
                    rg::Usage::transfer);
        if (depth_texels > 0) {
          reset.depths = p.write(
              p.create_buffer("shadow depths", {shadow_batch::frame_steady(depth_texels * sizeof(float))}),
              rg::Usage::transfer);
        }
        return reset;
      },
      [](const ShadowCullReset& written, const vk::PassRecorder& rec) {
        vkCmdFillBuffer(rec.cmd(), rec.buffer(written.counts), 0, VK_WHOLE_SIZE, 0);
        // The far plane, 1.0f: what a cleared tile holds.
        if (written.depths.valid())
          vkCmdFillBuffer(rec.cmd(), rec.buffer(written.depths), 0, VK_WHOLE_SIZE, 0x3F800000u);
      });
  return reset;
}

ShadowCullPass::ShadowCullPass(vk::VulkanContext& context, uint32_t frames_in_flight)
    : cull_layout_(context.device(),
                   {{shadow_views_binding, storage, 1, compute},
                    {shadow_casters_binding, storage, 1, compute},
                    {culled_pairs_binding, storage, 1, compute},
                    {draw_counts_binding, storage, 1, compute}},
                   vk::push_constants<BatchConstants>(compute)),
      draws_layout_(context.device(),
                    {{caster_meshes_binding, storage, 1, compute},
                     {draw_counts_binding, storage, 1, compute},
                     {shadow_draws_binding, storage, 1, compute},
                     {shadow_feedback_binding, storage, 1, compute}},
                    vk::push_constants<BatchConstants>(compute)),
      cull_pipeline_(
          vk::create_compute_pipeline(context, {shadow_cull_comp, {}, cull_layout_.get(), "shadow cull"})),
      draws_pipeline_(
          vk::create_compute_pipeline(context, {shadow_draws_comp, {}, draws_layout_.get(), "shadow draws"})),
      max_views_per_dispatch_(context.properties().limits.maxComputeWorkGroupCount[1]),
      feedback_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow feedback",
                VK_FORMAT_UNDEFINED, vk::MemoryUsage::readback) {
  for (PairCapacity& capacity : capacity_) capacity.in_slot.assign(frames_in_flight, 0);
}

bool ShadowCullPass::all_casters_kept(uint32_t slot) {
  // What the GPU kept the last time this slot ran (its fence has been waited for).
  std::array<uint32_t, 2> kept{};
  std::memcpy(kept.data(), feedback_.buffer(slot).mapped(), sizeof(kept));
  bool all_kept = true;
  for (size_t list = 0; list < capacity_.size(); ++list) {
    PairCapacity& capacity = capacity_[list];
    if (capacity.in_slot[slot] == 0) continue;
    if (kept[list] <= capacity.in_slot[slot]) continue;
    capacity.limit = std::max(capacity.limit, std::bit_ceil(uint64_t{kept[list]} + kept[list] / 2));
    all_kept = false;
  }
  if (capacity_[0].in_slot[slot] != 0) kept_pairs_ = uint64_t{kept[0]} + kept[1];
  return all_kept;
}

void ShadowCullPass::prepare(uint32_t slot, const ShadowBatchFrame& frame) {
  const std::array<uint32_t, 2> zeros{};
  feedback_.write(slot, std::span<const uint32_t>(zeros));
  const bool drawn = frame.views > 0 && frame.casters > 0;
  const std::array<uint64_t, 2> pairs{uint64_t{frame.full_views} * frame.casters,
                                      uint64_t{frame.views} * frame.moving_casters};
  for (size_t list = 0; list < capacity_.size(); ++list) {
    PairCapacity& capacity = capacity_[list];
    capacity.now = std::clamp<uint64_t>(pairs[list], 1, capacity.limit);
    capacity.in_slot[slot] = drawn && pairs[list] > 0 ? capacity.now : 0;
  }
}

CulledPairs ShadowCullPass::add_to(rg::RenderGraph& graph, const ShadowBatchFrame& frame, uint32_t slot,
                                   const ShadowCullReset& reset) const {
  CulledPairs culled{
      .capacity = {static_cast<uint32_t>(capacity_[0].now), static_cast<uint32_t>(capacity_[1].now)}};
  BatchConstants constants{frame.casters, frame.caster_groups, static_cast<uint32_t>(culled.capacity[0]), 0u};
  constants.skip_moving = frame.layered ? 1 : 0;
  constants.moving_capacity = static_cast<uint32_t>(culled.capacity[1]);
  constants.block_base = frame.first_block[0];
  graph.add_pass(
      "shadow cull",
      [&](rg::PassBuilder& p) {
        culled.counts = p.write(reset.counts, rg::Usage::storage_compute);
        culled.pairs = p.write(
            p.create_buffer("shadow culled pairs",
                            {shadow_batch::frame_steady(culled.capacity[0] * shadow_batch::pair_bytes)}),
            rg::Usage::storage_compute);
        if (frame.layered && frame.moving_casters > 0) {
          culled.moving_pairs = p.write(
              p.create_buffer("shadow moving pairs",
                              {shadow_batch::frame_steady(culled.capacity[1] * shadow_batch::pair_bytes)}),
              rg::Usage::storage_compute);
        }
        return culled;
      },
      [this, constants, frame](const CulledPairs& written, const vk::PassRecorder& rec) {
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, cull_pipeline_.get());
        // List 0: the views drawn with every caster against every still caster (every caster,
        // unlayered); list 1: every view against the moving casters.
        const auto cull = [&](rg::BufferHandle pairs, BatchConstants list, uint32_t view_count) {
          const VkDescriptorSet set = cull_layout_.write(rec.allocate_set(cull_layout_))
                                          .buffer(shadow_views_binding, frame.view_records)
                                          .buffer(shadow_casters_binding, frame.caster_records)
                                          .buffer(culled_pairs_binding, rec.buffer(pairs))
                                          .buffer(draw_counts_binding, rec.buffer(written.counts))
                                          .update();
          cull_layout_.bind_compute(rec.cmd(), set);
          for (uint32_t base = 0; base < view_count; base += max_views_per_dispatch_) {
            list.view_base = base;
            cull_layout_.push(rec.cmd(), list);
            vkCmdDispatch(rec.cmd(), 1, std::min(max_views_per_dispatch_, view_count - base),
                          1);  // a workgroup a view
          }
        };
        if (frame.full_views > 0) cull(written.pairs, constants, frame.full_views);
        if (written.moving_pairs.valid()) {
          BatchConstants moving = constants;
          moving.caster_base = frame.casters;
          moving.caster_count = frame.moving_casters;
          moving.capacity = constants.moving_capacity;
          moving.list = 1;
          moving.skip_moving = 0;
          moving.block_base = frame.first_block[1];
          cull(written.moving_pairs, moving, frame.views);
        }
      });
  graph.add_pass(
      "shadow draws",
      [&](rg::PassBuilder& p) {
        culled.counts = p.write(culled.counts, rg::Usage::storage_compute);
        culled.draws = p.write(p.create_buffer("shadow draw commands",
                                               {shadow_batch::draws_header_bytes +
                                                draw_count(frame) * sizeof(VkDrawIndexedIndirectCommand)}),
                               rg::Usage::storage_compute);
        return culled;
      },
      [this, constants, frame, slot](const CulledPairs& written, const vk::PassRecorder& rec) {
        const VkDescriptorSet set = draws_layout_.write(rec.allocate_set(draws_layout_))
                                        .buffer(caster_meshes_binding, frame.mesh_records)
                                        .buffer(draw_counts_binding, rec.buffer(written.counts))
                                        .buffer(shadow_draws_binding, rec.buffer(written.draws))
                                        .buffer(shadow_feedback_binding, feedback_.buffer(slot).handle())
                                        .update();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, draws_pipeline_.get());
        draws_layout_.bind_compute(rec.cmd(), set);
        draws_layout_.push(rec.cmd(), constants);
        vkCmdDispatch(rec.cmd(), 1, 1, 1);
      });
  return culled;
}

}  // namespace sg
