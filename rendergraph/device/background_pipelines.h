// SPDX-License-Identifier: MIT
#pragma once
// Compute pipelines built on a thread of their own, for passes that can do without theirs until
// it is ready (TiledLightingPass's group sets: on lavapipe a pipeline holding several shadow
// algorithms takes about 2 s to build, which a frame should not wait for). One thread builds
// them in the order asked; the frame thread asks, looks for what is built and may wait for it.
//
//   BackgroundPipelines builds(context);
//   builds.request(key, {spirv, constants, layout, "name"});   // once per key, returns at once
//   if (VkPipeline built = builds.find(key)) { ... }            // null until built
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <utility>

#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/unique_handle.h"

namespace sg::vk {

class BackgroundPipelines {
 public:
  explicit BackgroundPipelines(VulkanContext& context) : context_(context) {}
  // Waits for the build in progress and drops those not started.
  ~BackgroundPipelines();
  BackgroundPipelines(const BackgroundPipelines&) = delete;
  BackgroundPipelines& operator=(const BackgroundPipelines&) = delete;

  // Queues the build of `desc` as pipeline `key`, unless `key` was asked for before. The SPIR-V
  // `desc` points at must outlive the build (the embedded shaders do).
  void request(uint64_t key, ComputePipelineDesc desc);
  // Pipeline `key` once built; null while it waits or builds, or when never asked for. Throws
  // what a build threw (a std::runtime_error naming the pipeline), once.
  VkPipeline find(uint64_t key);
  // Whether `key` was asked for, built or not.
  bool asked(uint64_t key) const;
  // Waits until every pipeline asked for is built.
  void wait();
  // Pipelines asked for and not built yet.
  size_t pending() const;

 private:
  void build_queued();

  VulkanContext& context_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::pair<uint64_t, ComputePipelineDesc>> queue_;
  std::unordered_map<uint64_t, UniquePipeline> built_;  // null while queued or building
  size_t building_ = 0;                                 // 1 while the thread builds one
  std::exception_ptr error_;
  bool stopping_ = false;
  std::thread thread_;  // started at the first request
};

}  // namespace sg::vk
