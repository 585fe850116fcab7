// SPDX-License-Identifier: MIT
#pragma once
// The scene a frame renders and the view it starts from, chosen by the frame settings.
#include <string>

#include "systems/frame/frame_settings.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"

namespace sg {

struct SceneView {
  scene::Scene scene;
  scene::CameraPose pose;
  scene::Camera lens;
  // Where the pose came from, for the run's summary: "--camera", "--camera NAME", "glTF camera
  // 'NAME'" ("glTF camera" when the node has no name), "built-in camera", or "framed bounds".
  std::string camera_source;
};

// Loads settings.scene with settings.scene_params (scene::load_scene) and picks the view:
// - pose: --camera's pose when given; else the camera --camera names (SceneError listing the
//   scene's camera names when it has none of that name); else the scene's first camera (eye at its world
//   translation, looking down its world -Z); else scene::frame_bounds of the scene's bounds, using the lens's
//   field of view and `aspect` (viewport width / height).
// - lens: that camera's (the first one's under a --camera pose (the file's field of view belongs to
//   the scene, a pose only moves the eye)); scene::Camera{} when the scene has none.
// Then the saved edits beside the scene (scene_sidecar.h; with settings.sidecar, the pose only
// without --camera), then settings.algorithm for every light.
// A scene without any light gets a directional "sandbox sun" with a shadow (and a warning), so
// that files that bring no lights still show their shapes and shadows.
// Throws scene::SceneError when the scene cannot be loaded.
SceneView load_scene_view(const FrameSettings& settings, float aspect);

}  // namespace sg
