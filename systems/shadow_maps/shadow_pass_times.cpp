// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_pass_times.h"

#include <string>

#include "rendergraph/vulkan/graph_executor.h"

namespace sg {

ShadowPassTimes shadow_pass_times(const vk::FrameTimings& timings) {
  ShadowPassTimes times;
  for (size_t p = 0; p < timings.pass_ms.size(); ++p) {
    const std::string& name = timings.plan->passes[p].name;
    if (!name.starts_with("shadow ")) continue;
    times.ms += timings.pass_ms[p];
    if (name == "shadow raster") times.raster = shadows::ShadowRaster::compute;
    if (name == "shadow views") times.raster = shadows::ShadowRaster::hardware;
  }
  return times;
}

}  // namespace sg
