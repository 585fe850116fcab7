#pragma once
// Camera matrices in the engine's conventions: right-handed world with +Y up, Vulkan clip
// space (y pointing down in NDC, depth in [0, 1]). The camera itself is scene data: its lens
// (scene::Camera) and its placement (scene::CameraPose).
#include <glm/glm.hpp>

#include "systems/scene/camera.h"

namespace sg {

glm::mat4 view_matrix(const scene::CameraPose& pose);
// `aspect` is width / height of the viewport; the lens's own aspect, when set, wins.
glm::mat4 projection_matrix(const scene::Camera& lens, float aspect);

}  // namespace sg
