#pragma once
// Which casters each shadow view draws. A light can only shadow what lies within its reach, so
// every view keeps the casters whose world bounds meet the light's sphere of range (spot and
// point lights; directional and cylinder views keep every caster). The kept instances' indices
// go into one id buffer per frame slot, and each view gets one indirect command per mesh
// whose firstInstance points into that buffer: the shadow shaders read
// instances[view_instances[gl_InstanceIndex]] (shaders/shadow_map.vert).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "rendergraph/vulkan/frame_buffers.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

class GpuScene;

struct CasterView {
  uint32_t first_command = 0;
  uint32_t command_count = 0;
};

class ShadowCasterLists {
 public:
  ShadowCasterLists(vk::VulkanContext& context, uint32_t frames_in_flight);

  // Starts a frame's lists.
  void clear();
  // The casters of `scene` whose bounds meet the sphere `reach` (xyz centre, w radius; a
  // negative radius keeps every caster), each drawn `copies` times (6 for layered cubes).
  CasterView add_view(const GpuScene& scene, const glm::vec4& reach, uint32_t copies);
  // Writes the frame's ids and commands to the slot's buffers (after the last add_view).
  void upload(uint32_t slot);

  const vk::Buffer& ids(uint32_t slot) const { return ids_.buffer(slot); }
  // Draws `view` with the pipeline bound and the scene's geometry bound.
  void draw(VkCommandBuffer cmd, uint32_t slot, CasterView view) const;

  // Instances kept over all views of the frame, before copies: what culling left to draw.
  uint64_t kept_instances() const { return ids_scratch_.size(); }

 private:
  vk::FrameBuffers ids_;
  vk::FrameBuffers commands_;
  std::vector<uint32_t> ids_scratch_;
  std::vector<VkDrawIndexedIndirectCommand> commands_scratch_;
};

}  // namespace sg
