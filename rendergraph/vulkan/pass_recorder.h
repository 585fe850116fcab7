// SPDX-License-Identifier: MIT
#pragma once
// What a pass's execute function records with. An execute function that takes it is handed
// it directly (rg::RenderGraph::add_pass unwraps the rg::PassContext):
//
//   [=](const vk::PassRecorder& rec) {
//     rec.set_full_viewport();
//     vkCmdDraw(rec.cmd(), 3, 1, 0, 0);
//   }
//
// For a raster pass (one that declared color or depth attachments) rendering has already begun
// with those attachments, in declaration order, and ends after the function returns; the pass
// only binds and draws.
#include <optional>
#include <span>

#include <vulkan/vulkan.h>

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/core/resource_types.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/vulkan/plan_translation.h"

namespace sg::vk {

class VulkanContext;

class PassRecorder {
 public:
  PassRecorder(VulkanContext& context, VkCommandBuffer cmd, std::span<const PhysicalResource> resources,
               std::span<const rg::CompiledResource> descriptions, VkDescriptorPool frame_descriptors)
      : context_(context),
        cmd_(cmd),
        resources_(resources),
        descriptions_(descriptions),
        frame_descriptors_(frame_descriptors) {}

  VulkanContext& context() const { return context_; }
  VkCommandBuffer cmd() const { return cmd_; }

  // The Vulkan objects behind any version of a resource.
  VkImage image(rg::ImageHandle image) const { return resources_[image.index].image; }
  VkBuffer buffer(rg::BufferHandle buffer) const { return resources_[buffer.index].buffer; }

  // A view of `range` of the image, created once and cached. Without `type`: 2D for one layer,
  // cube or cube array for whole cubes of a cube-compatible image, 2D array otherwise. Throws
  // std::logic_error for an imported image bound without views (a swapchain image).
  VkImageView view(rg::ImageHandle image, rg::SubresourceRange range = rg::SubresourceRange::all(),
                   std::optional<VkImageViewType> type = std::nullopt) const;

  // The attachments' size in a raster pass; {0, 0} in other passes.
  VkExtent2D render_extent() const { return render_extent_; }
  // Viewport and scissor over the whole render area, depth [0, 1].
  void set_full_viewport() const;
  // Viewport and scissor over `area`, depth [0, 1].
  void set_viewport(const VkRect2D& area) const;

  // A descriptor set that lives for this frame only: the executor resets the frame's pool when
  // the frame slot comes around again. For the handful of sets a pass binds per frame (its
  // inputs are transients whose views change with the slot).
  VkDescriptorSet allocate_set(const PipelineLayout& layout) const;

 private:
  friend class GraphExecutor;

  VulkanContext& context_;
  VkCommandBuffer cmd_;
  std::span<const PhysicalResource> resources_;
  std::span<const rg::CompiledResource> descriptions_;  // the plan's, by resource index
  VkDescriptorPool frame_descriptors_;
  VkExtent2D render_extent_{0, 0};
};

}  // namespace sg::vk
