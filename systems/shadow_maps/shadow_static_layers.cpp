// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_static_layers.h"

#include <algorithm>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_static_restore.comp.spv.h"
#include "shaders/shadow_static_save.comp.spv.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {
namespace {

using namespace bindings;
using namespace shadow_batch;

// shaders/shadow_static_layers.glsl's LayerConstants.
struct LayerConstants {
  uint32_t view_base;
  uint32_t view_count;
};

// shaders/shadow_static_layers.glsl's TEXELS_PER_WORKGROUP.
constexpr uint64_t layer_texels_per_workgroup = 65536;

// The workgroups of a dispatch's x that every device allows (maxComputeWorkGroupCount[0]).
constexpr uint32_t max_workgroups_x = 65535;

}  // namespace

ShadowStaticLayers::ShadowStaticLayers(vk::VulkanContext& context)
    : layout_(context.device(),
              {{shadow_views_binding, storage, 1, compute},
               {shadow_depths_binding, storage, 1, compute},
               {static_layers_binding, storage, 1, compute}},
              vk::push_constants<LayerConstants>(compute)),
      save_pipeline_(vk::create_compute_pipeline(
          context, {shadow_static_save_comp, {}, layout_.get(), "shadow static save"})),
      restore_pipeline_(vk::create_compute_pipeline(
          context, {shadow_static_restore_comp, {}, layout_.get(), "shadow static restore"})) {}

rg::BufferHandle ShadowStaticLayers::add_save(rg::RenderGraph& graph, const ShadowBatchFrame& frame,
                                              uint32_t first, uint32_t count, rg::BufferHandle depths,
                                              rg::BufferHandle layers) const {
  add_copy(graph, "shadow static save", true, frame, first, count, depths, layers);
  return layers;
}

rg::BufferHandle ShadowStaticLayers::add_restore(rg::RenderGraph& graph, const ShadowBatchFrame& frame,
                                                 uint32_t first, uint32_t count, rg::BufferHandle depths,
                                                 rg::BufferHandle layers) const {
  add_copy(graph, "shadow static restore", false, frame, first, count, depths, layers);
  return depths;
}

void ShadowStaticLayers::add_copy(rg::RenderGraph& graph, const char* name, bool save,
                                  const ShadowBatchFrame& frame, uint32_t first, uint32_t count,
                                  rg::BufferHandle& depths, rg::BufferHandle& layers) const {
  uint64_t largest = 0;
  for (uint32_t v = first; v < first + count; ++v) {
    largest = std::max<uint64_t>(largest, uint64_t{frame.tiles[v].size} * frame.tiles[v].size);
  }
  const auto chunks =
      static_cast<uint32_t>((largest + layer_texels_per_workgroup - 1) / layer_texels_per_workgroup);
  graph.add_pass(
      name,
      [&](rg::PassBuilder& p) {
        if (save) {
          p.read(depths, rg::Usage::storage_compute);
          layers = p.write(layers, rg::Usage::storage_compute);
        } else {
          p.read(layers, rg::Usage::storage_compute);
          depths = p.write(depths, rg::Usage::storage_compute);
        }
      },
      [this, views = frame.view_records, save, first, count, chunks, depths,
       layers](const vk::PassRecorder& rec) {
        const VkDescriptorSet set = layout_.write(rec.allocate_set(layout_))
                                        .buffer(shadow_views_binding, views)
                                        .buffer(shadow_depths_binding, rec.buffer(depths))
                                        .buffer(static_layers_binding, rec.buffer(layers))
                                        .update();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE,
                          (save ? save_pipeline_ : restore_pipeline_).get());
        layout_.bind_compute(rec.cmd(), set);
        layout_.push(rec.cmd(), LayerConstants{first, count});
        vkCmdDispatch(rec.cmd(), std::min(count, max_workgroups_x), chunks, 1);
      });
}

}  // namespace sg
