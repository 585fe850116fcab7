// SPDX-License-Identifier: MIT
#include "rendergraph/device/background_pipelines.h"

namespace sg::vk {

BackgroundPipelines::~BackgroundPipelines() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void BackgroundPipelines::request(uint64_t key, ComputePipelineDesc desc) {
  {
    const std::lock_guard lock(mutex_);
    if (!built_.try_emplace(key).second) return;
    queue_.emplace_back(key, std::move(desc));
    if (!thread_.joinable()) thread_ = std::thread([this] { build_queued(); });
  }
  changed_.notify_all();
}

VkPipeline BackgroundPipelines::find(uint64_t key) {
  const std::lock_guard lock(mutex_);
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  const auto found = built_.find(key);
  return found == built_.end() ? VK_NULL_HANDLE : found->second.get();
}

bool BackgroundPipelines::asked(uint64_t key) const {
  const std::lock_guard lock(mutex_);
  return built_.contains(key);
}

void BackgroundPipelines::wait() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return (queue_.empty() && building_ == 0) || error_; });
}

size_t BackgroundPipelines::pending() const {
  const std::lock_guard lock(mutex_);
  return queue_.size() + building_;
}

void BackgroundPipelines::build_queued() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    auto [key, desc] = std::move(queue_.front());
    queue_.pop_front();
    building_ = 1;
    lock.unlock();
    UniquePipeline pipeline;
    std::exception_ptr error;
    try {
      pipeline = create_compute_pipeline(context_, desc);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    building_ = 0;
    if (error) {
      error_ = error;
    } else {
      built_[key] = std::move(pipeline);
    }
    changed_.notify_all();
  }
}

}  // namespace sg::vk
