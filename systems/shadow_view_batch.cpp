#include "systems/shadow_view_batch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <span>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_batch.vert.spv.h"
#include "shaders/shadow_cube.frag.spv.h"
#include "shaders/shadow_cull.comp.spv.h"
#include "shaders/shadow_draws.comp.spv.h"
#include "shaders/shadow_scatter.comp.spv.h"
#include "systems/shader_bindings.h"
#include "systems/shadow_atlas.h"
#include "systems/shadows/atlas_tile_coords.h"

namespace sg {
namespace {

using namespace bindings;
constexpr VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

// shaders/shadow_views.glsl's VIEW_KIND_* and VIEW_KINDS.
constexpr uint32_t view_kind_map = 0;
constexpr uint32_t view_kind_face = 1;
constexpr uint32_t view_kinds = 2;

// shaders/shadow_batch_compute.glsl's BatchConstants.
struct BatchConstants {
  uint32_t caster_count;
  uint32_t group_count;
  uint32_t capacity;
  uint32_t view_base;
};

constexpr VkDeviceSize counts_header_bytes = 16;  // total and padding
constexpr VkDeviceSize draws_header_bytes = 16;   // the scatter's dispatch
constexpr VkDeviceSize pair_bytes = 2 * sizeof(uint32_t);

float as_float(uint32_t bits) { return std::bit_cast<float>(bits); }

VkClearRect tile_clear(const shadows::AtlasTile& tile) {
  return {{{int32_t(tile.x), int32_t(tile.y)}, {tile.size, tile.size}}, tile.page, 1};
}

}  // namespace

bool ShadowViewBatch::supported(const vk::VulkanContext& context) {
  return context.optional_features().shader_output_layer;
}

ShadowViewBatch::ShadowViewBatch(vk::VulkanContext& context, uint32_t frames_in_flight)
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
      scatter_layout_(context.device(),
                      {{shadow_views_binding, storage, 1, compute},
                       {shadow_casters_binding, storage, 1, compute},
                       {culled_pairs_binding, storage, 1, compute},
                       {draw_counts_binding, storage, 1, compute},
                       {view_instances_binding, storage, 1, compute}},
                      vk::push_constants<BatchConstants>(compute)),
      raster_layout_(context.device(), {{instances_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                        {shadow_views_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                        {view_instances_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT}}),
      view_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow views"),
      caster_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow casters"),
      mesh_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow caster meshes"),
      feedback_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow feedback"),
      capacity_in_slot_(frames_in_flight, 0) {
  max_views_per_dispatch_ = context.properties().limits.maxComputeWorkGroupCount[1];
  cull_pipeline_ =
      vk::create_compute_pipeline(context, {shadow_cull_comp, {}, cull_layout_.get(), "shadow cull"});
  draws_pipeline_ =
      vk::create_compute_pipeline(context, {shadow_draws_comp, {}, draws_layout_.get(), "shadow draws"});
  scatter_pipeline_ = vk::create_compute_pipeline(
      context, {shadow_scatter_comp, {}, scatter_layout_.get(), "shadow scatter"});
  if (!supported(context)) return;
  vk::GraphicsPipelineDesc desc;
  scene_vertex_input(desc, false);
  desc.depth_format = vk::to_vk(ShadowAtlas::depth_format);
  // Receivers apply each light's own bias (ALGORITHMS.md section 4): casters are drawn as they
  // are, both faces, as in the per-light passes (shadow_passes.cpp).
  desc.cull_mode = VK_CULL_MODE_NONE;
  desc.layout = raster_layout_.get();
  desc.vertex_spirv = shadow_batch_vert;
  desc.name = "shadow batch maps";
  map_pipeline_ = vk::create_graphics_pipeline(context, desc);
  desc.fragment_spirv = shadow_cube_frag;
  desc.name = "shadow batch cube faces";
  face_pipeline_ = vk::create_graphics_pipeline(context, desc);
}

bool ShadowViewBatch::all_casters_kept(uint32_t slot) {
  // What the GPU kept the last time this slot ran (its fence has been waited for).
  if (capacity_in_slot_[slot] == 0) return true;
  uint32_t kept = 0;
  std::memcpy(&kept, feedback_.buffer(slot).mapped(), sizeof(kept));
  kept_pairs_ = kept;
  if (kept <= capacity_in_slot_[slot]) return true;
  capacity_limit_ = std::max(capacity_limit_, std::bit_ceil(uint64_t{kept} + kept / 2));
  return false;
}

void ShadowViewBatch::prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene,
                              uint32_t page_size) {
  views_.clear();
  clears_.clear();
  for (const shadows::ShadowMapView& map : lights.maps) {
    if (!map.render) continue;
    View& view = views_.emplace_back();
    view.view_projection = map.view.view_projection();
    view.tile = shadows::tile_clip_transform(map.tile, page_size);
    view.position_far = glm::vec4(0.0f);
    view.planes = shadows::frustum_planes(view.view_projection);
    view.info = {map.tile.page, view_kind_map, 0u, 0u};
    clears_.push_back(tile_clear(map.tile));
  }
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    if (!cube.render) continue;
    for (uint32_t face = 0; face < 6; ++face) {
      View& view = views_.emplace_back();
      view.view_projection = cube.views.view_projection[face];
      view.tile = shadows::tile_clip_transform(cube.tiles[face], page_size);
      view.position_far = cube.position_far;
      view.planes = shadows::frustum_planes(view.view_projection);
      view.info = {cube.tiles[face].page, view_kind_face, 0u, 0u};
      clears_.push_back(tile_clear(cube.tiles[face]));
    }
  }

  casters_.clear();
  meshes_.clear();
  const std::span<const VkDrawIndexedIndirectCommand> groups = scene.caster_groups();
  const std::span<const scene::Aabb> bounds = scene.instance_bounds();
  for (uint32_t g = 0; g < groups.size(); ++g) {
    const VkDrawIndexedIndirectCommand& group = groups[g];
    meshes_.push_back({group.indexCount, group.firstIndex, std::bit_cast<uint32_t>(group.vertexOffset), 0u});
    for (uint32_t i = group.firstInstance; i < group.firstInstance + group.instanceCount; ++i) {
      casters_.push_back({glm::vec4(bounds[i].min, as_float(g)), glm::vec4(bounds[i].max, as_float(i))});
    }
  }
  view_buffers_.write(slot, std::span<const View>(views_));
  caster_buffers_.write(slot, std::span<const Caster>(casters_));
  mesh_buffers_.write(slot, std::span<const glm::uvec4>(meshes_));
  const uint32_t zero = 0;
  feedback_.write(slot, std::span<const uint32_t>(&zero, 1));

  capacity_ = std::clamp<uint64_t>(uint64_t{views()} * casters_.size(), 1, capacity_limit_);
  capacity_in_slot_[slot] = views_.empty() || casters_.empty() ? 0 : capacity_;
}

rg::ImageHandle ShadowViewBatch::add_to(rg::RenderGraph& graph, rg::ImageHandle atlas, const GpuScene& scene,
                                        uint32_t slot) const {
  if (views_.empty()) return atlas;
  const auto group_count = static_cast<uint32_t>(meshes_.size());
  const BatchConstants constants{static_cast<uint32_t>(casters_.size()), group_count,
                                 static_cast<uint32_t>(capacity_), 0u};
  const uint32_t draw_count = view_kinds * group_count;
  const VkBuffer view_buffer = view_buffers_.buffer(slot).handle();
  const VkBuffer caster_buffer = caster_buffers_.buffer(slot).handle();

  struct Buffers {
    rg::BufferHandle counts, pairs, draws, sorted;
  } b{};
  if (!casters_.empty()) {
    graph.add_pass(
        "shadow cull reset",
        [&](rg::PassBuilder& p) {
          b.counts =
              p.write(p.create_buffer("shadow draw counts", {counts_header_bytes + 2 * draw_count * 4}),
                      rg::Usage::transfer);
          return b.counts;
        },
        [](rg::BufferHandle counts, const vk::PassRecorder& rec) {
          vkCmdFillBuffer(rec.cmd(), rec.buffer(counts), 0, VK_WHOLE_SIZE, 0);
        });
    graph.add_pass(
        "shadow cull",
        [&](rg::PassBuilder& p) {
          b.counts = p.write(b.counts, rg::Usage::storage_compute);
          b.pairs = p.write(p.create_buffer("shadow culled pairs", {capacity_ * pair_bytes}),
                            rg::Usage::storage_compute);
          return b;
        },
        [this, constants, view_buffer, caster_buffer](const Buffers& written, const vk::PassRecorder& rec) {
          const VkDescriptorSet set = cull_layout_.write(rec.allocate_set(cull_layout_))
                                          .buffer(shadow_views_binding, view_buffer)
                                          .buffer(shadow_casters_binding, caster_buffer)
                                          .buffer(culled_pairs_binding, rec.buffer(written.pairs))
                                          .buffer(draw_counts_binding, rec.buffer(written.counts))
                                          .update();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, cull_pipeline_.get());
          cull_layout_.bind_compute(rec.cmd(), set);
          const uint32_t columns = (constants.caster_count + 63) / 64;
          for (uint32_t base = 0; base < views(); base += max_views_per_dispatch_) {
            BatchConstants chunk = constants;
            chunk.view_base = base;
            cull_layout_.push(rec.cmd(), chunk);
            vkCmdDispatch(rec.cmd(), columns, std::min(max_views_per_dispatch_, views() - base), 1);
          }
        });
    graph.add_pass(
        "shadow draws",
        [&](rg::PassBuilder& p) {
          b.counts = p.write(b.counts, rg::Usage::storage_compute);
          b.draws = p.write(
              p.create_buffer("shadow draw commands",
                              {draws_header_bytes + draw_count * sizeof(VkDrawIndexedIndirectCommand)}),
              rg::Usage::storage_compute);
          return b;
        },
        [this, constants, slot](const Buffers& written, const vk::PassRecorder& rec) {
          const VkDescriptorSet set = draws_layout_.write(rec.allocate_set(draws_layout_))
                                          .buffer(caster_meshes_binding, mesh_buffers_.buffer(slot).handle())
                                          .buffer(draw_counts_binding, rec.buffer(written.counts))
                                          .buffer(shadow_draws_binding, rec.buffer(written.draws))
                                          .buffer(shadow_feedback_binding, feedback_.buffer(slot).handle())
                                          .update();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, draws_pipeline_.get());
          draws_layout_.bind_compute(rec.cmd(), set);
          draws_layout_.push(rec.cmd(), constants);
          vkCmdDispatch(rec.cmd(), 1, 1, 1);
        });
    graph.add_pass(
        "shadow scatter",
        [&](rg::PassBuilder& p) {
          p.read(b.draws, rg::Usage::indirect);
          p.read(b.pairs, rg::Usage::storage_compute);
          b.counts = p.write(b.counts, rg::Usage::storage_compute);
          b.sorted = p.write(p.create_buffer("shadow sorted pairs", {capacity_ * pair_bytes}),
                             rg::Usage::storage_compute);
          return b;
        },
        [this, constants, view_buffer, caster_buffer](const Buffers& written, const vk::PassRecorder& rec) {
          const VkDescriptorSet set = scatter_layout_.write(rec.allocate_set(scatter_layout_))
                                          .buffer(shadow_views_binding, view_buffer)
                                          .buffer(shadow_casters_binding, caster_buffer)
                                          .buffer(culled_pairs_binding, rec.buffer(written.pairs))
                                          .buffer(draw_counts_binding, rec.buffer(written.counts))
                                          .buffer(view_instances_binding, rec.buffer(written.sorted))
                                          .update();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, scatter_pipeline_.get());
          scatter_layout_.bind_compute(rec.cmd(), set);
          scatter_layout_.push(rec.cmd(), constants);
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(written.draws), 0);
        });
  }

  graph.add_pass(
      "shadow views",
      [&](rg::PassBuilder& p) {
        if (!casters_.empty()) {
          p.read(b.draws, rg::Usage::indirect);
          p.read(b.sorted, rg::Usage::storage_vertex);
        }
        atlas = p.write(atlas, rg::Usage::depth_attachment);  // kept: cached tiles stay
      },
      [this, &scene, slot, group_count, view_buffer, b](const vk::PassRecorder& rec) {
        const VkClearAttachment far{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {.depthStencil = {1.0f, 0}}};
        vkCmdClearAttachments(rec.cmd(), 1, &far, static_cast<uint32_t>(clears_.size()), clears_.data());
        if (casters_.empty() || !scene.bind_geometry(rec.cmd())) return;
        rec.set_full_viewport();
        const VkDescriptorSet set = raster_layout_.write(rec.allocate_set(raster_layout_))
                                        .buffer(instances_binding, scene.instances(slot).handle())
                                        .buffer(shadow_views_binding, view_buffer)
                                        .buffer(view_instances_binding, rec.buffer(b.sorted))
                                        .update();
        raster_layout_.bind(rec.cmd(), set);
        const VkBuffer draws = rec.buffer(b.draws);
        constexpr VkDeviceSize stride = sizeof(VkDrawIndexedIndirectCommand);
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, map_pipeline_.get());
        vkCmdDrawIndexedIndirect(rec.cmd(), draws, draws_header_bytes, group_count, stride);
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, face_pipeline_.get());
        vkCmdDrawIndexedIndirect(rec.cmd(), draws, draws_header_bytes + group_count * stride, group_count,
                                 stride);
      });
  return atlas;
}

}  // namespace sg
