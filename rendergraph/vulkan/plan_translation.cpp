// SPDX-License-Identifier: MIT
#include "rendergraph/vulkan/plan_translation.h"

#include <cstdint>
#include <stdexcept>
#include <string>

#include "rendergraph/device/resources.h"

namespace sg::vk {
namespace {

using rg::Access;
using rg::Format;
using rg::ImageLayout;
using rg::PipelineStage;

template <class E>
constexpr auto value(E e) {
  return static_cast<std::underlying_type_t<E>>(e);
}

static_assert(value(PipelineStage::none) == VK_PIPELINE_STAGE_2_NONE);
static_assert(value(PipelineStage::top_of_pipe) == VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT);
static_assert(value(PipelineStage::draw_indirect) == VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT);
static_assert(value(PipelineStage::vertex_shader) == VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
static_assert(value(PipelineStage::fragment_shader) == VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
static_assert(value(PipelineStage::early_fragment_tests) == VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT);
static_assert(value(PipelineStage::late_fragment_tests) == VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT);
static_assert(value(PipelineStage::color_attachment_output) ==
              VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
static_assert(value(PipelineStage::compute_shader) == VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
static_assert(value(PipelineStage::all_transfer) == VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
static_assert(value(PipelineStage::bottom_of_pipe) == VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT);
static_assert(value(PipelineStage::host) == VK_PIPELINE_STAGE_2_HOST_BIT);
static_assert(value(PipelineStage::all_graphics) == VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT);
static_assert(value(PipelineStage::all_commands) == VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT);
static_assert(value(PipelineStage::index_input) == VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT);
static_assert(value(PipelineStage::vertex_attribute_input) == VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT);

static_assert(value(Access::none) == VK_ACCESS_2_NONE);
static_assert(value(Access::indirect_command_read) == VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
static_assert(value(Access::index_read) == VK_ACCESS_2_INDEX_READ_BIT);
static_assert(value(Access::vertex_attribute_read) == VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
static_assert(value(Access::uniform_read) == VK_ACCESS_2_UNIFORM_READ_BIT);
static_assert(value(Access::color_attachment_read) == VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT);
static_assert(value(Access::color_attachment_write) == VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
static_assert(value(Access::depth_stencil_attachment_read) == VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
static_assert(value(Access::depth_stencil_attachment_write) ==
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
static_assert(value(Access::transfer_read) == VK_ACCESS_2_TRANSFER_READ_BIT);
static_assert(value(Access::transfer_write) == VK_ACCESS_2_TRANSFER_WRITE_BIT);
static_assert(value(Access::host_read) == VK_ACCESS_2_HOST_READ_BIT);
static_assert(value(Access::host_write) == VK_ACCESS_2_HOST_WRITE_BIT);
static_assert(value(Access::memory_read) == VK_ACCESS_2_MEMORY_READ_BIT);
static_assert(value(Access::memory_write) == VK_ACCESS_2_MEMORY_WRITE_BIT);
static_assert(value(Access::shader_sampled_read) == VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
static_assert(value(Access::shader_storage_read) == VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
static_assert(value(Access::shader_storage_write) == VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);

static_assert(value(ImageLayout::undefined) == VK_IMAGE_LAYOUT_UNDEFINED);
static_assert(value(ImageLayout::general) == VK_IMAGE_LAYOUT_GENERAL);
static_assert(value(ImageLayout::color_attachment_optimal) == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
static_assert(value(ImageLayout::depth_stencil_attachment_optimal) ==
              VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
static_assert(value(ImageLayout::depth_stencil_read_only_optimal) ==
              VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
static_assert(value(ImageLayout::shader_read_only_optimal) == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
static_assert(value(ImageLayout::transfer_src_optimal) == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
static_assert(value(ImageLayout::transfer_dst_optimal) == VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
static_assert(value(ImageLayout::read_only_optimal) == VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
static_assert(value(ImageLayout::attachment_optimal) == VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL);
static_assert(value(ImageLayout::present_src) == VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);

static_assert(value(Format::undefined) == VK_FORMAT_UNDEFINED);
static_assert(value(Format::rgba8_unorm) == VK_FORMAT_R8G8B8A8_UNORM);
static_assert(value(Format::rgba8_srgb) == VK_FORMAT_R8G8B8A8_SRGB);
static_assert(value(Format::bgra8_unorm) == VK_FORMAT_B8G8R8A8_UNORM);
static_assert(value(Format::bgra8_srgb) == VK_FORMAT_B8G8R8A8_SRGB);
static_assert(value(Format::rg16_sfloat) == VK_FORMAT_R16G16_SFLOAT);
static_assert(value(Format::rgba16_sfloat) == VK_FORMAT_R16G16B16A16_SFLOAT);
static_assert(value(Format::rgba32_sfloat) == VK_FORMAT_R32G32B32A32_SFLOAT);
static_assert(value(Format::r32_sfloat) == VK_FORMAT_R32_SFLOAT);
static_assert(value(Format::d16_unorm) == VK_FORMAT_D16_UNORM);
static_assert(value(Format::d32_sfloat) == VK_FORMAT_D32_SFLOAT);

static_assert(value(rg::ImageUsage::transfer_src) == VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
static_assert(value(rg::ImageUsage::transfer_dst) == VK_IMAGE_USAGE_TRANSFER_DST_BIT);
static_assert(value(rg::ImageUsage::sampled) == VK_IMAGE_USAGE_SAMPLED_BIT);
static_assert(value(rg::ImageUsage::storage) == VK_IMAGE_USAGE_STORAGE_BIT);
static_assert(value(rg::ImageUsage::color_attachment) == VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
static_assert(value(rg::ImageUsage::depth_stencil_attachment) == VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);

static_assert(value(rg::BufferUsage::transfer_src) == VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
static_assert(value(rg::BufferUsage::transfer_dst) == VK_BUFFER_USAGE_TRANSFER_DST_BIT);
static_assert(value(rg::BufferUsage::storage) == VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
static_assert(value(rg::BufferUsage::index) == VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
static_assert(value(rg::BufferUsage::vertex) == VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
static_assert(value(rg::BufferUsage::indirect) == VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);

}  // namespace

VkPipelineStageFlags2 to_vk(rg::PipelineStage stages) { return value(stages); }
VkAccessFlags2 to_vk(rg::Access access) { return value(access); }
VkImageLayout to_vk(rg::ImageLayout layout) { return static_cast<VkImageLayout>(value(layout)); }
VkFormat to_vk(rg::Format format) { return static_cast<VkFormat>(value(format)); }

Format from_vk(VkFormat format) {
  const auto candidate = static_cast<Format>(format);
  switch (candidate) {  // every enumerator, so that a new one must be added here
    case Format::undefined:
    case Format::rgba8_unorm:
    case Format::rgba8_srgb:
    case Format::bgra8_unorm:
    case Format::bgra8_srgb:
    case Format::rg16_sfloat:
    case Format::rgba16_sfloat:
    case Format::rgba32_sfloat:
    case Format::r32_sfloat:
    case Format::d16_unorm:
    case Format::d32_sfloat: return candidate;
  }
  throw std::invalid_argument("the render graph has no format for VkFormat " + std::to_string(format));
}

rg::ImageDesc graph_desc(const Image& image) {
  return {image.extent().width, image.extent().height, from_vk(image.format()),
          image.array_layers(), image.mip_levels(),    image.cube_compatible()};
}
VkImageUsageFlags to_vk(rg::ImageUsage usage) { return value(usage); }
VkBufferUsageFlags to_vk(rg::BufferUsage usage) { return value(usage); }

VkImageSubresourceRange to_vk(const rg::SubresourceRange& range, VkImageAspectFlags aspect) {
  return {aspect, range.base_mip, range.mip_count, range.base_layer, range.layer_count};
}

void record_barriers(VkCommandBuffer cmd, const rg::BarrierBatch& batch,
                     std::span<const PhysicalResource> resources, BarrierScratch& scratch) {
  if (batch.empty()) return;
  scratch.images.clear();
  scratch.buffers.clear();
  for (const rg::ImageBarrier& barrier : batch.images) {
    const PhysicalResource& resource = resources[barrier.resource];
    const rg::Dependency& d = barrier.dependency;
    VkImageMemoryBarrier2 vk_barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    vk_barrier.srcStageMask = to_vk(d.src_stages);
    vk_barrier.srcAccessMask = to_vk(d.src_access);
    vk_barrier.dstStageMask = to_vk(d.dst_stages);
    vk_barrier.dstAccessMask = to_vk(d.dst_access);
    vk_barrier.oldLayout = to_vk(d.old_layout);
    vk_barrier.newLayout = to_vk(d.new_layout);
    vk_barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    vk_barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    vk_barrier.image = resource.image;
    vk_barrier.subresourceRange = to_vk(barrier.range, resource.aspect);
    scratch.images.push_back(vk_barrier);
  }
  for (const rg::BufferBarrier& barrier : batch.buffers) {
    const rg::Dependency& d = barrier.dependency;
    VkBufferMemoryBarrier2 vk_barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    vk_barrier.srcStageMask = to_vk(d.src_stages);
    vk_barrier.srcAccessMask = to_vk(d.src_access);
    vk_barrier.dstStageMask = to_vk(d.dst_stages);
    vk_barrier.dstAccessMask = to_vk(d.dst_access);
    vk_barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    vk_barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    vk_barrier.buffer = resources[barrier.resource].buffer;
    vk_barrier.offset = 0;
    vk_barrier.size = VK_WHOLE_SIZE;
    scratch.buffers.push_back(vk_barrier);
  }
  VkDependencyInfo info{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  info.imageMemoryBarrierCount = static_cast<uint32_t>(scratch.images.size());
  info.pImageMemoryBarriers = scratch.images.data();
  info.bufferMemoryBarrierCount = static_cast<uint32_t>(scratch.buffers.size());
  info.pBufferMemoryBarriers = scratch.buffers.data();
  vkCmdPipelineBarrier2(cmd, &info);
}

}  // namespace sg::vk
