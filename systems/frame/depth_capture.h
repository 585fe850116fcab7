// SPDX-License-Identifier: MIT
#pragma once
// Keeps a copy of the camera's depth buffer after the frame, for tools that need the visible
// surface points on the CPU (tools/reference reconstructs world positions from it). The renderer's
// depth buffer is transient, so the copy goes into a persistent image imported as
// "captured depth", left in TRANSFER_SRC_OPTIMAL for read_depth_layer.
#include <optional>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/readback.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/graph_imports.h"

namespace sg {

class DepthCapture {
 public:
  // Declares the copy of `depth` (the renderer's D32 depth buffer) into the capture image,
  // (re)created at `depth`'s size when that changes.
  void add_to(vk::VulkanContext& context, rg::RenderGraph& graph, vk::GraphImports& imports,
              rg::ImageHandle depth);
  // The last captured frame's depths, rows top to bottom. Call after that frame's commands have
  // completed. Throws std::logic_error before any frame was captured.
  vk::DepthImage read(vk::VulkanContext& context) const;

 private:
  std::optional<vk::Image> image_;
};

}  // namespace sg
