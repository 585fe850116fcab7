// SPDX-License-Identifier: MIT
#pragma once
// Scripted sandbox runs (--script FILE), so that what a person would do in the window can be
// done, and tested, without one. One command a line; `#` starts a comment:
//
//   select NAME              the light named NAME (its scene name) becomes the selected one
//   algorithm NAME           its shadow algorithm: hard, pcf, noise, pcss, pcss_noise
//   resolution N             its requested shadow resolution, texels
//   update MODE              when its map is drawn again: auto, every_frame, on_demand
//   priority T               tiers added to its atlas importance, -4 to 4
//   redraw_shadow            ask for its map to be drawn again (scene::request_shadow_redraw)
//   move X Y Z               its position
//   camera EX,EY,EZ,TX,TY,TZ the view, as --camera
//   wait N                   render N frames (1/60 s each)
//   screenshot PATH          write the last frame as PNG
//   view lit|shadows         the picture, or the shadow-only debug view (--view)
//   save                     write the lights and camera beside the scene (scene_sidecar.h)
//   open PATH                replace the scene by a .gltf or .glb file (or a built-in scene), as
//                            dropping it on the window does; the view is the file's
//
// Edits are ECS writes, as the panels' are. Errors name the file and line.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "systems/lighting/lighting_path.h"
#include "systems/scene/camera.h"
#include "systems/scene/shadow_settings.h"

namespace sg::sandbox {

struct ScriptStep {
  struct Select {
    std::string name;
  };
  struct Algorithm {
    scene::ShadowAlgorithm algorithm;
  };
  struct Resolution {
    uint32_t texels;
  };
  struct Update {
    scene::ShadowUpdate update;
  };
  struct Priority {
    float tiers;
  };
  struct RedrawShadow {};
  struct Move {
    glm::vec3 position;
  };
  struct Camera {
    scene::CameraPose pose;
  };
  struct Wait {
    uint32_t frames;
  };
  struct Screenshot {
    std::string path;
  };
  struct View {
    LightingView view;
  };
  struct Save {};
  struct Open {
    std::string path;
  };
  std::variant<Select, Algorithm, Resolution, Update, Priority, RedrawShadow, Move, Camera, Wait, Screenshot,
               View, Save, Open>
      command;
  int line = 0;
};

// Parses `text` (from file `path`, for messages). Throws std::runtime_error
// "PATH:LINE: problem" for an unknown command or a malformed argument.
std::vector<ScriptStep> parse_script(const std::string& text, const std::string& path);

// Reads and parses the file; a missing or unreadable file is a std::runtime_error naming it.
std::vector<ScriptStep> load_script(const std::string& path);

}  // namespace sg::sandbox
