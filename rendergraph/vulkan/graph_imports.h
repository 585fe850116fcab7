// SPDX-License-Identifier: MIT
#pragma once
// The resources a frame's graph imports, declared and bound in one call:
//
//   const rg::ImageHandle maps = imports.import_image(graph, "shadow maps", maps_image, sampled);
//   ... add passes, compile ...
//   executor.execute(cmd, slot, frame, graph, plan, imports.resources());
//   imports.remember(*plan);
//
// A persistent image starts each frame in the states the previous frame's plan left it in,
// carried by name (rg::ImportedStates). An image recreated since (a different vk::Image under the
// same name) starts undefined, which is right for new contents: nobody has to say it was.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/imported_states.h"
#include "rendergraph/core/render_graph.h"
#include "rendergraph/vulkan/plan_translation.h"

namespace sg::vk {

class Buffer;
class Image;

// The physical objects of one frame's imported resources, by graph resource index.
class ImportedResources {
 public:
  void bind(rg::ImageHandle handle, const Image& image);
  // An image without a view cache (a swapchain image): passes may use it only for transfers
  // and barriers.
  void bind(rg::ImageHandle handle, VkImage image, VkFormat format);
  void bind(rg::BufferHandle handle, const Buffer& buffer);
  void clear() { bindings_.clear(); }

  std::span<const std::pair<uint32_t, PhysicalResource>> bindings() const { return bindings_; }

 private:
  std::vector<std::pair<uint32_t, PhysicalResource>> bindings_;
};

class GraphImports {
 public:
  // Declares `image` in `graph` as `name`, bound to it for this frame. `final_state`: where
  // the frame leaves it (required when a pass writes it). `image` must live until the frame's
  // commands are recorded.
  rg::ImageHandle import_image(rg::RenderGraph& graph, std::string name, const Image& image,
                               std::optional<rg::ResourceState> final_state);
  // An image whose contents are not kept from frame to frame (an acquired swapchain image):
  // starts in `initial_state`, bound without views.
  rg::ImageHandle import_image(rg::RenderGraph& graph, std::string name, VkImage image, VkFormat format,
                               VkExtent2D extent, rg::ResourceState initial_state,
                               rg::ResourceState final_state);

  // Declares `buffer` in `graph` as `name`, bound to it for this frame. The frame finds it in
  // `state` and leaves it there (the barriers to the frame's first use cover the earlier frame's
  // last). `buffer` must live until the frame's commands are recorded.
  rg::BufferHandle import_buffer(rg::RenderGraph& graph, std::string name, const Buffer& buffer,
                                 rg::ResourceState state);

  // This frame's bindings, for GraphExecutor::execute.
  const ImportedResources& resources() const { return resources_; }
  // After executing `plan`, compiled from this frame's graph: keeps where it left each imported
  // image for the next frame, and clears this frame's bindings.
  void remember(const rg::CompiledPlan& plan);

 private:
  rg::ImportedStates states_;
  std::unordered_map<std::string, uint64_t> serials_;  // by name: the image the states belong to
  ImportedResources resources_;
};

}  // namespace sg::vk
