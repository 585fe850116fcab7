// SPDX-License-Identifier: MIT
// Per-view caster culling: which instances a light's shadow view keeps, and the indirect
// commands that draw them.
#include <random>

#include <gtest/gtest.h>

#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/scene_queries.h"
#include "systems/shadow_maps/shadow_caster_lists.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

class ShadowCasterListsTest : public GpuTest {
 protected:
  // Unit boxes at x = 0, 5 and 20, a cylinder at x = 5, and a box at x = 0 that casts no shadow.
  ShadowCasterListsTest() {
    box = scene::add_box_mesh(world.meshes);
    cylinder = scene::add_cylinder_mesh(world.meshes, 8);
    for (float x : {0.0f, 5.0f, 20.0f}) {
      scene::add_instance(world, box, {{x, 0.0f, 0.0f}}, scene::Material{});
    }
    scene::add_instance(world, cylinder, {{5.0f, 0.0f, 0.0f}}, scene::Material{});
    const ecs::Entity receiver = scene::add_instance(world, box, {{0.0f, 0.0f, 0.0f}}, scene::Material{});
    world.world.get_mut<scene::MeshInstance>(receiver).casts_shadow = false;
    ecs::update_world_transforms(world.world, 0);
    gpu = std::make_unique<GpuScene>(context, world.meshes, 1);
    gpu->gather(world.world);
    gpu->upload(0);
  }

  scene::Scene world;
  uint32_t box = 0;
  uint32_t cylinder = 0;
  std::unique_ptr<GpuScene> gpu;
  ShadowCasterLists lists{context, 1};
};

TEST_F(ShadowCasterListsTest, AViewKeepsTheCastersWithinItsLightsReach) {
  ASSERT_EQ(gpu->caster_groups().size(), 2u);  // boxes, cylinder
  EXPECT_EQ(gpu->caster_groups()[0].instanceCount, 3u) << "the receiver-only box is not a caster";

  lists.begin_frame(*gpu, 3.0f);
  const CasterView near = lists.add_view(*gpu, {0.0f, 0.0f, 0.0f, 6.0f}, scene::all_layers, 1);
  EXPECT_EQ(near.command_count, 2u);
  EXPECT_EQ(lists.kept_instances(), 3u) << "boxes at 0 and 5 and the cylinder; not the box at 20";

  const CasterView box_only = lists.add_view(*gpu, {0.0f, 0.0f, 0.0f, 1.0f}, scene::all_layers, 1);
  EXPECT_EQ(box_only.first_command, 2u);
  EXPECT_EQ(box_only.command_count, 1u);
  EXPECT_EQ(lists.kept_instances(), 4u);

  const CasterView nothing = lists.add_view(*gpu, {100.0f, 0.0f, 0.0f, 1.0f}, scene::all_layers, 1);
  EXPECT_EQ(nothing.command_count, 0u);
  lists.upload(0);
}

TEST_F(ShadowCasterListsTest, ANegativeRadiusKeepsEveryCaster) {
  lists.begin_frame(*gpu, 3.0f);
  const CasterView all = lists.add_view(*gpu, {0.0f, 0.0f, 0.0f, -1.0f}, scene::all_layers, 6);
  EXPECT_EQ(all.command_count, 2u);
  EXPECT_EQ(lists.kept_instances(), 4u);
  lists.upload(0);
}

// A view keeps only the casters on its light's caster mask's layers, with a reach and without.
TEST_F(ShadowCasterListsTest, AViewKeepsOnlyTheCastersOnItsLightsLayers) {
  bool first = true;
  world.world.query<scene::MeshInstance>().for_each([&](ecs::Entity, scene::MeshInstance& instance) {
    if (first) instance.shadow_layers = 0x04;  // the box at x = 0 on layer 2 alone
    first = false;
  });
  gpu->gather(world.world);
  lists.begin_frame(*gpu, 3.0f);
  lists.add_view(*gpu, {0.0f, 0.0f, 0.0f, 6.0f}, scene::first_layer, 1);
  EXPECT_EQ(lists.kept_instances(), 2u) << "the box at 5 and the cylinder; the box at 0 is on layer 2";
  lists.add_view(*gpu, {0.0f, 0.0f, 0.0f, -1.0f}, 0x04, 1);
  EXPECT_EQ(lists.kept_instances(), 3u) << "everywhere, only the box at 0 is on layer 2";
  lists.add_view(*gpu, {0.0f, 0.0f, 0.0f, -1.0f}, 0x05, 1);
  EXPECT_EQ(lists.kept_instances(), 7u) << "layers 0 and 2 hold all four casters";
  lists.upload(0);
}

// The grid must find exactly what testing every caster finds, for any sphere.
TEST(ShadowCasterListsGrid, KeepsExactlyWhatABruteForceTestKeeps) {
  vk::VulkanContext context(validated_options());
  scene::BuiltinSceneParams params;
  params.triangles = 20000;
  params.point_lights = 0;
  params.spot_lights = 0;
  scene::Scene stress = scene::build_scene("stress", params);
  GpuScene gpu(context, stress.meshes, 1);
  gpu.gather(stress.world);
  gpu.upload(0);
  ShadowCasterLists lists(context, 1);
  lists.begin_frame(gpu, 4.0f);

  const scene::Aabb hall = scene::scene_bounds(stress);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  uint64_t kept_before = 0;
  int nonempty = 0;
  for (int view = 0; view < 200; ++view) {
    const glm::vec3 centre = hall.min + glm::vec3(unit(random), unit(random), unit(random)) * hall.extent();
    const float radius = 0.5f + 15.0f * unit(random);
    uint64_t expected = 0;
    for (const VkDrawIndexedIndirectCommand& group : gpu.caster_groups()) {
      for (uint32_t i = group.firstInstance; i < group.firstInstance + group.instanceCount; ++i) {
        const scene::Aabb& box = gpu.instance_bounds()[i];
        const glm::vec3 d = glm::clamp(centre, box.min, box.max) - centre;
        expected += glm::dot(d, d) <= radius * radius;
      }
    }
    lists.add_view(gpu, glm::vec4(centre, radius), scene::all_layers, 1);
    EXPECT_EQ(lists.kept_instances() - kept_before, expected) << "view " << view;
    kept_before = lists.kept_instances();
    nonempty += expected > 0;
  }
  EXPECT_GT(nonempty, 50) << "the spheres must meet casters for the comparison to mean anything";
  EXPECT_EQ(context.validation_errors(), 0u);
}

}  // namespace
}  // namespace sg::test
