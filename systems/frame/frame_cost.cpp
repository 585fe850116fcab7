// SPDX-License-Identifier: MIT
#include "systems/frame/frame_cost.h"

#include <algorithm>

#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "systems/frame/frame.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/headless_frames.h"
#include "systems/frame/scene_view.h"
#include "systems/shadows/frame_lights.h"

namespace sg {

FrameCost measure_frame_cost(vk::VulkanContext& context, const FrameSettings& settings, uint32_t frames) {
  SceneView view = load_scene_view(settings, float(settings.width) / float(settings.height));
  vk::FrameRing ring(context);
  Frame frame(context, view, settings, ring.frames_in_flight());
  frame.resize({settings.width, settings.height});
  // The first frames pay for first use (pipelines, memory, and on GPUs clocks rising from idle,
  // which made the first configuration a tool measured look several times slower than the same
  // one measured later): rendered, not counted.
  const uint32_t warm_up = std::max(frames / 2, 2u);
  GpuTimeLog discarded;
  render_headless_frames(frame, ring, warm_up, discarded);
  GpuTimeLog log;
  render_headless_frames(frame, ring, frames, log, false, warm_up);
  FrameCost cost;
  for (const PassTime& pass : log.pass_summaries()) {
    (pass.name.rfind("shadow", 0) == 0 ? cost.shadow_maps_ms : cost.lighting_ms) += pass.gpu_ms.median;
  }
  if (const auto frame_ms = summarize(log.frame_ms())) cost.frame_ms = frame_ms->median;
  const shadows::FrameLights& lights = frame.renderer().lights();
  cost.shadowed_lights = shadows::shadowed_light_count(lights);
  return cost;
}

}  // namespace sg
