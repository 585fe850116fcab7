#include "systems/shadow_caster_lists.h"

#include <span>

#include "systems/gpu_scene.h"

namespace sg {
namespace {

bool sphere_meets_box(const glm::vec4& sphere, const scene::Aabb& box) {
  const glm::vec3 centre(sphere);
  const glm::vec3 nearest = glm::clamp(centre, box.min, box.max);
  const glm::vec3 d = nearest - centre;
  return glm::dot(d, d) <= sphere.w * sphere.w;
}

}  // namespace

ShadowCasterLists::ShadowCasterLists(vk::VulkanContext& context, uint32_t frames_in_flight)
    : ids_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, frames_in_flight, "shadow caster ids"),
      commands_(context, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, frames_in_flight, "shadow caster draws") {}

void ShadowCasterLists::clear() {
  ids_scratch_.clear();
  commands_scratch_.clear();
}

CasterView ShadowCasterLists::add_view(const GpuScene& scene, const glm::vec4& reach, uint32_t copies) {
  CasterView view{static_cast<uint32_t>(commands_scratch_.size()), 0};
  const std::span<const scene::Aabb> bounds = scene.instance_bounds();
  for (const VkDrawIndexedIndirectCommand& group : scene.caster_groups()) {
    const auto first = static_cast<uint32_t>(ids_scratch_.size());
    for (uint32_t i = group.firstInstance; i < group.firstInstance + group.instanceCount; ++i) {
      if (reach.w < 0.0f || sphere_meets_box(reach, bounds[i])) ids_scratch_.push_back(i);
    }
    const auto kept = static_cast<uint32_t>(ids_scratch_.size()) - first;
    if (kept == 0) continue;
    VkDrawIndexedIndirectCommand command = group;
    command.instanceCount = kept * copies;
    command.firstInstance = first;
    commands_scratch_.push_back(command);
    ++view.command_count;
  }
  return view;
}

void ShadowCasterLists::upload(uint32_t slot) {
  ids_.write(slot, std::span<const uint32_t>(ids_scratch_));
  commands_.write(slot, std::span<const VkDrawIndexedIndirectCommand>(commands_scratch_));
}

void ShadowCasterLists::draw(VkCommandBuffer cmd, uint32_t slot, CasterView view) const {
  if (view.command_count == 0) return;
  vkCmdDrawIndexedIndirect(cmd, commands_.buffer(slot).handle(),
                           VkDeviceSize{view.first_command} * sizeof(VkDrawIndexedIndirectCommand),
                           view.command_count, sizeof(VkDrawIndexedIndirectCommand));
}

}  // namespace sg
