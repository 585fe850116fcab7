// SPDX-License-Identifier: MIT
#pragma once

// The synchronization vocabulary of the compiled plan: pipeline stages, memory accesses and image
// layouts, mirroring Vulkan synchronization2 without including Vulkan.
//
// Mapping: every enumerator carries the numeric value of the Vulkan enumerator named beside it
// (PipelineStage -> VkPipelineStageFlagBits2, Access -> VkAccessFlagBits2, ImageLayout ->
// VkImageLayout), so the executor converts with a static_cast guarded by static_asserts on each
// value (or a lookup table); nothing is renumbered.

#include <cstdint>
#include <string>

#include "rendergraph/core/flags.h"

namespace sg::rg {

enum class PipelineStage : std::uint64_t {
  none = 0,                               // VK_PIPELINE_STAGE_2_NONE
  top_of_pipe = 0x1,                      // VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT
  draw_indirect = 0x2,                    // VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT
  vertex_shader = 0x8,                    // VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT
  fragment_shader = 0x80,                 // VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT
  early_fragment_tests = 0x100,           // VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT
  late_fragment_tests = 0x200,            // VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT
  color_attachment_output = 0x400,        // VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT
  compute_shader = 0x800,                 // VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT
  all_transfer = 0x1000,                  // VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT
  bottom_of_pipe = 0x2000,                // VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT
  host = 0x4000,                          // VK_PIPELINE_STAGE_2_HOST_BIT
  all_graphics = 0x8000,                  // VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT
  all_commands = 0x10000,                 // VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT
  index_input = 0x1000000000,             // VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT
  vertex_attribute_input = 0x2000000000,  // VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT
};
template <>
inline constexpr bool is_flag_enum<PipelineStage> = true;

enum class Access : std::uint64_t {
  none = 0,                                // VK_ACCESS_2_NONE
  indirect_command_read = 0x1,             // VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT
  index_read = 0x2,                        // VK_ACCESS_2_INDEX_READ_BIT
  vertex_attribute_read = 0x4,             // VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT
  uniform_read = 0x8,                      // VK_ACCESS_2_UNIFORM_READ_BIT
  color_attachment_read = 0x80,            // VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT
  color_attachment_write = 0x100,          // VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT
  depth_stencil_attachment_read = 0x200,   // VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT
  depth_stencil_attachment_write = 0x400,  // VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT
  transfer_read = 0x800,                   // VK_ACCESS_2_TRANSFER_READ_BIT
  transfer_write = 0x1000,                 // VK_ACCESS_2_TRANSFER_WRITE_BIT
  host_read = 0x2000,                      // VK_ACCESS_2_HOST_READ_BIT
  host_write = 0x4000,                     // VK_ACCESS_2_HOST_WRITE_BIT
  memory_read = 0x8000,                    // VK_ACCESS_2_MEMORY_READ_BIT
  memory_write = 0x10000,                  // VK_ACCESS_2_MEMORY_WRITE_BIT
  shader_sampled_read = 0x100000000,       // VK_ACCESS_2_SHADER_SAMPLED_READ_BIT
  shader_storage_read = 0x200000000,       // VK_ACCESS_2_SHADER_STORAGE_READ_BIT
  shader_storage_write = 0x400000000,      // VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT
};
template <>
inline constexpr bool is_flag_enum<Access> = true;

// The accesses that modify memory; everything else in Access only reads.
inline constexpr Access write_accesses =
    Access::color_attachment_write | Access::depth_stencil_attachment_write | Access::transfer_write |
    Access::host_write | Access::memory_write | Access::shader_storage_write;

constexpr bool is_write(Access access) { return any(access & write_accesses); }

enum class ImageLayout : std::uint32_t {
  undefined = 0,                         // VK_IMAGE_LAYOUT_UNDEFINED
  general = 1,                           // VK_IMAGE_LAYOUT_GENERAL
  color_attachment_optimal = 2,          // VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL
  depth_stencil_attachment_optimal = 3,  // VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL
  depth_stencil_read_only_optimal = 4,   // VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
  shader_read_only_optimal = 5,          // VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
  transfer_src_optimal = 6,              // VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL
  transfer_dst_optimal = 7,              // VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL
  read_only_optimal = 1000314000,        // VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL
  attachment_optimal = 1000314001,       // VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL
  present_src = 1000001002,              // VK_IMAGE_LAYOUT_PRESENT_SRC_KHR
};

// How a resource (or one subresource range of it) is being used: the stages and accesses that
// touch it and, for images, the layout they need. Buffers always use ImageLayout::undefined.
struct ResourceState {
  PipelineStage stages = PipelineStage::none;
  Access access = Access::none;
  ImageLayout layout = ImageLayout::undefined;

  friend bool operator==(const ResourceState&, const ResourceState&) = default;
};

// "A|B" with the Vulkan names minus their prefix and _BIT suffix, "NONE" for an empty mask; for
// dumps and error messages.
std::string to_string(PipelineStage stages);
std::string to_string(Access access);
std::string to_string(ImageLayout layout);

}  // namespace sg::rg
