// SPDX-License-Identifier: MIT
#include "tests/support/floor_box_scene.h"

#include <span>

#include "ecs/transform_system.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"

namespace sg::test {

ecs::LocalTransform box_placement(const ShadowScene& s) {
  const glm::vec3 size{1.6f, 0.5f, 1.2f};
  return {{0.0f, s.box_bottom + size.y / 2, 0.0f}, glm::angleAxis(0.5f, glm::vec3(0, 1, 0)), size};
}

ecs::LocalTransform aimed_light(glm::vec3 position, glm::vec3 direction) {
  return {position, scene::look_rotation(position, position + direction), glm::vec3(1.0f)};
}

scene::Scene floor_scene(const char* name, uint32_t& box) {
  scene::Scene out;
  out.name = name;
  box = scene::add_box_mesh(out.meshes);
  scene::Material floor;
  floor.base_color = {0.6f, 0.6f, 0.6f, 1.0f};
  floor.specular = 0.0f;  // keeps shade measurable: no highlight to clip
  scene::add_instance(
      out, box,
      {{0.0f, -0.1f, 0.0f}, glm::quat(1, 0, 0, 0), {2 * floor_half_extent, 0.2f, 2 * floor_half_extent}},
      floor);
  return out;
}

scene::Scene build_shadow_scene(const ShadowScene& s, float intensity) {
  uint32_t box = 0;
  scene::Scene scene = floor_scene("shadow test", box);
  if (s.with_box) scene::add_instance(scene, box, box_placement(s), scene::Material{});
  if (s.scene_half_extent > floor_half_extent) {
    for (const float side : {-1.0f, 1.0f}) {
      const float at = side * s.scene_half_extent;
      scene::add_instance(scene, box, {{at, 0.1f, at}, glm::quat(1, 0, 0, 0), glm::vec3(0.2f)},
                          scene::Material{});
    }
  }
  const ecs::LocalTransform aim = aimed_light(s.light_position, s.aim);
  if (s.kind == LightKind::directional) {
    scene::DirectionalLight light;
    light.intensity = intensity;
    scene::add_light(scene, light, aim, s.shadow, "sun");
  } else if (s.kind == LightKind::spot) {
    scene::SpotLight light;
    light.intensity = intensity;
    light.range = 20.0f;
    light.inner_cone = glm::radians(55.0f);
    light.outer_cone = glm::radians(65.0f);
    scene::add_light(scene, light, aim, s.shadow, "spot");
  } else {
    scene::PointLight light;
    light.intensity = intensity;
    light.range = 20.0f;
    scene::add_light(scene, light, aim, s.shadow, "point");
  }
  ecs::update_world_transforms(scene.world, 0);
  return scene;
}

CameraImage floor_camera(glm::uvec2 size) {
  CameraImage c;
  c.pose = {{0.0f, 11.0f, 6.0f}, {0.0f, 0.0f, 0.0f}};
  c.lens = scene::Camera{};
  c.size = size;
  return c;
}

glm::vec3 reference_light_position(const ShadowScene& s) {
  // 10 km away the rays to a floor point 10 m from the centre turn by 1 mrad: 1.5 mm at the box.
  return s.kind == LightKind::directional ? -1.0e4f * glm::normalize(s.aim) : s.light_position;
}

FloorPixels floor_reference(const ShadowScene& s, glm::uvec2 size, int band) {
  const Box box{ecs::to_matrix(box_placement(s))};
  return with_edge_band(classify_floor(floor_camera(size), floor_half_extent, reference_light_position(s),
                                       std::span<const Box>(&box, s.with_box ? 1 : 0)),
                        band);
}

}  // namespace sg::test
