// SPDX-License-Identifier: MIT
#include "bench_gpu.h"

#include <algorithm>

#include "rendergraph/device/barriers.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/upload.h"
#include "rendergraph/device/vulkan_error.h"
#include "rendergraph/vulkan/pass_timer.h"

namespace sg::raster_bench {

GridMesh make_grid_mesh(vk::VulkanContext& context, uint32_t cells) {
  const uint32_t row = cells + 1;
  std::vector<float> positions;
  positions.reserve(size_t{row} * row * 2);
  for (uint32_t y = 0; y < row; ++y) {
    for (uint32_t x = 0; x < row; ++x) {
      positions.push_back(-1.0f + 2.0f * float(x) / float(cells));
      positions.push_back(-1.0f + 2.0f * float(y) / float(cells));
    }
  }
  std::vector<uint32_t> indices;
  indices.reserve(size_t{cells} * cells * 6);
  for (uint32_t y = 0; y < cells; ++y) {
    for (uint32_t x = 0; x < cells; ++x) {
      const uint32_t corner = y * row + x;
      for (const uint32_t i :
           {corner, corner + 1, corner + row, corner + 1, corner + row + 1, corner + row}) {
        indices.push_back(i);
      }
    }
  }
  GridMesh mesh;
  mesh.vertices = vk::Buffer(context, {positions.size() * sizeof(float),
                                       VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                       vk::MemoryUsage::gpu_only, "grid vertices"});
  mesh.indices = vk::Buffer(context, {indices.size() * sizeof(uint32_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                      vk::MemoryUsage::gpu_only, "grid indices"});
  mesh.index_count = static_cast<uint32_t>(indices.size());
  vk::UploadBatch upload(context);
  upload.copy(mesh.vertices, std::span<const float>(positions));
  upload.copy(mesh.indices, std::span<const uint32_t>(indices));
  upload.submit();
  return mesh;
}

vk::Image make_depth_target(vk::VulkanContext& context, uint32_t size, uint32_t layers) {
  return vk::Image(context, {{size, size},
                             VK_FORMAT_D32_SFLOAT,
                             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                             1,
                             layers,
                             layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
                             "raster-bench depth"});
}

void begin_depth_writes(VkCommandBuffer cmd, const vk::Image& target) {
  vk::ImageTransition t;
  t.image = target.handle();
  t.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  t.new_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  t.dst_stages = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  t.dst_access =
      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  vk::transition(cmd, t);
}

void begin_depth_pass(VkCommandBuffer cmd, VkImageView view, uint32_t size, VkAttachmentLoadOp load,
                      uint32_t layer_count) {
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = view;
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = load;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, {size, size}};
  rendering.layerCount = layer_count;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);
  const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
}

void bind_mesh(VkCommandBuffer cmd, const GridMesh& mesh) {
  const VkBuffer vertices = mesh.vertices.handle();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
  vkCmdBindIndexBuffer(cmd, mesh.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
}

vk::Buffer make_indirect_buffer(vk::VulkanContext& context,
                                std::span<const VkDrawIndexedIndirectCommand> draws) {
  vk::Buffer buffer(
      context, {draws.size_bytes(), VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                vk::MemoryUsage::gpu_only, "raster-bench draws"});
  vk::UploadBatch upload(context);
  upload.copy(buffer, draws);
  upload.submit();
  return buffer;
}

void draw_indexed_indirect(VkCommandBuffer cmd, const vk::VulkanContext& context, const vk::Buffer& draws,
                           uint32_t count) {
  const uint32_t most = context.properties().limits.maxDrawIndirectCount;
  for (uint32_t first = 0; first < count; first += most) {
    vkCmdDrawIndexedIndirect(cmd, draws.handle(), first * sizeof(VkDrawIndexedIndirectCommand),
                             std::min(most, count - first), sizeof(VkDrawIndexedIndirectCommand));
  }
}

std::vector<double> time_repetitions(vk::VulkanContext& context, uint32_t repetitions,
                                     const std::function<void(VkCommandBuffer)>& setup,
                                     const std::function<void(VkCommandBuffer)>& work) {
  vk::PassTimer timer(context, 1);
  const uint32_t copies = repetitions + 1;
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    setup(cmd);
    timer.begin_frame(cmd, 0, copies);
    for (uint32_t copy = 0; copy < copies; ++copy) {
      vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                         VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
      timer.begin_pass(cmd, 0, copy);
      work(cmd);
      timer.end_pass(cmd, 0, copy);
    }
  });
  std::vector<double> ms;
  if (!timer.collect(0, ms)) {
    throw vk::VulkanError("the device's queue has no timestamps, so nothing can be measured");
  }
  ms.erase(ms.begin());
  return ms;
}

}  // namespace sg::raster_bench
