// SPDX-License-Identifier: MIT
#pragma once
// How many entries the pool of light culling's lists holds (shaders/light_tiles_interface.glsl):
// every tile takes as many entries as lights reach it, so the pool is sized for what frames ask
// rather than by a limit per tile.
//
// A frame's pool holds every light in every tile (no frame asks for more; rounded up to a power
// of two so that adding a light rarely makes a new buffer) up to `sure_entries`, so that no frame
// of up to that many pairs can run out, whatever came before it; past that, twice what recent
// frames asked for (room for lights to move or come into view before the next answer comes back,
// frames in flight later), a power of two; never more than `max_entries`, the device's limit.
// It grows at once when a frame asks for more than half of it, and shrinks only after
// shrink_after frames in a row asked for less than an eighth, so that it is not rebuilt (a new
// buffer, a new plan) while a crowd of lights comes and goes. A frame that asks for more than
// its pool holds lists what fits and counts the rest as dropped.
#include <cstdint>

namespace sg {

class LightListPool {
 public:
  // 32 MiB: every one of 1,024 lights in every tile of a 1920x1080 frame.
  static constexpr uint64_t sure_entries = uint64_t{1} << 23;
  static constexpr uint64_t shrink_after = 120;

  explicit LightListPool(uint64_t max_entries) : max_entries_(max_entries) {}

  // The entries for a frame culling `lights` lights over `tiles` tiles.
  uint64_t entries(uint32_t tiles, uint32_t lights) const;
  // A frame asked for `wanted` entries.
  void asked(uint64_t wanted);

 private:
  uint64_t max_entries_;
  uint64_t sized_ = 0;  // from the frames' answers; 0 before the first
  uint64_t frames_small_ = 0;
};

}  // namespace sg
