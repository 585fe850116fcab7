// SPDX-License-Identifier: MIT
#pragma once
// Each light's shadow at each pixel of a lit frame, as the frame drew it: for tools that measure
// the whole frame against a reference (tools/reference's --whole-frame). Handed to the renderer
// (SceneRenderer::probe_shadows), the deferred lighting adds a pass after its light groups
// (shaders/shadow_probe.comp) that records, for every (pixel, light) pair whose shadow can
// change the pixel, the light's shade there and its weight (shadow_weight: the most its shadow
// can move the pixel's luminance). Pairs go to a device buffer of fixed capacity, copied to host
// memory at the end of the pass: with the counters in host memory every pair paid atomics across
// the bus, and a 4,096-light frame at 1920x1080 (about 170 pairs a pixel) did not finish within
// 150 s on the H200 (2026-12-02). With `keep` below 1 a random share of the pairs is kept, so
// that frames of many lights fit.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/device/fwd.h"
#include "rendergraph/device/resources.h"

namespace sg {

struct ShadowProbePair {
  uint32_t pixel = 0;  // y * width + x
  uint32_t light = 0;  // index into the frame's light records (FrameLights::records)
  float shade = 0.0f;  // 0 lit .. 1 shadowed, as the frame shaded it
  float weight = 0.0f;
};

struct ShadowProbeResult {
  uint64_t wanted = 0;                 // pairs the frame had
  uint64_t kept = 0;                   // of them, drawn into the sample (all where keep was 1)
  uint64_t listed = 0;                 // (tile, light) pairs the frame's light lists held
  std::vector<ShadowProbePair> pairs;  // the kept pairs, unless more were kept than fit
  bool complete() const { return kept == pairs.size(); }
  // Of the `listed` (tile, light) pairs, those the kept pairs fall in: the pairs that light at
  // least one pixel of a frame `width` pixels wide, where every pair was kept (fewer otherwise).
  uint64_t lighting_list_pairs(uint32_t width) const;
};

class ShadowProbe {
 public:
  // Room for `capacity` pairs; each pair kept with probability `keep` (0 < keep <= 1).
  ShadowProbe(vk::VulkanContext& context, uint64_t capacity, float keep);

  // Around the probe's dispatch, in its pass: clear the counts before, copy the pairs to host
  // memory after (the buffers live outside the frame's graph, so their barriers are here).
  void record_start(VkCommandBuffer cmd) const;
  void record_finish(VkCommandBuffer cmd) const;
  // The last probed frame's pairs; call once its commands have completed.
  ShadowProbeResult read() const;

  // What the probe's shader writes.
  const vk::Buffer& buffer() const { return device_; }

 private:
  uint32_t capacity_;
  float keep_;
  vk::Buffer device_;
  vk::Buffer host_;
};

}  // namespace sg
