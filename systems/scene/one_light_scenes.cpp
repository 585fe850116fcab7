// SPDX-License-Identifier: MIT
// Two static scenes of one shadowed light each, the size of the shadow samples that plain Vulkan
// renderers ship: what a frame costs when there is one light and the geometry is all the work.
#include <glm/gtc/constants.hpp>

#include "systems/scene/builtin_scene_builders.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"

namespace sg::scene {
namespace {

ShadowSettings one_shadow(ShadowAlgorithm algorithm, std::uint32_t resolution) {
  ShadowSettings shadow;
  shadow.algorithm = algorithm;
  shadow.resolution = resolution;
  return shadow;
}

const Material plaster{{0.75f, 0.73f, 0.7f, 1.0f}, no_texture, 0.1f, 16.0f};
const Material stone{{0.55f, 0.55f, 0.6f, 1.0f}, no_texture, 0.3f, 32.0f};

}  // namespace

// A closed 12 x 12 x 6 m room with six columns of 196 sides (4,752 triangles in all), lit by
// one point light in its middle with a 1024 cube, hard shadows.
Scene build_point_room_scene() {
  Scene scene;
  scene.name = "point-room";
  const std::uint32_t box = add_box_mesh(scene.meshes);
  const std::uint32_t column = add_cylinder_mesh(scene.meshes, 196);
  add_instance(scene, box, placed({0, -0.1f, 0}, {12, 0.2f, 12}), plaster);
  add_instance(scene, box, placed({0, 6.1f, 0}, {12, 0.2f, 12}), plaster);
  for (const float side : {-1.0f, 1.0f}) {
    add_instance(scene, box, placed({0, 3, side * 6.1f}, {12.4f, 6, 0.2f}), plaster);
    add_instance(scene, box, placed({side * 6.1f, 3, 0}, {0.2f, 6, 12}), plaster);
  }
  for (int k = 0; k < 6; ++k) {
    const float angle = glm::two_pi<float>() * float(k) / 6.0f;
    add_instance(scene, column,
                 placed({3.2f * std::cos(angle), 1.5f, 3.2f * std::sin(angle)}, {0.9f, 3, 0.9f}), stone);
  }
  add_light(scene, PointLight{{1.0f, 0.95f, 0.85f}, 2.0f, 14.0f}, {{0, 3.5f, 0}},
            one_shadow(ShadowAlgorithm::hard, 1024), "point");
  add_camera(scene.world, {{4.5f, 2.0f, 5.0f}, {-1.0f, 1.0f, -1.0f}});
  return scene;
}

// Twenty-four columns of 560 sides and a floor (53,676 triangles), lit by one spot light with a
// 2048 map, 3 x 3 PCF.
Scene build_spot_columns_scene() {
  Scene scene;
  scene.name = "spot-columns";
  const std::uint32_t box = add_box_mesh(scene.meshes);
  const std::uint32_t column = add_cylinder_mesh(scene.meshes, 560);
  add_instance(scene, box, placed({0, -0.1f, 0}, {30, 0.2f, 30}), plaster);
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 6; ++col) {
      const glm::vec3 at{-7.5f + 3.0f * float(col), 1.0f + 0.25f * float((row + col) % 3),
                         -6.0f + 4.0f * float(row)};
      add_instance(scene, column, placed(at, {0.8f, 2.0f * at.y, 0.8f}), stone);
    }
  }
  ShadowSettings shadow = one_shadow(ShadowAlgorithm::pcf, 2048);
  shadow.kernel.pcf_half_width = 1;
  add_light(scene, SpotLight{{1.0f, 0.97f, 0.9f}, 3.0f, 40.0f, 0.5f, 0.6f},
            aimed({-10.0f, 9.0f, 10.0f}, {0, 0, -1}), shadow, "spot");
  add_camera(scene.world, {{0.0f, 7.0f, 14.0f}, {0.0f, 0.5f, -2.0f}});
  return scene;
}

}  // namespace sg::scene
