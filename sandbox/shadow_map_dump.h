// SPDX-License-Identifier: MIT
#pragma once
// --dump-shadow-maps DIR: every light's shadow map as a grey PNG, for looking at what the
// shadow passes rendered. 2D maps (spot, directional, cylinder) show linear depth from the
// light's near (black) to far plane (white), over the light's own square region of its
// layer; point lights write six files, one per cube face, of distance / range.
#include <string>

namespace sg {
class SceneRenderer;
namespace vk {
class VulkanContext;
}
}  // namespace sg

namespace sg::sandbox {

// Creates `directory` if needed. The GPU must be idle and the renderer must have rendered a
// frame (the maps are in the state the frame left them). Throws std::runtime_error naming the
// path when a file cannot be written.
void dump_shadow_maps(vk::VulkanContext& context, const SceneRenderer& renderer,
                      const std::string& directory);

}  // namespace sg::sandbox
