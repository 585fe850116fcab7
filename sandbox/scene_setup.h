#pragma once
// The scene the sandbox renders and the view it starts from, chosen from the command line.
#include <string>

#include "sandbox/options.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"

namespace sg::sandbox {

struct SandboxScene {
  scene::Scene scene;
  scene::CameraPose pose;
  scene::Camera lens;
  // Where the pose came from, for the run's summary: "--camera", "glTF camera 'NAME'"
  // ("glTF camera" when the node has no name), "built-in camera", or "framed bounds".
  std::string camera_source;
};

// Loads options.scene with options.scene_params (scene::load_scene) and picks the view:
// - pose: --camera when given; else the scene's first camera (eye at its world translation,
//   looking down its world -Z); else scene::frame_bounds of the scene's bounds, using the
//   lens's field of view and `aspect` (viewport width / height).
// - lens: the scene's first camera's, also under --camera (the file's field of view belongs to
//   the scene, --camera only moves the eye); scene::Camera{} when the scene has none.
// A scene without any light gets a directional "sandbox sun" with a shadow (and a warning), so
// that files that bring no lights still show their shapes and shadows.
// Throws scene::SceneError when the scene cannot be loaded.
SandboxScene load_sandbox_scene(const Options& options, float aspect);

}  // namespace sg::sandbox
