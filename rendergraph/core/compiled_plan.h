// SPDX-License-Identifier: MIT
#pragma once

// The result of compile(): plain data an executor walks front to back. Indices into `passes` are
// execution positions; `declared_index` links back to RenderGraph::passes() (for the execute
// callback, which is never copied into the plan so that a cached plan can serve a rebuilt graph).
// Resource indices are the graph's resource indices.
//
// Executing a plan:
//   create/alias the transients per `resources[i].placement` inside `heaps`
//   for each pass: record `barriers` (one vkCmdPipelineBarrier2), then the pass's execute function
//   record `final_barriers`; hand `exported_states` to next frame's imports

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/core/resource_types.h"
#include "rendergraph/core/sync_types.h"

namespace sg::rg {

// One synchronization2 dependency. old_layout == new_layout means no layout transition; buffers
// always carry ImageLayout::undefined in both.
struct Dependency {
  PipelineStage src_stages = PipelineStage::none;
  Access src_access = Access::none;
  PipelineStage dst_stages = PipelineStage::none;
  Access dst_access = Access::none;
  ImageLayout old_layout = ImageLayout::undefined;
  ImageLayout new_layout = ImageLayout::undefined;

  friend bool operator==(const Dependency&, const Dependency&) = default;
};

// -> VkImageMemoryBarrier2 (aspect from the image's format).
struct ImageBarrier {
  std::uint32_t resource = invalid_index;
  SubresourceRange range;
  Dependency dependency;
};

// -> VkBufferMemoryBarrier2 over the whole buffer.
struct BufferBarrier {
  std::uint32_t resource = invalid_index;
  Dependency dependency;
};

// Everything one pass boundary needs: recorded as a single vkCmdPipelineBarrier2.
struct BarrierBatch {
  std::vector<ImageBarrier> images;
  std::vector<BufferBarrier> buffers;

  bool empty() const { return images.empty() && buffers.empty(); }
};

struct CompiledPass {
  std::uint32_t declared_index = invalid_index;
  std::string name;
  QueueType queue = QueueType::graphics;
  bool side_effects = false;
  std::vector<ResourceAccess> accesses;   // as declared; attachments for dynamic rendering
  std::vector<std::uint32_t> depends_on;  // earlier execution positions, ascending
  BarrierBatch barriers;                  // before the pass
};

struct CulledPass {
  std::uint32_t declared_index = invalid_index;
  std::string name;
};

// Execution positions of the first and last pass that touch a resource.
struct Lifetime {
  std::uint32_t first = 0;
  std::uint32_t last = 0;

  friend bool operator==(const Lifetime&, const Lifetime&) = default;
};

// Where a transient lives. `previous_occupants` are the transients whose memory it reuses (their
// lifetimes ended before this one starts); its first barrier waits for their last use.
struct MemoryPlacement {
  std::uint32_t heap = invalid_index;
  std::uint64_t offset = 0;
  std::uint64_t size = 0;
  std::vector<std::uint32_t> previous_occupants;
};

// One device allocation that transients are placed in. Images and buffers get separate heaps
// (memory types and bufferImageGranularity differ).
struct MemoryHeap {
  ResourceKind kind = ResourceKind::image;
  std::uint64_t size = 0;
  std::uint64_t alignment = 1;
};

struct CompiledResource {
  std::string name;
  ResourceKind kind = ResourceKind::image;
  bool imported = false;
  ImageDesc image;
  BufferDesc buffer;
  ImageUsage image_usage = ImageUsage::none;  // union over executed passes' declarations
  BufferUsage buffer_usage = BufferUsage::none;
  std::uint32_t version_count = 1;
  std::optional<Lifetime> lifetime;          // none when no executed pass touches it
  std::optional<MemoryPlacement> placement;  // transients with a lifetime
};

// The state an imported resource is left in, per range: the next frame's import_image() input.
struct ExportedState {
  std::uint32_t resource = invalid_index;
  std::vector<RangeState> states;
};

struct MemoryStats {
  std::uint64_t unaliased_bytes = 0;  // every transient in its own allocation
  std::uint64_t aliased_bytes = 0;    // the heaps' total
  std::uint64_t saved_bytes() const { return unaliased_bytes - aliased_bytes; }
};

struct CompiledPlan {
  std::vector<CompiledPass> passes;         // execution order
  std::vector<CulledPass> culled;           // declaration order
  std::vector<CompiledResource> resources;  // graph resource order
  std::vector<MemoryHeap> heaps;
  MemoryStats memory;
  BarrierBatch final_barriers;  // imported resources to their final states
  std::vector<ExportedState> exported_states;
};

}  // namespace sg::rg
