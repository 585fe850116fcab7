// SPDX-License-Identifier: MIT
#pragma once
// The CPU side of a ShadowViewBatch frame: one record per shadow view due (a 2D map, or one face
// of a point light's cube: its matrix, its atlas tile and frustum) and one per shadow caster
// (world bounds, mesh, instance), written straight into the frame slot's buffers; and what the
// batch's passes share with their shaders about those buffers (shaders/shadow_views.glsl,
// shaders/shadow_batch_compute.glsl).
//
// The views drawn with every caster come first, then those drawn with the moving casters alone
// (ShadowMapView::moving_casters_only): the cull takes a range each. The casters come by caster
// group (a mesh's casters, consecutive instances); on layered frames
// (ShadowViewBatch::static_layers_kept) the moving ones come again after them all, for pair
// list 1.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "ecs/fwd.h"
#include "ecs/jobs/parallel_pieces.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/shadows/frame_lights.h"

namespace sg {

namespace shadow_batch {

// The batch's passes bind storage buffers, mostly to compute shaders: their layouts' shorthand.
constexpr VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;

// shaders/shadow_views.glsl's VIEW_KINDS: 2D maps and cube faces, each kind drawn by its own
// draws.
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
  uint32_t block_base = 0;
};

// shaders/shadow_views.glsl's CASTER_BLOCK: the casters of a list whose bounds one block record
// holds, so that the cull tests a view against a block before its casters.
constexpr uint32_t caster_block = 64;
inline uint32_t caster_blocks(uint32_t casters) { return (casters + caster_block - 1) / caster_block; }

// shaders/shadow_draws.comp's Draws: the scatter's dispatch, the compute raster's of list 0 and
// of list 1, then the draws.
constexpr VkDeviceSize scatter_dispatch_offset = 0;
constexpr VkDeviceSize raster_dispatch_offset = 16;
constexpr VkDeviceSize moving_raster_dispatch_offset = 32;
constexpr VkDeviceSize draws_header_bytes = 48;

// A culled pair: caster record, view.
constexpr VkDeviceSize pair_bytes = 2 * sizeof(uint32_t);

// The size to declare for a transient buffer needing `bytes`: rounded up to a power of two, so
// that frames drawing different numbers of views keep the graph's shape, and with it the
// compiled plan and its memory (rg::PlanCache), instead of recompiling and reallocating.
inline uint64_t frame_steady(uint64_t bytes) { return std::bit_ceil(std::max<uint64_t>(bytes, 256)); }

}  // namespace shadow_batch

// A prepared frame as its passes read it; valid until the next lay_out.
struct ShadowBatchFrame {
  uint32_t views = 0;  // records in view_records
  // The first views, drawn with every caster; the others are drawn with the moving casters alone.
  uint32_t full_views = 0;
  uint32_t casters = 0;         // records of every caster, by caster group
  uint32_t moving_casters = 0;  // layered: the moving casters' records again, after them
  // After those, a block record per CASTER_BLOCK casters of each list (every caster's, then the
  // moving casters'): their bounds and their layers. Per list, the index of its first.
  std::array<uint32_t, 2> first_block{};
  uint32_t caster_groups = 0;  // records in mesh_records (shaders/shadow_views.glsl's CasterMesh)
  // GpuScene::first_cut_out_group: the groups from here on are drawn cut out.
  uint32_t first_cut_out_group = 0;
  bool layered = false;                       // static layers kept: moving casters drawn apart (list 1)
  std::span<const shadows::AtlasTile> tiles;  // per view
  // The slot's, once written.
  VkBuffer view_records = VK_NULL_HANDLE;
  VkBuffer caster_records = VK_NULL_HANDLE;
  VkBuffer mesh_records = VK_NULL_HANDLE;
};

class ShadowBatchRecords {
 public:
  ShadowBatchRecords(vk::VulkanContext& context, uint32_t frames_in_flight);

  // Which views of `lights` render this frame (`render`), in order, and their tiles; how
  // `scene`'s casters lie by group. With `pool`, the lights are read on its threads. The frame
  // then has its counts, tiles and groups; write adds the moving casters and the buffers.
  const ShadowBatchFrame& lay_out(const shadows::FrameLights& lights, const GpuScene& scene,
                                  jobs::ThreadPool* pool);
  // Writes the laid-out frame's records into `slot`'s buffers: `lights` and `scene` as laid out,
  // the views in an atlas of `page_size` texels a page, view v's depths at `depth_places[v]` in
  // the compute raster's buffer (DepthPlacement::places). `layered`: the moving casters are
  // drawn apart; without, every view is drawn with every caster. With `pool`, the records are
  // written on its threads.
  const ShadowBatchFrame& write(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene,
                                uint32_t page_size, std::span<const glm::uvec2> depth_places, bool layered,
                                jobs::ThreadPool* pool);

  const ShadowBatchFrame& frame() const { return frame_; }

 private:
  void write_views(uint32_t slot, const shadows::FrameLights& lights, uint32_t page_size,
                   std::span<const glm::uvec2> depth_places, jobs::ThreadPool* pool);
  void write_casters(uint32_t slot, const GpuScene& scene, jobs::ThreadPool* pool);

  vk::FrameBuffers view_buffers_;
  vk::FrameBuffers caster_buffers_;
  vk::FrameBuffers mesh_buffers_;
  ShadowBatchFrame frame_;
  uint32_t every_caster_views_ = 0;  // the views whose lights want every caster, first
  struct DrawnLight {
    uint32_t index;       // among maps, then cubes
    uint32_t first_view;  // its views' first
    uint8_t drawn_as;     // with every caster, or the moving ones only
  };
  std::vector<DrawnLight> drawn_;  // the lights drawn, in order
  jobs::KeepScratch keep_scratch_;
  std::vector<shadows::AtlasTile> tiles_;     // per view
  std::vector<glm::uvec4> meshes_;            // per caster group: its CasterMesh
  std::vector<uint32_t> group_first_caster_;  // per caster group: its first caster record
  std::vector<uint32_t> moving_casters_;      // layered: the moving casters' instances
};

}  // namespace sg
