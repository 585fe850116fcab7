// SPDX-License-Identifier: MIT
#pragma once
// Light culling for tiled lighting (shaders/light_tiles.comp): per screen tile of
// LIGHT_TILE_SIZE pixels, the lights that reach the tile's visible surfaces, grouped by light
// group, and per group the tiles to shade with their indirect dispatch.
#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/lighting/light_list_pool.h"
#include "systems/shadows/light_groups.h"

namespace sg {

namespace tiles {
using uint = std::uint32_t;
#include "shaders/light_tile_layout.glsl"
}  // namespace tiles

// The culling's outputs, laid out as shaders/light_tiles.comp documents.
struct LightTiles {
  rg::BufferHandle lights;  // the pool of every tile's list of light indices (LightListPool)
  rg::BufferHandle ranges;  // per tile and group: first entry, count
  rg::BufferHandle tiles;   // per group, the tiles that have its lights, then per group set its tiles
  // Per group, then per group set, a VkDispatchIndirectCommand (a workgroup per tile), at a
  // 16-byte stride.
  rg::BufferHandle commands;
};

// A frame's group sets (shaders/light_tiles_interface.glsl): bit g for light group g, 0 for none.
using GroupSets = std::array<uint32_t, tiles::LIGHT_GROUP_SETS>;

// Per combination of light groups (bit g for group g), the tiles whose groups with lights it was.
using TilesByGroups = std::array<uint32_t, std::size_t{1} << shadows::light_group_count>;

struct LightTileGrid {
  uint32_t across = 0;
  uint32_t down = 0;
  uint32_t count() const { return across * down; }
  // The grid of coarse tiles over this one (shaders/light_tiles_coarse.glsl).
  LightTileGrid coarse() const;
  static LightTileGrid of(uint32_t width, uint32_t height);
};

// How the culling runs: a coarse pass, then a workgroup per tile, its threads side by side
// (shaders/light_tiles_coarse.comp and light_tiles.comp, GPUs), or an invocation per tile with no
// barriers, testing every light (shaders/light_tiles_serial.comp, CPU drivers, which switch between
// SIMD batches at every barrier). Both write the same lists; automatic picks by device type.
enum class LightCullingShape { automatic, workgroup_per_tile, thread_per_tile };

class LightTilesPass {
 public:
  // With `transparent_bounds`, tiles are bounded by where transparent surfaces may lie as well
  // (add_to's `transparent_bounds`, TransparentPass). The lists' pool holds at most
  // `most_pool_entries` entries, the coarse tiles' pool `most_coarse_entries` (0: what one storage
  // buffer reaches, up to 1 GiB).
  LightTilesPass(vk::VulkanContext& context, uint32_t frames_in_flight,
                 LightCullingShape shape = LightCullingShape::automatic, bool transparent_bounds = false,
                 uint64_t most_pool_entries = 0, uint64_t most_coarse_entries = 0);
  LightCullingShape shape() const { return shape_; }

  // Bytes of each output for `grid`, for callers that provide their own buffers (whose `lights`
  // may hold any number of entries, 4 bytes each).
  static uint64_t ranges_bytes(LightTileGrid grid);
  static uint64_t tiles_bytes(LightTileGrid grid);
  static uint64_t commands_bytes();
  // The offset in `commands` of `group`'s dispatch, or of the group set's whose place is `group`
  // less light_group_count.
  static uint64_t dispatch_offset(uint32_t group);

  // Culls the first `light_count` records of `lights` (sorted by group) against the tiles of
  // `depth` (the scene's D32 depth, rendered with `view_projection`), and on a pass made with
  // transparent bounds against `transparent_bounds` too (transparent_tile_bounds, a vec2 a tile).
  // Writes into `outputs` when given (imported buffers of the sizes above), else into new
  // transients; returns the outputs' new versions. `lights` and `transparent_bounds` must live
  // until the frame is recorded. The lists' pool holds as many entries as LightListPool sizes, or
  // as the given `outputs->lights` holds. Where the pass runs an invocation per tile, a tile whose
  // groups with lights are one of `group_sets` is listed for that set's dispatch, not its groups'.
  LightTiles add_to(rg::RenderGraph& graph, uint32_t slot, rg::ImageHandle depth, const vk::Buffer& lights,
                    uint32_t light_count, const glm::mat4& view_projection,
                    const LightTiles* outputs = nullptr, const vk::Buffer* transparent_bounds = nullptr,
                    const GroupSets& group_sets = {}) const;

  // After FrameRing::begin_frame returned `slot`, before add_to: the (tile, light) pairs the frame
  // that last used the slot could not list (its pool ran out), zeroed for this frame. What that
  // frame's lists, and its coarse tiles' lists, asked of their pools sizes them for the frames after.
  uint64_t take_dropped_pairs(uint32_t slot);
  // What the frame the last take_dropped_pairs read back asked of the pool: the (tile, light)
  // pairs its lists held, dropped ones included, which the lighting's cost follows.
  uint64_t listed_pairs() const { return listed_pairs_; }
  // That frame's tiles whose lists a CPU driver's guard against endless loops cut short (an
  // invocation per tile; shaders/light_tiles_serial.comp): lights of theirs are missing.
  uint32_t tiles_cut() const { return tiles_cut_; }
  // That frame's tiles by their groups with lights, where it ran an invocation per tile (zeros
  // otherwise): what a frame's group sets are chosen from (TiledLightingPass).
  const TilesByGroups& tiles_by_groups() const { return tiles_by_groups_; }
  // The entries of the pool of the next frame culling `light_count` lights over `grid`.
  uint64_t pool_entries(LightTileGrid grid, uint32_t light_count) const {
    return pool_.entries(grid.count(), light_count);
  }

 private:
  struct CoarseLists;
  struct Constants;
  CoarseLists add_coarse_pass(rg::RenderGraph& graph, uint32_t slot, rg::ImageHandle depth,
                              const vk::Buffer& lights, const Constants& constants,
                              const vk::Buffer* transparent_bounds, LightTileGrid grid) const;

  LightCullingShape shape_;
  bool transparent_bounds_;
  // Per slot, as light_tiles_interface.glsl's Feedback: the dropped pairs, the entries wanted.
  vk::FrameBuffers feedback_;
  LightListPool pool_;
  LightListPool coarse_pool_;  // of the coarse tiles' lists (workgroup_per_tile)
  uint64_t listed_pairs_ = 0;
  uint32_t tiles_cut_ = 0;
  TilesByGroups tiles_by_groups_{};
  vk::UniqueSampler nearest_;
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
  vk::PipelineLayout coarse_layout_;  // workgroup_per_tile only
  vk::UniquePipeline coarse_pipeline_;
};

}  // namespace sg
