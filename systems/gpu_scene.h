#pragma once
// The scene's drawables on the GPU: the mesh library in one vertex and one index buffer
// (uploaded once), and per frame the instances of every drawable entity plus one indirect draw
// per mesh, so that a view of the whole scene is a single vkCmdDrawIndexedIndirect call
// whatever the number of instances.
//
// Instances are grouped by mesh, shadow casters first within each mesh, so that the caster
// draws are the same commands with smaller instance counts (shadow passes draw casters only).
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "ecs/world.h"
#include "rendergraph/vulkan/frame_buffers.h"
#include "rendergraph/vulkan/resources.h"
#include "systems/scene/mesh_library.h"
#include "systems/scene_gpu_types.h"

namespace sg {

enum class DrawSet {
  all,
  casters,
  // The caster draws with six times the instances, for single-pass cube rendering
  // (shaders/shadow_cube_layered.vert picks instance k / 6 and face k % 6).
  casters_per_cube_face,
};

class GpuScene {
 public:
  GpuScene(vk::VulkanContext& context, const scene::MeshLibrary& meshes, uint32_t frames_in_flight);

  // Gathers every entity with WorldTransform and MeshInstance (Material when present, the
  // default grey otherwise) into the slot's instance buffer and draw lists. Transforms must be
  // up to date (ecs::update_world_transforms).
  void update(ecs::World& world, uint32_t slot);

  // Binds the vertex and index buffers and draws `set` with the pipeline already bound. The
  // pipeline's vertex input is scene::Vertex at binding 0; instance data comes from the
  // instance buffer, indexed by gl_InstanceIndex.
  void draw(VkCommandBuffer cmd, uint32_t slot, DrawSet set) const;

  const vk::Buffer& instances(uint32_t slot) const { return instances_.buffer(slot); }
  uint32_t instance_count() const { return instance_count_; }
  uint32_t caster_count() const { return caster_count_; }

 private:
  vk::Buffer vertices_;
  vk::Buffer indices_;
  std::vector<scene::MeshRange> meshes_;
  vk::FrameBuffers instances_;
  vk::FrameBuffers draws_;  // all draws, then caster draws, then caster draws x 6
  uint32_t draw_count_ = 0;
  uint32_t caster_draw_count_ = 0;
  uint32_t instance_count_ = 0;
  uint32_t caster_count_ = 0;

  // Per-frame scratch, reused so that gathering allocates nothing once it has grown.
  struct Item {
    uint32_t mesh;
    bool caster;
    uint32_t index;  // into gathered_
  };
  std::vector<Item> items_;
  std::vector<GpuInstance> gathered_;
  std::vector<GpuInstance> sorted_;
  std::vector<VkDrawIndexedIndirectCommand> commands_;
  std::vector<VkDrawIndexedIndirectCommand> caster_commands_;
};

}  // namespace sg
