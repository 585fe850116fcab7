// SPDX-License-Identifier: MIT
#include <glm/gtc/constants.hpp>

#include "systems/scene/builtin_scene_builders.h"
#include "systems/scene/camera.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"

namespace sg::scene {
namespace {

ShadowSettings shadow_with(ShadowAlgorithm algorithm) {
  ShadowSettings shadow;
  shadow.algorithm = algorithm;
  return shadow;
}

}  // namespace

Scene build_default_scene() {
  Scene scene;
  scene.name = "default";
  const std::uint32_t box = add_box_mesh(scene.meshes);
  const std::uint32_t cylinder = add_cylinder_mesh(scene.meshes, 24);
  const Material floor{{0.6f, 0.6f, 0.58f, 1.0f}, no_texture, 0.1f, 16.0f};
  const Material wall{{0.7f, 0.68f, 0.62f, 1.0f}, no_texture, 0.1f, 16.0f};
  const Material stone{{0.55f, 0.55f, 0.6f, 1.0f}};
  const Material crate{{0.6f, 0.4f, 0.25f, 1.0f}, no_texture, 0.3f, 48.0f};

  add_instance(scene, box, placed({0, -0.1f, 0}, {20, 0.2f, 20}), floor);
  for (const float side : {-1.0f, 1.0f}) {
    add_instance(scene, box, placed({0, 2, side * 10.1f}, {20.4f, 4, 0.2f}), wall);
    add_instance(scene, box, placed({side * 10.1f, 2, 0}, {0.2f, 4, 20}), wall);
  }
  for (const glm::vec2 at : {glm::vec2(-4, -4), glm::vec2(4, -4), glm::vec2(-4, 4), glm::vec2(4, 4)}) {
    add_instance(scene, cylinder, placed({at.x, 2, at.y}, {0.8f, 4, 0.8f}), stone);
  }
  struct Crate {
    glm::vec3 center;
    float size;
    float yaw;
  };
  const Crate crates[] = {{{-1.5f, 0.5f, -1.0f}, 1.0f, 0.3f}, {{1.8f, 0.35f, 1.2f}, 0.7f, -0.5f},
                          {{-6.5f, 0.6f, 2.0f}, 1.2f, 0.8f},  {{6.0f, 0.4f, -6.5f}, 0.8f, 0.1f},
                          {{2.5f, 0.75f, -6.0f}, 1.5f, 0.6f}, {{-7.0f, 0.5f, -7.0f}, 1.0f, 0.0f},
                          {{7.0f, 0.5f, 6.5f}, 1.0f, 1.1f},   {{-1.5f, 1.25f, -1.0f}, 0.5f, 1.0f}};
  for (const Crate& c : crates) add_instance(scene, box, placed(c.center, glm::vec3(c.size), c.yaw), crate);

  // One light per kind and algorithm; all five algorithms appear.
  add_light(scene, DirectionalLight{{1.0f, 0.96f, 0.9f}, 0.6f}, aimed({0, 10, 0}, {-3, 0, -4}),
            shadow_with(ShadowAlgorithm::pcf), "sun");
  add_light(scene, PointLight{{1.0f, 0.8f, 0.6f}, 1.0f, 9.0f}, {{-5, 3, 5}},
            shadow_with(ShadowAlgorithm::pcss), "warm point");
  add_light(scene, PointLight{{0.6f, 0.7f, 1.0f}, 0.8f, 8.0f}, {{5, 2.5f, 3}},
            shadow_with(ShadowAlgorithm::hard), "cool point");
  add_light(scene, SpotLight{{1.0f, 1.0f, 0.9f}, 1.5f, 14.0f, 0.35f, 0.5f}, aimed({-6, 3.5f, -6}, {0, 0, 0}),
            shadow_with(ShadowAlgorithm::noise), "spot west");
  add_light(scene, SpotLight{{0.9f, 1.0f, 0.9f}, 1.5f, 14.0f, 0.3f, 0.45f}, aimed({6, 3.5f, 6}, {1, 0, -1}),
            shadow_with(ShadowAlgorithm::pcss_noise), "spot east");
  add_light(scene, CylinderLight{{1.0f, 0.9f, 0.7f}, 0.8f, 0.6f, 1.5f}, aimed({-1.5f, 6, -1}, {-1.5f, 0, -1}),
            shadow_with(ShadowAlgorithm::hard), "beam");

  add_camera(scene.world, {{0, 5, 9}, {0, 0.5f, -2}});
  return scene;
}

}  // namespace sg::scene
