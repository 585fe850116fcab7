#pragma once

namespace sg::shadows {

// How a point light's six cube faces are rendered: in one layered pass (the vertex shader picks
// the face with gl_Layer; needs shaderOutputLayer) or in six passes, one per face.
enum class CubeShadowMode { layered, six_passes };

}  // namespace sg::shadows
