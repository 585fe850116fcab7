#include "sandbox/frame_cost.h"

#include <algorithm>

#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "sandbox/gpu_time_log.h"
#include "sandbox/headless_frames.h"
#include "sandbox/sandbox_frame.h"
#include "sandbox/scene_setup.h"

namespace sg::sandbox {

FrameCost measure_frame_cost(vk::VulkanContext& context, const Options& options, uint32_t frames) {
  SandboxScene scene = load_sandbox_scene(options, float(options.width) / float(options.height));
  vk::FrameRing ring(context);
  SandboxFrame frame(context, scene, options, ring.frames_in_flight());
  frame.resize({options.width, options.height});
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
  cost.shadowed_lights = static_cast<uint32_t>(lights.maps.size() + lights.cubes.size());
  return cost;
}

}  // namespace sg::sandbox
