// SPDX-License-Identifier: MIT
#pragma once
// What every raster-bench case needs on the device layer: grid meshes, depth targets, a
// depth-only pass and repetitions timed with GPU timestamps.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/fwd.h"
#include "rendergraph/device/resources.h"

namespace sg::raster_bench {

// A square of cells x cells quads over NDC -1..1, two triangles each, with shared vertices
// (vec2 positions) so that vertex work per triangle is what an indexed caster mesh costs.
struct GridMesh {
  vk::Buffer vertices;
  vk::Buffer indices;  // uint32, row by row, 6 per cell
  uint32_t index_count = 0;
  uint32_t triangle_count() const { return index_count / 3; }
};
GridMesh make_grid_mesh(vk::VulkanContext& context, uint32_t cells);

// A D32_SFLOAT image used only as a depth attachment; layers > 1 makes a 2D-array view.
vk::Image make_depth_target(vk::VulkanContext& context, uint32_t size, uint32_t layers = 1);

// Records UNDEFINED -> DEPTH_ATTACHMENT_OPTIMAL for every layer (the contents are discarded).
void begin_depth_writes(VkCommandBuffer cmd, const vk::Image& target);

// Begins dynamic rendering into `view` (a depth attachment of `layer_count` layers, no color),
// loading or clearing to 1, and sets the viewport and scissor to the whole size x size target.
void begin_depth_pass(VkCommandBuffer cmd, VkImageView view, uint32_t size, VkAttachmentLoadOp load,
                      uint32_t layer_count = 1);

void bind_mesh(VkCommandBuffer cmd, const GridMesh& mesh);

// A device-local buffer of indirect draw commands.
vk::Buffer make_indirect_buffer(vk::VulkanContext& context,
                                std::span<const VkDrawIndexedIndirectCommand> draws);
// Records the buffer's first `count` commands as multi-draw indirect calls: one call, or as few
// as the device's maxDrawIndirectCount allows.
void draw_indexed_indirect(VkCommandBuffer cmd, const vk::VulkanContext& context, const vk::Buffer& draws,
                           uint32_t count);

// Records `setup`, then repetitions + 1 copies of `work`, each between two timestamps and after a
// full barrier so that no copy overlaps another; submits, waits, and returns each copy's GPU
// milliseconds but the first one's (a warm-up, which pays first-use costs).
std::vector<double> time_repetitions(vk::VulkanContext& context, uint32_t repetitions,
                                     const std::function<void(VkCommandBuffer)>& setup,
                                     const std::function<void(VkCommandBuffer)>& work);

}  // namespace sg::raster_bench
