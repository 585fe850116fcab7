// SPDX-License-Identifier: MIT
#include "systems/lighting/light_record_upload.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "rendergraph/device/context.h"
#include "systems/gpu/changed_items_copy.h"
#include "systems/lighting/light_resources.h"

namespace sg {

LightRecordUpload::LightRecordUpload(vk::VulkanContext& context, uint32_t frames_in_flight)
    : buffers_(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
               frames_in_flight, "light records", light_record_texel_format),
      max_records_(context.properties().limits.maxTexelBufferElements / (sizeof(shadows::GpuLight) / 16)),
      uploaded_at_(frames_in_flight, 0) {}

const vk::Buffer& LightRecordUpload::upload(shadows::FrameLights& lights, uint32_t slot,
                                            jobs::ThreadPool* pool) {
  const size_t count = lights.records.size();
  if (count + lights.cascades.size() > max_records_) {
    throw std::runtime_error(std::to_string(count) + " lights and " + std::to_string(lights.cascades.size()) +
                             " cascades, but this device's texel buffers hold " +
                             std::to_string(max_records_) + " light records");
  }
  ++uploads_;
  if (sorted_.size() != count) {  // every place changes, for every slot
    sorted_.resize(count);
    changed_at_.assign(count, uploads_);
  }
  shadows::sort_by_group(lights, sorted_, pool, {changed_at_, uploads_});

  const VkDeviceSize bytes = (count + lights.cascades.size()) * sizeof(shadows::GpuLight);
  const bool grows = buffers_.buffer(slot).size() < bytes;
  const vk::Buffer& buffer = buffers_.reserve(slot, bytes);
  auto* mapped = static_cast<shadows::GpuLight*>(buffer.mapped());
  // Pieces of 512 records (104 KiB).
  copy_changed_items(mapped, std::span<const shadows::GpuLight>(sorted_),
                     std::span<const uint64_t>(changed_at_), std::exchange(uploaded_at_[slot], uploads_),
                     grows, 512, pool);
  std::copy(lights.cascades.begin(), lights.cascades.end(), mapped + count);
  return buffer;
}

}  // namespace sg
