#include "systems/shadow_maps/shadow_view_batch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_batch.vert.spv.h"
#include "shaders/shadow_batch_cut_out.vert.spv.h"
#include "shaders/shadow_cube.frag.spv.h"
#include "shaders/shadow_cube_cut_out.frag.spv.h"
#include "shaders/shadow_cull.comp.spv.h"
#include "shaders/shadow_cut_out.frag.spv.h"
#include "shaders/shadow_draws.comp.spv.h"
#include "shaders/shadow_raster.comp.spv.h"
#include "shaders/shadow_raster_cut_out.comp.spv.h"
#include "shaders/shadow_scatter.comp.spv.h"
#include "shaders/shadow_static_restore.comp.spv.h"
#include "shaders/shadow_static_save.comp.spv.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/shadow_maps/shadow_atlas.h"
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
  uint32_t caster_base = 0;
  uint32_t list = 0;
  uint32_t skip_moving = 0;
  uint32_t moving_capacity = 0;
};

// shaders/shadow_static_layers.glsl's LayerConstants.
struct LayerConstants {
  uint32_t view_base;
  uint32_t view_count;
};

// shaders/shadow_static_layers.glsl's TEXELS_PER_WORKGROUP.
constexpr uint64_t layer_texels_per_workgroup = 65536;

// shaders/shadow_views.glsl's CASTER_MOVING and CASTER_BLENDED, in a caster record's group.
constexpr uint32_t caster_moving = 0x80000000u;
constexpr uint32_t caster_blended = 0x40000000u;

constexpr VkDeviceSize counts_header_bytes = 16;  // the two lists' totals and padding
constexpr VkDeviceSize draws_header_bytes = 48;   // the scatter's and the raster's dispatches
constexpr VkDeviceSize raster_dispatch_offset = 16;
constexpr VkDeviceSize moving_raster_dispatch_offset = 32;
// The workgroups of a dispatch's x that every device allows (maxComputeWorkGroupCount[0]).
constexpr uint32_t max_workgroups_x = 65535;
constexpr VkDeviceSize pair_bytes = 2 * sizeof(uint32_t);

float as_float(uint32_t bits) { return std::bit_cast<float>(bits); }

// The size to declare for a transient buffer needing `bytes`: rounded up to a power of two, so
// that frames drawing different numbers of views keep the graph's shape, and with it the
// compiled plan and its memory (rg::PlanCache), instead of recompiling and reallocating.
uint64_t frame_steady(uint64_t bytes) { return std::bit_ceil(std::max<uint64_t>(bytes, 256)); }

VkClearRect tile_clear(const shadows::AtlasTile& tile) {
  return {{{int32_t(tile.x), int32_t(tile.y)}, {tile.size, tile.size}}, tile.page, 1};
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
      cull_layout_(context.device(),
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
                                        {view_instances_binding, storage, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                        {material_textures_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                         1, VK_SHADER_STAGE_FRAGMENT_BIT}}),
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
      static_layers_layout_(context.device(),
                            {{shadow_views_binding, storage, 1, compute},
                             {shadow_depths_binding, storage, 1, compute},
                             {static_layers_binding, storage, 1, compute}},
                            vk::push_constants<LayerConstants>(compute)),
      view_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow views"),
      caster_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow casters"),
      mesh_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow caster meshes"),
      feedback_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow feedback") {
  for (PairCapacity& capacity : capacity_) capacity.in_slot.assign(frames_in_flight, 0);
  max_views_per_dispatch_ = context.properties().limits.maxComputeWorkGroupCount[1];
  cull_pipeline_ =
      vk::create_compute_pipeline(context, {shadow_cull_comp, {}, cull_layout_.get(), "shadow cull"});
  draws_pipeline_ =
      vk::create_compute_pipeline(context, {shadow_draws_comp, {}, draws_layout_.get(), "shadow draws"});
  scatter_pipeline_ = vk::create_compute_pipeline(
      context, {shadow_scatter_comp, {}, scatter_layout_.get(), "shadow scatter"});
  if (setting_ != shadows::ShadowRaster::hardware) {
    if (context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
      std::printf(
          "shadowgraph: compute shadow raster on a CPU device: slow, and llvmpipe stops a shader's loops "
          "after 65,535 iterations, which can leave tiles over 512 texels incomplete\n");
    }
    compute_raster_pipeline_ = vk::create_compute_pipeline(
        context, {shadow_raster_comp, {}, compute_raster_layout_.get(), "shadow raster"});
    static_save_pipeline_ = vk::create_compute_pipeline(
        context, {shadow_static_save_comp, {}, static_layers_layout_.get(), "shadow static save"});
    static_restore_pipeline_ = vk::create_compute_pipeline(
        context, {shadow_static_restore_comp, {}, static_layers_layout_.get(), "shadow static restore"});
  }
  opaque_ = make_raster_pipelines(false);
}

ShadowViewBatch::RasterPipelines ShadowViewBatch::make_raster_pipelines(bool cut_out) const {
  using Spirv = std::span<const uint32_t>;
  vk::GraphicsPipelineDesc desc = cut_out ? shadow_cut_out_pipeline_desc(raster_layout_.get(), textures_)
                                          : shadow_pipeline_desc(raster_layout_.get());
  const std::string suffix = cut_out ? " cut out" : "";
  RasterPipelines made;
  desc.vertex_spirv = cut_out ? Spirv(shadow_batch_cut_out_vert) : Spirv(shadow_batch_vert);
  if (cut_out) desc.fragment_spirv = shadow_cut_out_frag;  // 2D maps need none otherwise
  desc.name = "shadow batch maps" + suffix;
  made.map = vk::create_graphics_pipeline(context_, desc);
  desc.fragment_spirv = cut_out ? Spirv(shadow_cube_cut_out_frag) : Spirv(shadow_cube_frag);
  desc.name = "shadow batch cube faces" + suffix;
  made.face = vk::create_graphics_pipeline(context_, desc);
  return made;
}

void ShadowViewBatch::make_cut_out_pipelines() {
  cut_out_ = make_raster_pipelines(true);
  if (compute_raster_pipeline_) {
    compute_raster_cut_out_pipeline_ = vk::create_compute_pipeline(
        context_, {shadow_raster_cut_out_comp, material_pass_constants(0, 0, textures_),
                   compute_raster_layout_.get(), "shadow raster cut out"});
  }
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

bool ShadowViewBatch::all_casters_kept(uint32_t slot) {
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

void ShadowViewBatch::prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene,
                              uint32_t page_size, jobs::ThreadPool* pool) {
  // Where each drawn view goes: the views drawn with every caster first, then those drawn with
  // the moving casters alone (the cull's two dispatches take a range each). How each light is
  // drawn is read on the pool, a byte a light (the views lie hundreds of bytes apart), the places
  // counted here from the bytes, the tiles copied on the pool; then where compute raster puts
  // its depths; then the view records, independent, in chunks on the pool (written once each,
  // in order: they are most of what this frame uploads).
  constexpr uint32_t not_drawn = UINT32_MAX;
  constexpr uint8_t skipped = 0, every_caster = 1, moving_casters = 2;
  const size_t map_count = lights.maps.size();
  const size_t light_count = map_count + lights.cubes.size();
  const auto drawn_as = [](const auto& view) {
    return !view.render ? skipped : view.moving_casters_only ? moving_casters : every_caster;
  };
  drawn_as_.resize(light_count);
  jobs::run_in_pieces(pool, light_count, 64, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      drawn_as_[i] = i < map_count ? drawn_as(lights.maps[i]) : drawn_as(lights.cubes[i - map_count]);
  });
  first_view_.assign(light_count, not_drawn);
  uint32_t next = 0;
  for (const uint8_t pass : {every_caster, moving_casters}) {
    for (size_t i = 0; i < light_count; ++i) {
      if (drawn_as_[i] != pass) continue;
      first_view_[i] = next;
      next += i < map_count ? 1 : 6;
    }
    if (pass == every_caster) full_views_ = next;
  }
  view_tiles_.resize(next);
  jobs::run_in_pieces(pool, light_count, 64, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      if (first_view_[i] == not_drawn) continue;
      if (i < map_count) {
        view_tiles_[first_view_[i]] = lights.maps[i].tile;
      } else {
        const std::array<shadows::AtlasTile, 6>& tiles = lights.cubes[i - map_count].tiles;
        std::copy(tiles.begin(), tiles.end(), view_tiles_.begin() + first_view_[i]);
      }
    }
  });
  const size_t count = view_tiles_.size();

  if (setting_ == shadows::ShadowRaster::automatic) {
    uint64_t large_texels = 0;
    for (const shadows::AtlasTile& tile : view_tiles_) {
      if (tile.size >= shadows::large_tile) large_texels += uint64_t{tile.size} * tile.size;
    }
    raster_ = shadows::raster_for_views(static_cast<uint32_t>(count), large_texels);
  }
  if (raster_ == shadows::ShadowRaster::compute) {
    place_depths();
  } else {
    depth_placement_.place_nowhere(count);
  }

  // The casters of each group (a mesh's casters, consecutive instances), one after the other;
  // layered, the moving ones again after them all.
  meshes_.clear();
  group_first_caster_.clear();
  const std::span<const VkDrawIndexedIndirectCommand> groups = scene.caster_groups();
  const std::span<const scene::Aabb> bounds = scene.instance_bounds();
  first_cut_out_group_ = scene.first_cut_out_group();
  if (first_cut_out_group_ < groups.size() && !cut_out_.map) make_cut_out_pipelines();
  uint32_t caster_count = 0;
  for (uint32_t g = 0; g < groups.size(); ++g) {
    const VkDrawIndexedIndirectCommand& group = groups[g];
    meshes_.push_back({group.indexCount, group.firstIndex, std::bit_cast<uint32_t>(group.vertexOffset),
                       g >= first_cut_out_group_ ? 1u : 0u});
    group_first_caster_.push_back(caster_count);
    caster_count += group.instanceCount;
  }
  caster_count_ = caster_count;
  layered_ = has_static_layers_ && raster_ == shadows::ShadowRaster::compute && count > 0 && caster_count > 0;
  if (!layered_) full_views_ = static_cast<uint32_t>(count);  // every view gets every caster
  moving_casters_.clear();
  if (layered_) {
    for (const uint32_t i : scene.moving_instances()) {
      if (scene.casts_shadow(i)) moving_casters_.push_back(i);
    }
  }
  moving_count_ = static_cast<uint32_t>(moving_casters_.size());

  // Records go straight into the slot's mapped buffers, from the pool's threads: writes into
  // mapped GPU memory go faster from several cores, and a copy through a vector first cost a
  // serial pass over half a megabyte each with a thousand lights.
  view_count_ = static_cast<uint32_t>(count);
  clears_.resize(count);
  auto* views = static_cast<View*>(view_buffers_.reserve(slot, count * sizeof(View)).mapped());
  const auto place_view = [&](uint32_t v, const glm::mat4& view_projection, const glm::vec4& position_far,
                              uint32_t kind) {
    const shadows::AtlasTile& tile = view_tiles_[v];
    // Below 2^32: the static layers are bound whole, within maxStorageBufferRange (atlas_shape).
    const auto layer = static_cast<uint32_t>((uint64_t{tile.page} * page_size + tile.y) * page_size + tile.x);
    views[v] = {view_projection, shadows::tile_clip_transform(tile, page_size), position_far,
                glm::uvec4(tile.page, kind, tile.size, 0u),
                glm::uvec4(depth_placement_.places()[v], layer, page_size)};
    clears_[v] = tile_clear(tile);
  };
  jobs::run_in_pieces(pool, light_count, 64, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const uint32_t first = first_view_[i];
      if (first == not_drawn) continue;
      if (i < lights.maps.size()) {
        const shadows::ShadowMapView& map = lights.maps[i];
        place_view(first, map.view.view_projection(), map.reach, view_kind_map);
        continue;
      }
      const shadows::ShadowCubeView& cube = lights.cubes[i - lights.maps.size()];
      for (uint32_t face = 0; face < 6; ++face) {
        place_view(first + face, cube.views.view_projection[face], cube.position_far, view_kind_face);
      }
    }
  });

  // A caster's group word: its group, whether it moves (layered) and whether it is transparent.
  const auto group_word = [&](uint32_t instance, uint32_t group, bool moving) {
    return group | (moving ? caster_moving : 0u) |
           (scene.draw_class(instance) & draw_blended ? caster_blended : 0u);
  };
  const auto group_of = [&](uint32_t instance) {
    return static_cast<uint32_t>(std::upper_bound(groups.begin(), groups.end(), instance,
                                                  [](uint32_t i, const VkDrawIndexedIndirectCommand& g) {
                                                    return i < g.firstInstance;
                                                  }) -
                                 groups.begin() - 1);
  };
  auto* casters = static_cast<Caster*>(
      caster_buffers_.reserve(slot, (caster_count + moving_count_) * sizeof(Caster)).mapped());
  // Pieces of 512 casters (16 KiB of records): 15,000 casters in pieces of 2,048 left half of
  // 16 threads without a piece.
  jobs::run_in_pieces(pool, caster_count, 512, [&](size_t begin, size_t end) {
    auto g = static_cast<uint32_t>(
        std::upper_bound(group_first_caster_.begin(), group_first_caster_.end(), begin) -
        group_first_caster_.begin() - 1);
    for (size_t c = begin; c < end; ++c) {
      while (g + 1 < groups.size() && c >= group_first_caster_[g + 1]) ++g;
      const uint32_t i = groups[g].firstInstance + static_cast<uint32_t>(c - group_first_caster_[g]);
      const uint32_t group = group_word(i, g, layered_ && scene.moving(i));
      casters[c] = {glm::vec4(bounds[i].min, as_float(group)), glm::vec4(bounds[i].max, as_float(i))};
    }
  });
  jobs::run_in_pieces(pool, moving_count_, 1024, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const uint32_t i = moving_casters_[k];
      casters[caster_count + k] = {glm::vec4(bounds[i].min, as_float(group_word(i, group_of(i), true))),
                                   glm::vec4(bounds[i].max, as_float(i))};
    }
  });
  mesh_buffers_.write(slot, std::span<const glm::uvec4>(meshes_));
  const std::array<uint32_t, 2> zeros{};
  feedback_.write(slot, std::span<const uint32_t>(zeros));

  const bool drawn = view_count_ > 0 && caster_count_ > 0;
  const std::array<uint64_t, 2> pairs{uint64_t{full_views_} * caster_count_,
                                      uint64_t{view_count_} * moving_count_};
  for (size_t list = 0; list < capacity_.size(); ++list) {
    PairCapacity& capacity = capacity_[list];
    capacity.now = std::clamp<uint64_t>(pairs[list], 1, capacity.limit);
    capacity.in_slot[slot] = drawn && pairs[list] > 0 ? capacity.now : 0;
  }
}

void ShadowViewBatch::place_depths() {
  if (!depth_placement_.place(view_tiles_)) return;
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
  if (view_count_ == 0) return atlas;
  if (caster_count_ == 0) return add_hardware_raster(graph, atlas, scene, slot, {}, {}, {});
  const bool compute = raster_ == shadows::ShadowRaster::compute;
  const bool moving_list = layered_ && moving_count_ > 0;
  const auto group_count = static_cast<uint32_t>(meshes_.size());
  BatchConstants constants{caster_count_, group_count, static_cast<uint32_t>(capacity_[0].now), 0u};
  constants.skip_moving = layered_ ? 1 : 0;
  constants.moving_capacity = static_cast<uint32_t>(capacity_[1].now);
  const uint32_t draw_count = view_kinds * group_count;
  const VkBuffer view_buffer = view_buffers_.buffer(slot).handle();
  const VkBuffer caster_buffer = caster_buffers_.buffer(slot).handle();

  struct Buffers {
    rg::BufferHandle counts, pairs, moving_pairs, draws, depths;
  } b{};
  graph.add_pass(
      "shadow cull reset",
      [&](rg::PassBuilder& p) {
        b.counts = p.write(p.create_buffer("shadow draw counts", {counts_header_bytes + 2 * draw_count * 4}),
                           rg::Usage::transfer);
        if (compute) {
          b.depths = p.write(
              p.create_buffer("shadow depths", {frame_steady(depth_placement_.texels() * sizeof(float))}),
              rg::Usage::transfer);
        }
        return b;
      },
      [](const Buffers& written, const vk::PassRecorder& rec) {
        vkCmdFillBuffer(rec.cmd(), rec.buffer(written.counts), 0, VK_WHOLE_SIZE, 0);
        // The far plane, 1.0f: what a cleared tile holds.
        if (written.depths.valid())
          vkCmdFillBuffer(rec.cmd(), rec.buffer(written.depths), 0, VK_WHOLE_SIZE, 0x3F800000u);
      });
  graph.add_pass(
      "shadow cull",
      [&](rg::PassBuilder& p) {
        b.counts = p.write(b.counts, rg::Usage::storage_compute);
        b.pairs =
            p.write(p.create_buffer("shadow culled pairs", {frame_steady(capacity_[0].now * pair_bytes)}),
                    rg::Usage::storage_compute);
        if (moving_list) {
          b.moving_pairs =
              p.write(p.create_buffer("shadow moving pairs", {frame_steady(capacity_[1].now * pair_bytes)}),
                      rg::Usage::storage_compute);
        }
        return b;
      },
      [this, constants, view_buffer, caster_buffer](const Buffers& written, const vk::PassRecorder& rec) {
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, cull_pipeline_.get());
        // List 0: the views drawn with every caster against every still caster (every caster,
        // unlayered); list 1: every view against the moving casters.
        const auto cull = [&](rg::BufferHandle pairs, BatchConstants list, uint32_t view_count) {
          const VkDescriptorSet set = cull_layout_.write(rec.allocate_set(cull_layout_))
                                          .buffer(shadow_views_binding, view_buffer)
                                          .buffer(shadow_casters_binding, caster_buffer)
                                          .buffer(culled_pairs_binding, rec.buffer(pairs))
                                          .buffer(draw_counts_binding, rec.buffer(written.counts))
                                          .update();
          cull_layout_.bind_compute(rec.cmd(), set);
          const uint32_t columns = (list.caster_count + 63) / 64;
          for (uint32_t base = 0; base < view_count; base += max_views_per_dispatch_) {
            list.view_base = base;
            cull_layout_.push(rec.cmd(), list);
            vkCmdDispatch(rec.cmd(), columns, std::min(max_views_per_dispatch_, view_count - base), 1);
          }
        };
        if (full_views_ > 0) cull(written.pairs, constants, full_views_);
        if (written.moving_pairs.valid()) {
          BatchConstants moving = constants;
          moving.caster_base = caster_count_;
          moving.caster_count = moving_count_;
          moving.capacity = constants.moving_capacity;
          moving.list = 1;
          moving.skip_moving = 0;
          cull(written.moving_pairs, moving, views());
        }
      });
  graph.add_pass(
      "shadow draws",
      [&](rg::PassBuilder& p) {
        b.counts = p.write(b.counts, rg::Usage::storage_compute);
        b.draws =
            p.write(p.create_buffer("shadow draw commands",
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
  return compute ? add_compute_raster(graph, atlas, scene, slot, b.pairs, b.moving_pairs, b.counts, b.draws,
                                      b.depths, static_layers)
                 : add_hardware_raster(graph, atlas, scene, slot, b.pairs, b.counts, b.draws);
}

void ShadowViewBatch::add_static_layer_pass(rg::RenderGraph& graph, const char* name, uint32_t slot,
                                            bool save, uint32_t first, uint32_t count,
                                            rg::BufferHandle& depths, rg::BufferHandle& static_layers) const {
  uint64_t largest = 0;
  for (uint32_t v = first; v < first + count; ++v) {
    largest = std::max<uint64_t>(largest, uint64_t{view_tiles_[v].size} * view_tiles_[v].size);
  }
  const auto chunks =
      static_cast<uint32_t>((largest + layer_texels_per_workgroup - 1) / layer_texels_per_workgroup);
  graph.add_pass(
      name,
      [&](rg::PassBuilder& p) {
        if (save) {
          p.read(depths, rg::Usage::storage_compute);
          static_layers = p.write(static_layers, rg::Usage::storage_compute);
        } else {
          p.read(static_layers, rg::Usage::storage_compute);
          depths = p.write(depths, rg::Usage::storage_compute);
        }
      },
      [this, slot, save, first, count, chunks, depths, static_layers](const vk::PassRecorder& rec) {
        const VkDescriptorSet set = static_layers_layout_.write(rec.allocate_set(static_layers_layout_))
                                        .buffer(shadow_views_binding, view_buffers_.buffer(slot).handle())
                                        .buffer(shadow_depths_binding, rec.buffer(depths))
                                        .buffer(static_layers_binding, rec.buffer(static_layers))
                                        .update();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE,
                          (save ? static_save_pipeline_ : static_restore_pipeline_).get());
        static_layers_layout_.bind_compute(rec.cmd(), set);
        static_layers_layout_.push(rec.cmd(), LayerConstants{first, count});
        vkCmdDispatch(rec.cmd(), std::min(count, max_workgroups_x), chunks, 1);
      });
}

rg::ImageHandle ShadowViewBatch::add_hardware_raster(rg::RenderGraph& graph, rg::ImageHandle atlas,
                                                     const GpuScene& scene, uint32_t slot,
                                                     rg::BufferHandle pairs, rg::BufferHandle counts,
                                                     rg::BufferHandle draws) const {
  const auto group_count = static_cast<uint32_t>(meshes_.size());
  const BatchConstants constants{caster_count_, group_count, static_cast<uint32_t>(capacity_[0].now), 0u};
  const VkBuffer view_buffer = view_buffers_.buffer(slot).handle();
  const VkBuffer caster_buffer = caster_buffers_.buffer(slot).handle();
  rg::BufferHandle sorted;
  if (draws.valid()) {
    // Execute gets the sorted pairs from setup: they do not exist before it runs.
    graph.add_pass(
        "shadow scatter",
        [&](rg::PassBuilder& p) {
          p.read(draws, rg::Usage::indirect);
          p.read(pairs, rg::Usage::storage_compute);
          counts = p.write(counts, rg::Usage::storage_compute);
          sorted =
              p.write(p.create_buffer("shadow sorted pairs", {frame_steady(capacity_[0].now * pair_bytes)}),
                      rg::Usage::storage_compute);
          return sorted;
        },
        [this, constants, view_buffer, caster_buffer, pairs, counts, draws](rg::BufferHandle sorted,
                                                                            const vk::PassRecorder& rec) {
          const VkDescriptorSet set = scatter_layout_.write(rec.allocate_set(scatter_layout_))
                                          .buffer(shadow_views_binding, view_buffer)
                                          .buffer(shadow_casters_binding, caster_buffer)
                                          .buffer(culled_pairs_binding, rec.buffer(pairs))
                                          .buffer(draw_counts_binding, rec.buffer(counts))
                                          .buffer(view_instances_binding, rec.buffer(sorted))
                                          .update();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, scatter_pipeline_.get());
          scatter_layout_.bind_compute(rec.cmd(), set);
          scatter_layout_.push(rec.cmd(), constants);
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(draws), 0);
        });
  }
  graph.add_pass(
      "shadow views",
      [&](rg::PassBuilder& p) {
        if (draws.valid()) {
          p.read(draws, rg::Usage::indirect);
          p.read(sorted, rg::Usage::storage_vertex);
        }
        atlas = p.write(atlas, rg::Usage::depth_attachment);  // kept: cached tiles stay
      },
      [this, &scene, slot, group_count, view_buffer, draws, sorted](const vk::PassRecorder& rec) {
        const VkClearAttachment far{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {.depthStencil = {1.0f, 0}}};
        vkCmdClearAttachments(rec.cmd(), 1, &far, static_cast<uint32_t>(clears_.size()), clears_.data());
        if (!draws.valid() || !scene.bind_geometry(rec.cmd())) return;
        rec.set_full_viewport();
        const VkDescriptorSet set =
            raster_layout_.write(rec.allocate_set(raster_layout_))
                .buffer(instances_binding, scene.instances(slot).handle())
                .buffer(shadow_views_binding, view_buffer)
                .buffer(view_instances_binding, rec.buffer(sorted))
                .image(material_textures_binding, textures_.array().view(), textures_.sampler())
                .update();
        raster_layout_.bind(rec.cmd(), set);
        // Per view kind, its draws by caster group: the opaque groups', then the cut-out ones'.
        const VkBuffer commands = rec.buffer(draws);
        constexpr VkDeviceSize stride = sizeof(VkDrawIndexedIndirectCommand);
        const uint32_t opaque = first_cut_out_group_;
        const auto draw = [&](VkPipeline pipeline, uint32_t first, uint32_t count) {
          if (count == 0) return;
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
          vkCmdDrawIndexedIndirect(rec.cmd(), commands, draws_header_bytes + first * stride, count, stride);
        };
        draw(opaque_.map.get(), 0, opaque);
        draw(cut_out_.map.get(), opaque, group_count - opaque);
        draw(opaque_.face.get(), group_count, opaque);
        draw(cut_out_.face.get(), group_count + opaque, group_count - opaque);
      });
  return atlas;
}

rg::ImageHandle ShadowViewBatch::add_compute_raster(rg::RenderGraph& graph, rg::ImageHandle atlas,
                                                    const GpuScene& scene, uint32_t slot,
                                                    rg::BufferHandle pairs, rg::BufferHandle moving_pairs,
                                                    rg::BufferHandle counts, rg::BufferHandle draws,
                                                    rg::BufferHandle depths,
                                                    rg::BufferHandle static_layers) const {
  const auto raster = [&](const char* name, rg::BufferHandle list_pairs, uint32_t list) {
    BatchConstants constants{caster_count_, static_cast<uint32_t>(meshes_.size()),
                             static_cast<uint32_t>(capacity_[list].now), 0u};
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
        [this, &scene, slot, constants, list_pairs, counts, draws, depths, dispatch,
         cut_out = first_cut_out_group_ < meshes_.size()](const vk::PassRecorder& rec) {
          const VkDescriptorSet set =
              compute_raster_layout_.write(rec.allocate_set(compute_raster_layout_))
                  .buffer(instances_binding, scene.instances(slot).handle())
                  .buffer(shadow_views_binding, view_buffers_.buffer(slot).handle())
                  .buffer(shadow_casters_binding, caster_buffers_.buffer(slot).handle())
                  .buffer(caster_meshes_binding, mesh_buffers_.buffer(slot).handle())
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
  raster("shadow raster", pairs, 0);
  if (layered_ && full_views_ > 0) {
    add_static_layer_pass(graph, "shadow static save", slot, true, 0, full_views_, depths, static_layers);
  }
  // The restored views' squares are not list 0's, so restoring comes late: its wait for the
  // previous frame's save would otherwise come before the frame's culling and rasterizing.
  if (layered_ && full_views_ < view_count_) {
    add_static_layer_pass(graph, "shadow static restore", slot, false, full_views_, view_count_ - full_views_,
                          depths, static_layers);
  }
  if (moving_pairs.valid()) raster("shadow raster moving", moving_pairs, 1);
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
