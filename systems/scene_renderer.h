#pragma once
// Draws the built-in scene into an offscreen colour target: one instanced draw of the unit
// box, per-instance transforms and materials in a storage buffer. Both output paths (window,
// PNG) start from this target, so they show the same pixels.
#include <vulkan/vulkan.h>

#include "rendergraph/vulkan/resources.h"
#include "rendergraph/vulkan/unique_handle.h"
#include "systems/builtin_scene.h"
#include "systems/scene/mesh_library.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

class SceneRenderer {
 public:
  static constexpr VkFormat color_format = VK_FORMAT_R8G8B8A8_SRGB;
  static constexpr VkFormat depth_format = VK_FORMAT_D32_SFLOAT;

  SceneRenderer(vk::VulkanContext& context, const BuiltinScene& scene);

  // (Re)creates the colour and depth targets; call before the first frame and on resize.
  void resize(VkExtent2D extent);

  // Records one frame. Afterwards the colour target is in TRANSFER_SRC_OPTIMAL with its
  // writes available to copies and blits later on the queue. Earlier transfer reads of the
  // target (last frame's blit) are waited for.
  void record(VkCommandBuffer cmd, const scene::CameraPose& pose, const scene::Camera& lens) const;

  const vk::Image& color_target() const { return color_; }

 private:
  vk::VulkanContext& context_;
  DirectionalLight sun_;
  float ambient_;
  vk::Buffer vertices_;
  vk::Buffer indices_;
  vk::Buffer instances_;
  scene::MeshRange box_;
  uint32_t instance_count_ = 0;
  vk::UniqueDescriptorSetLayout set_layout_;
  vk::UniqueDescriptorPool descriptor_pool_;
  VkDescriptorSet descriptor_set_ = VK_NULL_HANDLE;
  vk::UniquePipelineLayout pipeline_layout_;
  vk::UniquePipeline pipeline_;
  vk::Image color_;
  vk::Image depth_;
};

}  // namespace sg
