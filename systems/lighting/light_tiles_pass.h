#pragma once
// Light culling for tiled lighting (shaders/light_tiles.comp): per screen tile of
// LIGHT_TILE_SIZE pixels, the lights that reach the tile's visible surfaces, grouped by light
// group, and per group the tiles to shade with their indirect dispatch.
#include <cstdint>

#include <glm/glm.hpp>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/unique_handle.h"

namespace sg {

namespace tiles {
using uint = std::uint32_t;
#include "shaders/light_tile_layout.glsl"
}  // namespace tiles

// The culling's outputs, laid out as shaders/light_tiles.comp documents.
struct LightTiles {
  rg::BufferHandle lights;  // per tile, MAX_LIGHTS_PER_TILE light indices
  rg::BufferHandle ranges;  // per tile and group: first entry, count
  rg::BufferHandle tiles;   // per group, the tiles that have its lights
  // Per group a VkDispatchIndirectCommand (a workgroup per tile), at a 16-byte stride.
  rg::BufferHandle commands;
};

struct LightTileGrid {
  uint32_t across = 0;
  uint32_t down = 0;
  uint32_t count() const { return across * down; }
  static LightTileGrid of(uint32_t width, uint32_t height);
};

// How the culling runs: a workgroup per tile, its threads side by side (shaders/light_tiles.comp,
// GPUs), or an invocation per tile with no barriers (shaders/light_tiles_serial.comp, CPU drivers,
// which switch between SIMD batches at every barrier). Both write the same lists; automatic picks
// by device type.
enum class LightCullingShape { automatic, workgroup_per_tile, thread_per_tile };

class LightTilesPass {
 public:
  // With `transparent_bounds`, tiles are bounded by where transparent surfaces may lie as well
  // (add_to's `transparent_bounds`, TransparentPass).
  LightTilesPass(vk::VulkanContext& context, uint32_t frames_in_flight,
                 LightCullingShape shape = LightCullingShape::automatic, bool transparent_bounds = false);
  LightCullingShape shape() const { return shape_; }

  // Bytes of each output for `grid`, for callers that provide their own buffers.
  static uint64_t lights_bytes(LightTileGrid grid);
  static uint64_t ranges_bytes(LightTileGrid grid);
  static uint64_t tiles_bytes(LightTileGrid grid);
  static uint64_t commands_bytes();
  // The offset in `commands` of `group`'s dispatch.
  static uint64_t dispatch_offset(uint32_t group);

  // Culls the first `light_count` records of `lights` (sorted by group) against the tiles of
  // `depth` (the scene's D32 depth, rendered with `view_projection`), and on a pass made with
  // transparent bounds against `transparent_bounds` too (transparent_tile_bounds, a vec2 a tile).
  // Writes into `outputs` when given (imported buffers of the sizes above), else into new
  // transients; returns the outputs' new versions. `lights` and `transparent_bounds` must live
  // until the frame is recorded. The slot's count of dropped pairs (take_dropped_pairs) grows.
  LightTiles add_to(rg::RenderGraph& graph, uint32_t slot, rg::ImageHandle depth, const vk::Buffer& lights,
                    uint32_t light_count, const glm::mat4& view_projection,
                    const LightTiles* outputs = nullptr,
                    const vk::Buffer* transparent_bounds = nullptr) const;

  // After FrameRing::begin_frame returned `slot`, before add_to: the (tile, light) pairs the frame
  // that last used the slot could not list (more than MAX_LIGHTS_PER_TILE lights reached a
  // tile), and zero for this frame.
  uint64_t take_dropped_pairs(uint32_t slot);

 private:
  LightCullingShape shape_;
  bool transparent_bounds_;
  vk::FrameBuffers feedback_;  // per slot: the dropped pairs
  vk::UniqueSampler nearest_;
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
};

}  // namespace sg
