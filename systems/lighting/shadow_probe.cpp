#include "systems/lighting/shadow_probe.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/packing.hpp>

namespace sg {
namespace {

// shaders/shadow_probe.comp's header, then three words a pair.
struct Header {
  uint32_t wanted;
  uint32_t kept;
  uint32_t capacity;
  float keep;
};
constexpr uint64_t words_per_pair = 3;

}  // namespace

ShadowProbe::ShadowProbe(vk::VulkanContext& context, uint64_t capacity, float keep)
    : capacity_(
          static_cast<uint32_t>(std::min<uint64_t>(capacity, std::numeric_limits<uint32_t>::max() / 4))),
      keep_(keep),
      buffer_(context,
              vk::BufferDesc{sizeof(Header) + capacity_ * words_per_pair * sizeof(uint32_t),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::readback, "shadow probe"}) {
  if (!(keep > 0.0f && keep <= 1.0f)) throw std::invalid_argument("ShadowProbe: keep must be in (0, 1]");
  if (capacity == 0) throw std::invalid_argument("ShadowProbe: no room for any pair");
  reset();
}

void ShadowProbe::reset() {
  const Header header{0, 0, capacity_, keep_};
  std::memcpy(buffer_.mapped(), &header, sizeof(header));
}

ShadowProbeResult ShadowProbe::read() const {
  Header header;
  std::memcpy(&header, buffer_.mapped(), sizeof(header));
  ShadowProbeResult result{header.wanted, header.kept, {}};
  if (header.kept > capacity_) return result;
  const auto* words =
      reinterpret_cast<const uint32_t*>(static_cast<const std::byte*>(buffer_.mapped()) + sizeof(Header));
  result.pairs.resize(header.kept);
  for (uint32_t i = 0; i < header.kept; ++i) {
    const glm::vec2 shade_weight = glm::unpackHalf2x16(words[words_per_pair * i + 2]);
    result.pairs[i] = {words[words_per_pair * i], words[words_per_pair * i + 1], shade_weight.x,
                       shade_weight.y};
  }
  return result;
}

}  // namespace sg
