// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_batch_records.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <limits>

#include "ecs/jobs/thread_pool.h"
#include "systems/shadows/atlas_tile_coords.h"

namespace sg {
namespace {

// shaders/shadow_views.glsl's VIEW_KIND_MAP and VIEW_KIND_FACE.
constexpr uint32_t view_kind_map = 0;
constexpr uint32_t view_kind_face = 1;

// shaders/shadow_views.glsl's CASTER_MOVING and CASTER_BLENDED, in a caster record's group.
constexpr uint32_t caster_moving = 0x80000000u;
constexpr uint32_t caster_blended = 0x40000000u;

// shaders/shadow_views.glsl's ShadowView.
struct ViewRecord {
  glm::mat4 view_projection;
  glm::vec4 tile;
  glm::vec4 position_far;
  glm::uvec4 info;
  glm::uvec4 raster;
};

// shaders/shadow_views.glsl's ShadowCaster.
struct CasterRecord {
  glm::vec3 lo;
  uint32_t group;
  glm::vec3 hi;
  uint32_t instance;  // below 2^24 (GpuScene::max_instances); above, the shadow layers
};
static_assert(sizeof(CasterRecord) == 32 && offsetof(CasterRecord, hi) == 16);

// A caster record's instance word: the instance below bit 24, its shadow layers above.
constexpr uint32_t layers_shift = 24;
constexpr uint32_t layers_bits = ~0u << layers_shift;

uint32_t instance_word(const GpuScene& scene, uint32_t instance) {
  return instance | uint32_t{scene.shadow_layers(instance)} << layers_shift;
}

// A list's block records (shadow_batch::caster_block), gathered while its casters are written: a
// piece of casters starting at a block's first writes whole blocks. A block holds the bounds and
// the layers of the casters its cull may keep; with none, it has no layers.
class BlockWriter {
 public:
  BlockWriter(CasterRecord* blocks, size_t casters) : blocks_(blocks), casters_(casters) {}

  // After caster `k` of the list (`kept`: the cull may keep it), writes the block it ends.
  void add(size_t k, const CasterRecord& caster, bool kept) {
    if (kept) {
      block_.lo = glm::min(block_.lo, caster.lo);
      block_.hi = glm::max(block_.hi, caster.hi);
      block_.instance |= caster.instance & layers_bits;
    }
    if ((k + 1) % shadow_batch::caster_block == 0 || k + 1 == casters_) {
      blocks_[k / shadow_batch::caster_block] = block_;
      block_ = empty;
    }
  }

 private:
  static constexpr CasterRecord empty{glm::vec3(std::numeric_limits<float>::max()), 0,
                                      glm::vec3(std::numeric_limits<float>::lowest()), 0};
  CasterRecord* blocks_;
  size_t casters_;
  CasterRecord block_ = empty;
};

// How a light's views are drawn this frame.
constexpr uint8_t skipped = 0, with_every_caster = 1, with_moving_casters = 2;

}  // namespace

ShadowBatchRecords::ShadowBatchRecords(vk::VulkanContext& context, uint32_t frames_in_flight)
    : view_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow views"),
      caster_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow casters"),
      mesh_buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow caster meshes") {}

const ShadowBatchFrame& ShadowBatchRecords::lay_out(const shadows::FrameLights& lights, const GpuScene& scene,
                                                    jobs::ThreadPool* pool) {
  // Where each drawn view goes: the views drawn with every caster first, then those drawn with
  // the moving casters alone (the cull's two dispatches take a range each). How each light is
  // drawn is read on the pool (the views lie hundreds of bytes apart) as the drawn lights are
  // listed; their places are counted here, their tiles copied on the pool. Of 100,000 lights
  // about 1,500 are drawn a frame, so only those are walked after the listing.
  const size_t map_count = lights.maps.size();
  const size_t light_count = map_count + lights.cubes.size();
  const auto drawn_as = [](const auto& view) {
    return !view.render ? skipped : view.moving_casters_only ? with_moving_casters : with_every_caster;
  };
  const auto light_drawn_as = [&](size_t i) {
    return i < map_count ? drawn_as(lights.maps[i]) : drawn_as(lights.cubes[i - map_count]);
  };
  drawn_.resize(light_count);
  drawn_.resize(jobs::keep_in_pieces(
      pool, light_count, 256, keep_scratch_, [&](size_t i) { return light_drawn_as(i) != skipped; },
      [&](size_t i, size_t rank) {
        drawn_[rank] = {static_cast<uint32_t>(i), 0, light_drawn_as(i)};
      }));
  uint32_t next = 0;
  for (const uint8_t pass : {with_every_caster, with_moving_casters}) {
    for (DrawnLight& light : drawn_) {
      if (light.drawn_as != pass) continue;
      light.first_view = next;
      next += light.index < map_count ? 1 : 6;
    }
    if (pass == with_every_caster) every_caster_views_ = next;
  }
  tiles_.resize(next);
  jobs::run_in_pieces(pool, drawn_.size(), 64, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const DrawnLight& light = drawn_[k];
      if (light.index < map_count) {
        tiles_[light.first_view] = lights.maps[light.index].tile;
      } else {
        const std::array<shadows::AtlasTile, 6>& tiles = lights.cubes[light.index - map_count].tiles;
        std::copy(tiles.begin(), tiles.end(), tiles_.begin() + light.first_view);
      }
    }
  });

  // The casters of each group, one after the other.
  meshes_.clear();
  group_first_caster_.clear();
  const std::span<const VkDrawIndexedIndirectCommand> groups = scene.caster_groups();
  const uint32_t first_cut_out_group = scene.first_cut_out_group();
  uint32_t caster_count = 0;
  for (uint32_t g = 0; g < groups.size(); ++g) {
    const VkDrawIndexedIndirectCommand& group = groups[g];
    meshes_.push_back({group.indexCount, group.firstIndex, std::bit_cast<uint32_t>(group.vertexOffset),
                       g >= first_cut_out_group ? 1u : 0u});
    group_first_caster_.push_back(caster_count);
    caster_count += group.instanceCount;
  }
  frame_ = {.views = next,
            .full_views = next,
            .casters = caster_count,
            .caster_groups = static_cast<uint32_t>(groups.size()),
            .first_cut_out_group = first_cut_out_group,
            .tiles = tiles_};
  return frame_;
}

const ShadowBatchFrame& ShadowBatchRecords::write(uint32_t slot, const shadows::FrameLights& lights,
                                                  const GpuScene& scene, uint32_t page_size,
                                                  std::span<const glm::uvec2> depth_places, bool layered,
                                                  jobs::ThreadPool* pool) {
  frame_.layered = layered;
  if (layered) frame_.full_views = every_caster_views_;  // else every view gets every caster
  moving_casters_.clear();
  if (layered) {
    for (const uint32_t i : scene.moving_instances()) {
      if (scene.casts_shadow(i)) moving_casters_.push_back(i);
    }
  }
  frame_.moving_casters = static_cast<uint32_t>(moving_casters_.size());
  // Records go straight into the slot's mapped buffers, from the pool's threads: writes into
  // mapped GPU memory go faster from several cores, and a copy through a vector first cost a
  // serial pass over half a megabyte each with a thousand lights.
  write_views(slot, lights, page_size, depth_places, pool);
  write_casters(slot, scene, pool);
  frame_.mesh_records = mesh_buffers_.write(slot, std::span<const glm::uvec4>(meshes_)).handle();
  return frame_;
}

void ShadowBatchRecords::write_views(uint32_t slot, const shadows::FrameLights& lights, uint32_t page_size,
                                     std::span<const glm::uvec2> depth_places, jobs::ThreadPool* pool) {
  // Independent, in chunks on the pool (written once each, in order: they are most of what this
  // frame uploads).
  const vk::Buffer& buffer = view_buffers_.reserve(slot, frame_.views * sizeof(ViewRecord));
  frame_.view_records = buffer.handle();
  auto* views = static_cast<ViewRecord*>(buffer.mapped());
  const auto place_view = [&](uint32_t v, const glm::mat4& view_projection, const glm::vec4& position_far,
                              uint32_t kind, uint32_t caster_mask) {
    const shadows::AtlasTile& tile = tiles_[v];
    // Below 2^32: the static layers are bound whole, within maxStorageBufferRange (atlas_shape).
    const auto layer = static_cast<uint32_t>((uint64_t{tile.page} * page_size + tile.y) * page_size + tile.x);
    views[v] = {view_projection, shadows::tile_clip_transform(tile, page_size), position_far,
                glm::uvec4(tile.page, kind, tile.size, caster_mask),
                glm::uvec4(depth_places[v], layer, page_size)};
  };
  jobs::run_in_pieces(pool, drawn_.size(), 16, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const DrawnLight& light = drawn_[k];
      if (light.index < lights.maps.size()) {
        const shadows::ShadowMapView& map = lights.maps[light.index];
        place_view(light.first_view, map.view.view_projection(), map.reach, view_kind_map, map.caster_mask);
        continue;
      }
      const shadows::ShadowCubeView& cube = lights.cubes[light.index - lights.maps.size()];
      const shadows::CubeViews faces = shadows::face_views(cube);
      for (uint32_t face = 0; face < 6; ++face) {
        place_view(light.first_view + face, faces.view_projection[face], cube.position_far, view_kind_face,
                   cube.caster_mask);
      }
    }
  });
}

void ShadowBatchRecords::write_casters(uint32_t slot, const GpuScene& scene, jobs::ThreadPool* pool) {
  const std::span<const VkDrawIndexedIndirectCommand> groups = scene.caster_groups();
  const std::span<const scene::Aabb> bounds = scene.instance_bounds();
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
  const uint32_t caster_count = frame_.casters;
  frame_.first_block = {caster_count + frame_.moving_casters,
                        caster_count + frame_.moving_casters + shadow_batch::caster_blocks(caster_count)};
  const vk::Buffer& buffer = caster_buffers_.reserve(
      slot,
      (frame_.first_block[1] + shadow_batch::caster_blocks(frame_.moving_casters)) * sizeof(CasterRecord));
  frame_.caster_records = buffer.handle();
  auto* casters = static_cast<CasterRecord*>(buffer.mapped());
  // Pieces start at multiples of the block, so that each writes whole blocks (BlockWriter).
  static_assert(512 % shadow_batch::caster_block == 0 && 1024 % shadow_batch::caster_block == 0);
  // Pieces of 512 casters (16 KiB of records): 15,000 casters in pieces of 2,048 left half of
  // 16 threads without a piece.
  jobs::run_in_pieces(pool, caster_count, 512, [&](size_t begin, size_t end) {
    auto g = static_cast<uint32_t>(
        std::upper_bound(group_first_caster_.begin(), group_first_caster_.end(), begin) -
        group_first_caster_.begin() - 1);
    BlockWriter blocks(casters + frame_.first_block[0], caster_count);
    for (size_t c = begin; c < end; ++c) {
      while (g + 1 < groups.size() && c >= group_first_caster_[g + 1]) ++g;
      const uint32_t i = groups[g].firstInstance + static_cast<uint32_t>(c - group_first_caster_[g]);
      const bool moving = frame_.layered && scene.moving(i);
      const CasterRecord caster{bounds[i].min, group_word(i, g, moving), bounds[i].max,
                                instance_word(scene, i)};
      casters[c] = caster;             // mapped memory, written and never read back
      blocks.add(c, caster, !moving);  // list 0 on layered frames leaves moving casters to list 1
    }
  });
  jobs::run_in_pieces(pool, moving_casters_.size(), 1024, [&](size_t begin, size_t end) {
    BlockWriter blocks(casters + frame_.first_block[1], moving_casters_.size());
    for (size_t k = begin; k < end; ++k) {
      const uint32_t i = moving_casters_[k];
      const CasterRecord caster{bounds[i].min, group_word(i, group_of(i), true), bounds[i].max,
                                instance_word(scene, i)};
      casters[caster_count + k] = caster;
      blocks.add(k, caster, true);
    }
  });
}

}  // namespace sg
