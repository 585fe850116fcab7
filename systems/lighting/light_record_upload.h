// SPDX-License-Identifier: MIT
#pragma once
// The frame's light records in light-group order (shadows::sort_by_group), kept here from frame
// to frame and copied into the frame slot's buffer, which the lighting passes read: only the
// records that changed since that slot was last written, then the cascades' records after them.
// The buffers lie in stream memory (vk::MemoryUsage), device-local where the device maps it, so
// each byte written crosses the bus: 100,000 records are 20.8 MB, most of them unchanged from
// frame to frame with 5% of the lights moving. There the CPU frame took 5.26-5.31 ms against
// 5.69-5.70 writing every record (H100's host, 1920x1080, from afar, 2026-12-06).
#include <cstdint>
#include <vector>

#include "ecs/jobs/thread_pool.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "systems/shadows/frame_lights.h"

namespace sg {

class LightRecordUpload {
 public:
  LightRecordUpload(vk::VulkanContext& context, uint32_t frames_in_flight);

  // Sorts `lights`' records by group into the slot's buffer, after them `lights.cascades`. Throws
  // std::runtime_error where the device's texel buffers cannot hold them all.
  const vk::Buffer& upload(shadows::FrameLights& lights, uint32_t slot, jobs::ThreadPool* pool);

  const vk::Buffer& buffer(uint32_t slot) const { return buffers_.buffer(slot); }

 private:
  vk::FrameBuffers buffers_;
  std::size_t max_records_;  // what the device's texel buffers hold (maxTexelBufferElements)
  std::vector<shadows::GpuLight> sorted_;
  std::vector<uint64_t> changed_at_;   // by place: the upload that last changed its record
  std::vector<uint64_t> uploaded_at_;  // by slot: the upload whose records it holds
  uint64_t uploads_ = 0;
};

}  // namespace sg
