// SPDX-License-Identifier: MIT
#pragma once
// Runs a compiled render graph on Vulkan.
//
// Per frame: the transients of the plan are looked up (created on first use of a plan, one set
// per frame in flight, memory aliased as the device's requirements allow); then for each pass in
// execution order the executor records its barrier batch as one vkCmdPipelineBarrier2, opens a
// debug label, writes a timestamp, begins dynamic rendering when the pass declared attachments,
// calls the pass's execute function with a PassRecorder, and closes all of that again; at the
// end it records the plan's final barriers.
//
// Imported resources are bound by the caller for each frame (ImportedResources); their states at
// the end of the frame are the plan's exported_states, which the caller feeds to the next frame's
// imports. GraphImports does both: it declares, binds and carries states in one call.
//
// Every pass runs on the graphics queue whatever its QueueType: the engine uses one queue.
//
// Attachments: load op CLEAR when the write declared a ClearValue, LOAD otherwise; store op STORE
// for writes, NONE for read-only depth. Clear values and execute functions are read from the
// graph, never from the plan, so a cached plan serves every frame with the same shape.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/compiled_plan.h"
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/unique_handle.h"
#include "rendergraph/vulkan/graph_imports.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/pass_timer.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "rendergraph/vulkan/transient_resources.h"

namespace sg::vk {

class VulkanContext;

// GPU milliseconds of the passes of one completed frame, by execution position of `plan`.
struct FrameTimings {
  uint64_t frame_number = 0;
  std::shared_ptr<const rg::CompiledPlan> plan;
  std::vector<double> pass_ms;
};

class GraphExecutor {
 public:
  GraphExecutor(VulkanContext& context, uint32_t frames_in_flight);
  ~GraphExecutor();
  GraphExecutor(const GraphExecutor&) = delete;
  GraphExecutor& operator=(const GraphExecutor&) = delete;

  // Records the frame into `cmd`. `slot` is the frame-in-flight index (FrameSlot::slot): the
  // GPU must have finished the slot's previous frame (FrameRing::begin_frame waits for it).
  // `plan` must have been compiled from a graph shaped like `graph`. Throws std::logic_error
  // when an imported resource an executed pass uses has no binding.
  void execute(VkCommandBuffer cmd, uint32_t slot, uint64_t frame_number, const rg::RenderGraph& graph,
               const std::shared_ptr<const rg::CompiledPlan>& plan, const ImportedResources& imports);

  // Reads the timestamps of the slot's previous frame, if not read yet, into latest_timings().
  // execute() does this itself; call it after the last frames to see their timings too. The GPU
  // must have finished the slot's frame (FrameRing::begin_frame or wait_idle).
  void collect_timings(uint32_t slot);

  // The most recent frame whose timestamps have been read (frames_in_flight frames behind);
  // nullopt before the first one or when the device has no timestamps.
  const std::optional<FrameTimings>& latest_timings() const { return latest_timings_; }
  bool timestamps_supported() const { return timer_.supported(); }

  // Transient memory of the plan last executed in `slot`: allocated, and had nothing aliased.
  uint64_t transient_heap_bytes(uint32_t slot) const;
  uint64_t transient_unaliased_bytes(uint32_t slot) const;

 private:
  struct CachedTransients {
    std::weak_ptr<const rg::CompiledPlan> plan;
    const rg::CompiledPlan* key = nullptr;
    std::unique_ptr<TransientResources> resources;
  };
  struct Slot {
    std::vector<CachedTransients> transients;      // most recently used first
    std::shared_ptr<const rg::CompiledPlan> plan;  // in flight; keeps names for timings
    uint64_t frame_number = 0;
    UniqueDescriptorPool descriptors;
  };

  TransientResources& transients_for(Slot& slot, const std::shared_ptr<const rg::CompiledPlan>& plan);
  void record_pass(VkCommandBuffer cmd, const rg::CompiledPass& pass, const rg::PassDeclaration& declaration,
                   PassRecorder& recorder);

  VulkanContext& context_;
  PassTimer timer_;
  std::vector<Slot> slots_;
  std::optional<FrameTimings> latest_timings_;
  // Per-frame scratch, reused so that a frame allocates nothing once they have grown.
  std::vector<PhysicalResource> physical_;
  std::vector<double> pass_ms_;
  BarrierScratch barrier_scratch_;
  std::vector<VkRenderingAttachmentInfo> color_attachments_;
};

}  // namespace sg::vk
