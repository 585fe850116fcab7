// SPDX-License-Identifier: MIT
#pragma once
// The scene's drawables on the GPU: the mesh library in one vertex and one index buffer
// (uploaded once), and per frame the instances of every drawable entity plus one indirect draw
// per mesh, so that the camera's view of the whole scene is a single vkCmdDrawIndexedIndirect
// call whatever the number of instances.
//
// Instances are grouped by mesh, shadow casters first within each mesh: the caster groups
// (caster_groups()) and the instances' world bounds are what shadow views cull against
// (ShadowCasterLists).
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "ecs/jobs/thread_pool.h"
#include "ecs/world.h"
#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "systems/gpu/camera.h"
#include "systems/gpu/scene_gpu_types.h"
#include "systems/scene/aabb.h"
#include "systems/scene/layers.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_library.h"

namespace sg {

// What a pipeline reads of scene::Vertex at binding 0 (GpuScene::bind_geometry): the position at
// location 0, then the normal at 1 (surface) and the uv at 2 (surface, position_uv).
enum class VertexInput { position, position_uv, surface };
void scene_vertex_input(vk::GraphicsPipelineDesc& desc, VertexInput input);

// The depth buffer of every pass that draws the scene from the camera, its depth reversed
// (systems/gpu/camera.h): cleared to the far depth, a nearer surface has a greater depth.
inline constexpr rg::Format camera_depth_format = rg::Format::d32_sfloat;
inline constexpr rg::ClearValue camera_depth_clear = rg::ClearValue::depth_of(camera_far_depth);
inline constexpr VkCompareOp camera_depth_test = VK_COMPARE_OP_GREATER;
// Passes that shade what a depth prepass already decided: the nearest surface passes again.
inline constexpr VkCompareOp camera_depth_retest = VK_COMPARE_OP_GREATER_OR_EQUAL;

// How a camera pass draws an instance, a bit each: both faces (double-sided materials; single-
// sided ones have their back faces culled), a mask's cut-out (material.glsl's ALPHA_TEST) and
// transparency.
// Instances are drawn class by class, each class with a pipeline of its own (CameraPipelines).
inline constexpr uint32_t draw_double_sided = 1;
inline constexpr uint32_t draw_masked = 2;
inline constexpr uint32_t draw_blended = 4;  // transparent
inline constexpr uint32_t draw_class_count = 8;
uint32_t draw_class_of(const scene::Material& material);

class GpuScene {
 public:
  // The most instances gather() takes: a shadow caster's record keeps the index in 24 bits
  // (shaders/shadow_views.glsl); so many instances' records alone would take 1.8 GiB.
  static constexpr uint32_t max_instances = 1u << 24;

  GpuScene(vk::VulkanContext& context, const scene::MeshLibrary& meshes, uint32_t frames_in_flight);

  // Gathers every entity with WorldTransform and MeshInstance (Material when present, the
  // default grey otherwise) into instances and draw lists, on the CPU; bounds() and
  // instance_bounds() describe them from here on. Transforms must be up to date
  // (ecs::update_world_transforms). With `pool`, the per-instance work runs on its threads.
  //
  // Incremental: after the first call, only instances whose WorldTransform or Material was
  // written at or after the tick of the previous call are read again, unless a MeshInstance was
  // written or one of the three components removed (then everything is). So always pass the
  // same world, let its tick advance between frames (ecs::World::advance_tick) so that a
  // frame's writes are told from the previous frame's, and keep its removal history back to the
  // previous call (ecs::World::forget_removals_before).
  void gather(const ecs::World& world, jobs::ThreadPool* pool = nullptr);
  // Writes what gather() found into the slot's instance and indirect-draw buffers: only the
  // instances gathered since the slot was last written, unless the order changed or the buffer
  // had to grow (with `pool`, the copy runs on its threads).
  void upload(uint32_t slot, jobs::ThreadPool* pool = nullptr);

  // Binds the vertex and index buffers (scene::Vertex at binding 0, 32-bit indices); false when
  // the scene has no geometry, and nothing may be drawn.
  bool bind_geometry(VkCommandBuffer cmd) const;
  // A camera pass's recording: viewport over the render area, `set` as set 0 of `layout` and
  // `constants` pushed, every opaque instance drawn, each draw class with its pipeline of
  // `pipelines`.
  void draw_camera_pass(const vk::PassRecorder& rec, std::span<const VkPipeline, draw_class_count> pipelines,
                        const vk::PipelineLayout& layout, VkDescriptorSet set,
                        const FrameConstants& constants, uint32_t slot) const;
  // Whether the last gather found instances of `draw_class`, and of any transparent class.
  bool has_draw_class(uint32_t draw_class) const { return class_commands_[draw_class].count > 0; }
  bool has_transparent() const;
  // Orders the transparent instances back to front as seen from `eye`, by their bounds' centres.
  void order_transparent(const glm::vec3& eye);
  // The transparent instances in that order.
  std::span<const uint32_t> transparent_order() const { return transparent_order_; }
  // As draw_camera_pass, the transparent instances in that order, one draw each.
  void draw_transparent(const vk::PassRecorder& rec, std::span<const VkPipeline, draw_class_count> pipelines,
                        const vk::PipelineLayout& layout, VkDescriptorSet set,
                        const FrameConstants& constants) const;

  const vk::Buffer& instances(uint32_t slot) const { return instances_.buffer(slot); }
  // The mesh library's vertices (scene::Vertex) and 32-bit indices, also readable as storage
  // buffers; no handle (VK_NULL_HANDLE) when the scene has no geometry.
  const vk::Buffer& vertices() const { return vertices_; }
  const vk::Buffer& indices() const { return indices_; }
  uint32_t instance_count() const { return static_cast<uint32_t>(bounds_.size()); }
  // Triangles of all instances drawn, as the camera passes draw them (before culling).
  uint64_t triangles() const { return triangles_; }
  // Per (draw class, mesh) with casters: its draw over exactly its casters (firstInstance and
  // instanceCount give their range in the instance buffer).
  std::span<const VkDrawIndexedIndirectCommand> caster_groups() const { return caster_groups_; }
  // The caster groups from this one on are masked or transparent, their shadows cut out
  // (shaders/shadow_cut_out.glsl); the opaque ones come before (draw classes in order).
  uint32_t first_cut_out_group() const { return first_cut_out_group_; }
  // World-space bounds of every instance, in instance-buffer order, and of all of them.
  std::span<const scene::Aabb> instance_bounds() const { return bounds_; }
  // The entity of every instance, in instance-buffer order, as ecs::entity_key.
  std::span<const uint64_t> instance_keys() const { return keys_; }
  const scene::Aabb& bounds() const { return scene_bounds_; }

  // What the last gather() did: ordered every instance anew (new, removed or re-meshed ones), or
  // re-placed only the instances written since the gather before, listed by replaced(), with the
  // bounds they had before it in replaced_bounds_before() and have now in replaced_bounds_after()
  // (same order; copies of instance_bounds() read in order, not one by one across the buffer).
  bool laid_out_in_last_gather() const { return laid_out_at_ == gathers_; }
  std::span<const uint32_t> replaced() const { return changed_; }
  std::span<const scene::Aabb> replaced_bounds_before() const { return bounds_before_; }
  std::span<const scene::Aabb> replaced_bounds_after() const { return bounds_after_; }
  bool casts_shadow(uint32_t instance) const { return items_[instance].caster; }
  // MeshInstance::shadow_layers: the maps of lights whose caster_mask shares a layer draw it.
  scene::LayerMask shadow_layers(uint32_t instance) const { return items_[instance].shadow_layers; }
  uint32_t draw_class(uint32_t instance) const { return items_[instance].draw_class; }
  // Moving instances: those whose bounds changed in a gather since the last layout (the layout
  // makes every instance still again). Shadow maps keep a layer of the other casters and redraw
  // only these over it (ShadowViewBatch). moving_instances() lists them in the order they first
  // moved.
  std::span<const uint32_t> moving_instances() const { return moving_; }
  bool moving(uint32_t instance) const { return moved_at_[instance] != 0; }
  // Whether `instance` first moved in the last gather (it was still before).
  bool first_moved_in_last_gather(uint32_t instance) const { return moved_at_[instance] == gathers_; }

 private:
  vk::Buffer vertices_;
  vk::Buffer indices_;
  std::vector<scene::MeshRange> meshes_;
  vk::FrameBuffers instances_;
  vk::FrameBuffers draws_;

  // Per-frame data and scratch, reused so that gathering allocates nothing once it has grown.
  struct Item {
    uint32_t mesh;
    bool caster;
    bool receiver;  // MeshInstance::receives_shadow
    uint8_t draw_class;
    scene::LayerMask light_layers;
    scene::LayerMask shadow_layers;
    ecs::Entity entity;
  };
  // A draw class's stretch of commands_.
  struct CommandRange {
    uint32_t first = 0;
    uint32_t count = 0;
  };

  // Instance i's record, bounds and key, from its entity (items_[i]).
  void place(const ecs::World& world, size_t i);
  // Re-places the instances written at or after `since`; false, having changed nothing, when
  // instances were added, removed or reordered.
  bool gather_changes(const ecs::World& world, ecs::Tick since, jobs::ThreadPool* pool);
  void gather_all(const ecs::World& world, jobs::ThreadPool* pool);
  // The scene's bounds from every instance's.
  void regrow_scene_bounds(jobs::ThreadPool* pool);
  // chunk_bounds_[chunk] from its instances' bounds.
  void regrow_chunk(size_t chunk);
  // The scene's bounds from every chunk's.
  void grow_scene_bounds();

  ecs::Tick gathered_at_ = 0;               // the world's tick at the last gather
  uint64_t gathers_ = 0;                    // gather() calls so far
  uint64_t laid_out_at_ = 0;                // the call that last ordered every instance
  std::vector<uint32_t> place_of_;          // by entity index: its instance, or SparseSet::npos
  std::vector<uint64_t> written_at_;        // by instance: the call that last placed it (0: the layout's)
  std::vector<uint64_t> moved_at_;          // by instance: the call whose move made it moving (0: still)
  std::vector<uint32_t> moving_;            // the moving instances, in the order they first moved
  std::vector<uint32_t> changed_;           // the instances the current call re-places, by chunk
  std::vector<scene::Aabb> bounds_before_;  // their bounds before it
  std::vector<scene::Aabb> bounds_after_;   // and after
  // gather_changes' scratch: each changed chunk's re-placed instances, listed from the chunk's
  // first instance's place, and how many.
  struct Replacement {
    uint32_t instance;
    scene::Aabb before;
    scene::Aabb after;
  };
  std::vector<Replacement> replaced_by_chunk_;
  std::vector<uint32_t> chunk_changes_;
  static constexpr size_t changes_per_task = 256;  // the change lookups' pieces
  std::vector<uint64_t> uploaded_at_;              // by slot: the call whose instances it holds
  std::vector<Item> items_;
  std::vector<Item> sorted_items_;
  std::vector<uint32_t> slot_starts_;  // counting sort: per (draw class, mesh, caster or not)
  std::vector<GpuInstance> sorted_;
  std::vector<scene::Aabb> bounds_;
  // The bounds of each chunk of instances_per_chunk consecutive instances (the last may be
  // short), kept so that a change regrows only its chunk and the scene's bounds come from the
  // chunks': exact, whether the bounds grow or shrink. A chunk is also gather_changes' piece of
  // work: the stress scene's 2,200 moving crates, spread over 14,000 instances, make 14.
  static constexpr size_t instances_per_chunk = 1024;
  std::vector<scene::Aabb> chunk_bounds_;
  std::vector<uint8_t> chunk_changed_;    // gather_changes': per chunk, whether an instance changed
  std::vector<uint32_t> regrown_chunks_;  // the chunks with changed instances
  std::vector<uint64_t> keys_;
  scene::Aabb scene_bounds_;
  std::vector<VkDrawIndexedIndirectCommand> commands_;  // per (draw class, mesh), classes in order
  uint64_t triangles_ = 0;                              // over commands_
  std::array<CommandRange, draw_class_count> class_commands_{};
  std::vector<VkDrawIndexedIndirectCommand> caster_groups_;
  uint32_t first_cut_out_group_ = 0;
  std::vector<uint32_t> transparent_order_;  // order_transparent's
  std::vector<std::pair<float, uint32_t>> transparent_by_distance_;
};

}  // namespace sg
