// SPDX-License-Identifier: MIT
#include "rendergraph/core/usage.h"

namespace sg::rg {
namespace {

constexpr PipelineStage depth_tests =
    PipelineStage::early_fragment_tests | PipelineStage::late_fragment_tests;

// Shader-storage access through `stage`: a write is a read-modify-write.
constexpr ResourceState storage(PipelineStage stage, Direction direction, ResourceKind kind) {
  const Access access = direction == Direction::read
                            ? Access::shader_storage_read
                            : Access::shader_storage_read | Access::shader_storage_write;
  return {stage, access, kind == ResourceKind::image ? ImageLayout::general : ImageLayout::undefined};
}

}  // namespace

std::optional<ResourceState> usage_state(Usage usage, Direction direction, ResourceKind kind) {
  const bool image = kind == ResourceKind::image;
  const bool read = direction == Direction::read;
  switch (usage) {
    case Usage::depth_attachment:
      if (!image) return std::nullopt;
      // The sync2 generic layouts let a read-only depth attachment also be sampled in one pass.
      if (read)
        return ResourceState{depth_tests, Access::depth_stencil_attachment_read,
                             ImageLayout::read_only_optimal};
      return ResourceState{depth_tests,
                           Access::depth_stencil_attachment_read | Access::depth_stencil_attachment_write,
                           ImageLayout::attachment_optimal};
    case Usage::color_attachment:
      if (!image || read) return std::nullopt;
      return ResourceState{PipelineStage::color_attachment_output,
                           Access::color_attachment_read | Access::color_attachment_write,
                           ImageLayout::attachment_optimal};
    case Usage::sampled_fragment:
    case Usage::sampled_compute:
      if (!image || !read) return std::nullopt;
      return ResourceState{
          usage == Usage::sampled_fragment ? PipelineStage::fragment_shader : PipelineStage::compute_shader,
          Access::shader_sampled_read, ImageLayout::read_only_optimal};
    case Usage::storage_vertex: return storage(PipelineStage::vertex_shader, direction, kind);
    case Usage::storage_fragment: return storage(PipelineStage::fragment_shader, direction, kind);
    case Usage::storage_compute: return storage(PipelineStage::compute_shader, direction, kind);
    case Usage::transfer:
      if (read) {
        return ResourceState{PipelineStage::all_transfer, Access::transfer_read,
                             image ? ImageLayout::transfer_src_optimal : ImageLayout::undefined};
      }
      return ResourceState{PipelineStage::all_transfer, Access::transfer_write,
                           image ? ImageLayout::transfer_dst_optimal : ImageLayout::undefined};
    case Usage::indirect:
      if (image || !read) return std::nullopt;
      return ResourceState{PipelineStage::draw_indirect, Access::indirect_command_read,
                           ImageLayout::undefined};
    case Usage::vertex:
      if (image || !read) return std::nullopt;
      return ResourceState{PipelineStage::vertex_attribute_input, Access::vertex_attribute_read,
                           ImageLayout::undefined};
    case Usage::index:
      if (image || !read) return std::nullopt;
      return ResourceState{PipelineStage::index_input, Access::index_read, ImageLayout::undefined};
  }
  return std::nullopt;
}

ImageUsage image_usage(Usage usage, Direction direction) {
  switch (usage) {
    case Usage::depth_attachment: return ImageUsage::depth_stencil_attachment;
    case Usage::color_attachment: return ImageUsage::color_attachment;
    case Usage::sampled_fragment:
    case Usage::sampled_compute: return ImageUsage::sampled;
    case Usage::storage_vertex:
    case Usage::storage_fragment:
    case Usage::storage_compute: return ImageUsage::storage;
    case Usage::transfer:
      return direction == Direction::read ? ImageUsage::transfer_src : ImageUsage::transfer_dst;
    case Usage::indirect:
    case Usage::vertex:
    case Usage::index: return ImageUsage::none;
  }
  return ImageUsage::none;
}

BufferUsage buffer_usage(Usage usage, Direction direction) {
  switch (usage) {
    case Usage::storage_vertex:
    case Usage::storage_fragment:
    case Usage::storage_compute: return BufferUsage::storage;
    case Usage::transfer:
      return direction == Direction::read ? BufferUsage::transfer_src : BufferUsage::transfer_dst;
    case Usage::indirect: return BufferUsage::indirect;
    case Usage::vertex: return BufferUsage::vertex;
    case Usage::index: return BufferUsage::index;
    case Usage::depth_attachment:
    case Usage::color_attachment:
    case Usage::sampled_fragment:
    case Usage::sampled_compute: return BufferUsage::none;
  }
  return BufferUsage::none;
}

std::string_view usage_name(Usage usage) {
  switch (usage) {
    case Usage::depth_attachment: return "depth_attachment";
    case Usage::color_attachment: return "color_attachment";
    case Usage::sampled_fragment: return "sampled_fragment";
    case Usage::sampled_compute: return "sampled_compute";
    case Usage::storage_vertex: return "storage_vertex";
    case Usage::storage_fragment: return "storage_fragment";
    case Usage::storage_compute: return "storage_compute";
    case Usage::transfer: return "transfer";
    case Usage::indirect: return "indirect";
    case Usage::vertex: return "vertex";
    case Usage::index: return "index";
  }
  return "unknown";
}

std::string_view direction_name(Direction direction) {
  return direction == Direction::read ? "read" : "write";
}

}  // namespace sg::rg
