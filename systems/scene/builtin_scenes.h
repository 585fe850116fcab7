// SPDX-License-Identifier: MIT
#pragma once
// Scenes that need no files, selected by name, and the one entry point for the sandbox's
// --scene default|stress|point-room|spot-columns|PATH.
//
// "default": a 20 x 20 m room (floor top at y = 0, four walls 4 m high, no ceiling), four
//   pillars and eight boxes, lit by a directional sun, two point lights, two spot lights and a
//   cylinder light; every light casts a shadow and each of the five algorithms is used by at
//   least one light. Fixed content (the seed is not used). Has a camera.
// "stress": a hall of columns and furniture on a grid of 4 m cells, filled until the triangle
//   count reaches `triangles`, with the requested point and spot lights (algorithms assigned in
//   turn, so all five appear once there are five lights), a sun, and a camera framing the hall.
//   `moving_fraction` of the lights and of the crates get an OrbitMotion (animate_orbits).
//   Everything follows from `seed`: equal parameters give identical scenes.
// "point-room": a closed room with six columns (4,752 triangles), one point light in its middle
//   with a 1024 cube and hard shadows. "spot-columns": 24 columns on a floor (53,676 triangles),
//   one spot light with a 2048 map and 3 x 3 PCF. Both static, with a camera: the size of the
//   shadow samples plain Vulkan renderers ship, for comparing one-light frames.
// Built-in lights use FalloffMode::linear_window.
#include <array>
#include <cstdint>
#include <string_view>

#include <glm/glm.hpp>

#include "ecs/world.h"
#include "systems/scene/motions.h"  // the stress scene's moving entities carry OrbitMotion
#include "systems/scene/scene.h"

namespace sg::scene {

struct BuiltinSceneParams {
  std::uint64_t triangles = 250'000;  // stress: target, met within one cell's furniture (~200)
  std::uint32_t point_lights = 32;
  std::uint32_t spot_lights = 32;
  float moving_fraction = 0.1f;  // [0, 1] of lights and of crates
  // (0, 1]: the side of the square the lights are spread over, as a fraction of the hall's. Below
  // 1 the square is centred across the hall from its near edge, in front of the street camera:
  // the same lights, their reaches overlapping more (0.5: a quarter of the floor).
  float light_spread = 1.0f;
  std::uint64_t seed = 1;
};

inline constexpr std::array<std::string_view, 4> builtin_scene_names = {"default", "stress", "point-room",
                                                                        "spot-columns"};

// Throws SceneError for an unknown name (the message lists the known ones) or a
// moving_fraction outside [0, 1]. World transforms are up to date on return.
Scene build_scene(std::string_view name, const BuiltinSceneParams& params = {});

// A built-in scene when `name_or_path` is one of builtin_scene_names, otherwise load_gltf.
Scene load_scene(std::string_view name_or_path, const BuiltinSceneParams& params = {});

}  // namespace sg::scene
