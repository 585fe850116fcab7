// SPDX-License-Identifier: MIT
#include "systems/lighting/shadow_probe.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <glm/packing.hpp>

#include "rendergraph/device/barriers.h"
#include "systems/lighting/light_tiles_pass.h"

namespace sg {
namespace {

// shaders/shadow_probe.comp's header, then three words a pair.
struct Header {
  uint32_t wanted;
  uint32_t kept;
  uint32_t capacity;
  float keep;
  uint32_t listed;
};
constexpr uint64_t words_per_pair = 3;

VkDeviceSize probe_bytes(uint32_t capacity) {
  return sizeof(Header) + capacity * words_per_pair * sizeof(uint32_t);
}

}  // namespace

uint64_t ShadowProbeResult::lighting_list_pairs(uint32_t width) const {
  const uint32_t across = LightTileGrid::of(width, 1).across;
  std::vector<uint64_t> keys;
  keys.reserve(pairs.size());
  for (const ShadowProbePair& pair : pairs) {
    const uint32_t x = pair.pixel % width, y = pair.pixel / width;
    const uint64_t tile = uint64_t{y / tiles::LIGHT_TILE_SIZE} * across + x / tiles::LIGHT_TILE_SIZE;
    keys.push_back(tile << 32 | pair.light);
  }
  std::sort(keys.begin(), keys.end());
  return static_cast<uint64_t>(std::unique(keys.begin(), keys.end()) - keys.begin());
}

ShadowProbe::ShadowProbe(vk::VulkanContext& context, uint64_t capacity, float keep)
    : capacity_(
          static_cast<uint32_t>(std::min<uint64_t>(capacity, std::numeric_limits<uint32_t>::max() / 4))),
      keep_(keep),
      device_(context, vk::BufferDesc{probe_bytes(capacity_),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                          VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                      vk::MemoryUsage::gpu_only, "shadow probe"}),
      host_(context, vk::BufferDesc{probe_bytes(capacity_), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    vk::MemoryUsage::readback, "shadow probe readback"}) {
  if (!(keep > 0.0f && keep <= 1.0f)) throw std::invalid_argument("ShadowProbe: keep must be in (0, 1]");
  if (capacity == 0) throw std::invalid_argument("ShadowProbe: no room for any pair");
}

void ShadowProbe::record_start(VkCommandBuffer cmd) const {
  const Header header{0, 0, capacity_, keep_, 0};
  vkCmdUpdateBuffer(cmd, device_.handle(), 0, sizeof(header), &header);
  vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

void ShadowProbe::record_finish(VkCommandBuffer cmd) const {
  vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  const VkBufferCopy region{0, 0, device_.size()};
  vkCmdCopyBuffer(cmd, device_.handle(), host_.handle(), 1, &region);
  vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

ShadowProbeResult ShadowProbe::read() const {
  Header header;
  std::memcpy(&header, host_.mapped(), sizeof(header));
  ShadowProbeResult result{header.wanted, header.kept, header.listed, {}};
  if (header.kept > capacity_) return result;
  const auto* words =
      reinterpret_cast<const uint32_t*>(static_cast<const std::byte*>(host_.mapped()) + sizeof(Header));
  result.pairs.resize(header.kept);
  for (uint32_t i = 0; i < header.kept; ++i) {
    const glm::vec2 shade_weight = glm::unpackHalf2x16(words[words_per_pair * i + 2]);
    result.pairs[i] = {words[words_per_pair * i], words[words_per_pair * i + 1], shade_weight.x,
                       shade_weight.y};
  }
  return result;
}

}  // namespace sg
