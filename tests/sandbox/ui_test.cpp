// SPDX-License-Identifier: MIT
// The panels' state without drawing them: what F frames.
#include <gtest/gtest.h>

#include "ecs/hierarchy.h"
#include "ecs/transform_system.h"
#include "sandbox/mesh_panel.h"
#include "sandbox/ui.h"
#include "systems/scene/lights.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene_builder.h"

namespace sg::sandbox {
namespace {

TEST(SandboxUi, FFramesTheSelectedLightsReachOrNothing) {
  scene::Scene scene;
  scene::PointLight bulb;
  bulb.range = 4.0f;
  const ecs::Entity point =
      scene::add_light(scene, bulb, ecs::LocalTransform{glm::vec3(1, 2, 3)}, {}, "bulb");
  scene::SpotLight far_reaching;
  far_reaching.range = 500.0f;
  const ecs::Entity spot =
      scene::add_light(scene, far_reaching, ecs::LocalTransform{glm::vec3(0)}, {}, "spot");
  const ecs::Entity sun =
      scene::add_light(scene, scene::DirectionalLight{}, ecs::LocalTransform{glm::vec3(0, 9, 0)}, {}, "sun");
  ecs::update_world_transforms(scene.world, 0);
  SandboxUi ui(nullptr);

  EXPECT_TRUE(ui.selection_bounds(scene.world).empty());  // nothing selected: the scene is framed
  ui.select(point);
  scene::Aabb box = ui.selection_bounds(scene.world);
  EXPECT_EQ(box.min, glm::vec3(-3, -2, -1));
  EXPECT_EQ(box.max, glm::vec3(5, 6, 7));
  ui.select(spot);
  EXPECT_EQ(ui.selection_bounds(scene.world).max, glm::vec3(10.0f));  // the reach is held to 10 m
  ui.select(sun);
  box = ui.selection_bounds(scene.world);
  EXPECT_EQ(box.center(), glm::vec3(0, 9, 0));
  EXPECT_EQ(box.extent(), glm::vec3(2.0f));
  scene.world.destroy(point);
  ui.select(point);
  EXPECT_TRUE(ui.selection_bounds(scene.world).empty());
}

TEST(MeshPanel, ADrawableIsNamedByItselfItsParentOrItsMesh) {
  scene::Scene scene;
  const uint32_t box = scene::add_box_mesh(scene.meshes);
  const ecs::Entity plain = scene::add_instance(scene, box, {}, scene::Material{});
  const ecs::Entity named = scene::add_instance(scene, box, {}, scene::Material{});
  scene.world.add<scene::Name>(named, "crate");
  const ecs::Entity node = scene.world.create();
  scene.world.add<scene::Name>(node, "table");
  const ecs::Entity primitive = scene::add_instance(scene, box, {}, scene::Material{});
  ecs::set_parent(scene.world, primitive, node);
  EXPECT_EQ(mesh_label(scene.world, plain), "mesh " + std::to_string(box));
  EXPECT_EQ(mesh_label(scene.world, named), "crate");
  EXPECT_EQ(mesh_label(scene.world, primitive), "table") << "an imported node's primitive";
}

}  // namespace
}  // namespace sg::sandbox
