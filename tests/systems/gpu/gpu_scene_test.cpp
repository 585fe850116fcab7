// SPDX-License-Identifier: MIT
// GpuScene's incremental gathering: after any sequence of moves, material edits, additions and
// removals, what a long-lived GpuScene holds and uploads must equal what a fresh one gathers
// from scratch, and what it says it re-placed must cover every move.
#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "ecs/jobs/thread_pool.h"
#include "ecs/query.h"
#include "ecs/transform_system.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene/scene.h"
#include "systems/scene/scene_builder.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

std::vector<ecs::Entity> instances_of(ecs::World& world) {
  std::vector<ecs::Entity> found;
  world.query<const ecs::WorldTransform, const scene::MeshInstance>().for_each(
      [&](ecs::Entity e, const ecs::WorldTransform&, const scene::MeshInstance&) { found.push_back(e); });
  return found;
}

void expect_same_boxes(std::span<const scene::Aabb> a, std::span<const scene::Aabb> b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].min, b[i].min) << "instance " << i;
    ASSERT_EQ(a[i].max, b[i].max) << "instance " << i;
  }
}

// Two boxes of default material, at x = 0 and x = 4, their transforms up to date and the tick
// past them, as a renderer finds a loaded scene.
struct TwoBoxes {
  scene::Scene scene;
  uint32_t box = 0;  // the mesh
  ecs::Entity first;
  ecs::Entity second;
};
TwoBoxes two_boxes() {
  TwoBoxes boxes;
  boxes.box = scene::add_box_mesh(boxes.scene.meshes);
  boxes.first = scene::add_instance(boxes.scene, boxes.box, {{0.0f, 0.0f, 0.0f}}, scene::Material{});
  boxes.second = scene::add_instance(boxes.scene, boxes.box, {{4.0f, 0.0f, 0.0f}}, scene::Material{});
  ecs::update_world_transforms(boxes.scene.world, 0);
  boxes.scene.world.advance_tick();
  return boxes;
}

class GpuSceneTest : public GpuTest {};

// On a pool, with instances in several chunks of the scene's bounds, so that moves fall into
// different chunks and the pieces run concurrently.
TEST_F(GpuSceneTest, IncrementalGatherEqualsAFreshGatherEveryFrame) {
  scene::BuiltinSceneParams params;
  params.triangles = 40000;
  params.point_lights = 0;
  params.spot_lights = 0;
  scene::Scene s = scene::build_scene("stress", params);
  ecs::World& world = s.world;
  constexpr uint32_t slots = 2;
  GpuScene kept(context, s.meshes, slots);
  jobs::ThreadPool pool(3);
  std::mt19937 random(7);
  ecs::Tick transforms_at = 0;

  ecs::Entity pending;
  for (uint32_t frame = 0; frame < 12; ++frame) {
    std::vector<ecs::Entity> all = instances_of(world);
    ASSERT_GT(all.size(), 2000u);
    // Most frames move a few instances and recolor one; some change the instance set.
    ecs::Entity moved;
    for (int m = 0; m < 40; ++m) {
      moved = all[random() % all.size()];
      world.get_mut<ecs::LocalTransform>(moved).translation.x += 0.5f;
    }
    const auto recolor = [&](ecs::Entity entity, int channel) {
      if (world.has<scene::Material>(entity)) {
        world.get_mut<scene::Material>(entity).base_color[channel] = float(frame) / 12.0f;
      }
    };
    recolor(all[random() % all.size()], 0);
    recolor(moved, 1);  // moved and recolored in one frame
    if (frame == 3) scene::add_instance(s, 0, {{1.0f, 2.0f, 3.0f}}, scene::Material{});
    if (frame == 5) world.destroy(all[random() % all.size()]);
    if (frame == 7) world.get_mut<scene::MeshInstance>(all[random() % all.size()]).casts_shadow = false;
    if (frame == 9) world.remove<scene::Material>(all[random() % all.size()]);
    // An instance without transforms is no instance yet; gaining them makes it one.
    if (frame == 9) pending = world.create();
    if (frame == 9) world.add<scene::MeshInstance>(pending, scene::MeshInstance{0, true});
    if (frame == 11) world.add<ecs::LocalTransform>(pending, ecs::LocalTransform{{2.0f, 1.0f, 0.0f}});
    if (frame == 11) world.add<ecs::WorldTransform>(pending);
    ecs::update_world_transforms(world, transforms_at);
    transforms_at = world.tick();
    world.advance_tick();

    const uint32_t slot = frame % slots;
    const std::vector<scene::Aabb> before(kept.instance_bounds().begin(), kept.instance_bounds().end());
    kept.gather(world, &pool);
    kept.upload(slot, &pool);
    GpuScene fresh(context, s.meshes, 1);
    fresh.gather(world);
    fresh.upload(0);

    SCOPED_TRACE("frame " + std::to_string(frame));
    expect_same_boxes(kept.instance_bounds(), fresh.instance_bounds());
    ASSERT_EQ(kept.bounds().min, fresh.bounds().min);
    ASSERT_EQ(kept.bounds().max, fresh.bounds().max);
    ASSERT_TRUE(std::ranges::equal(kept.instance_keys(), fresh.instance_keys()));
    ASSERT_EQ(kept.caster_groups().size(), fresh.caster_groups().size());
    for (size_t g = 0; g < kept.caster_groups().size(); ++g) {
      EXPECT_EQ(kept.caster_groups()[g].firstInstance, fresh.caster_groups()[g].firstInstance);
      EXPECT_EQ(kept.caster_groups()[g].instanceCount, fresh.caster_groups()[g].instanceCount);
    }
    // What moved, and from where: every instance whose box changed is listed, with its old box.
    if (!kept.laid_out_in_last_gather()) {
      ASSERT_EQ(kept.replaced().size(), kept.replaced_bounds_before().size());
      ASSERT_EQ(kept.replaced().size(), kept.replaced_bounds_after().size());
      std::vector<bool> listed(kept.instance_count(), false);
      for (size_t k = 0; k < kept.replaced().size(); ++k) {
        const uint32_t i = kept.replaced()[k];
        EXPECT_FALSE(listed[i]) << "instance " << i << " listed twice";
        listed[i] = true;
        EXPECT_EQ(kept.replaced_bounds_before()[k].min, before[i].min);
        EXPECT_EQ(kept.replaced_bounds_before()[k].max, before[i].max);
        EXPECT_EQ(kept.replaced_bounds_after()[k].min, kept.instance_bounds()[i].min);
        EXPECT_EQ(kept.replaced_bounds_after()[k].max, kept.instance_bounds()[i].max);
      }
      for (uint32_t i = 0; i < kept.instance_count(); ++i) {
        const bool moved = kept.instance_bounds()[i].min != before[i].min;
        EXPECT_TRUE(!moved || listed[i]) << "instance " << i;
      }
    }
    const size_t bytes = size_t{fresh.instance_count()} * sizeof(GpuInstance);
    EXPECT_EQ(std::memcmp(kept.instances(slot).mapped(), fresh.instances(0).mapped(), bytes), 0)
        << "slot " << slot << " holds other instance records than a fresh upload";
  }
}

TEST_F(GpuSceneTest, AFrameWithoutWritesKeepsEveryInstance) {
  TwoBoxes boxes = two_boxes();
  scene::Scene& s = boxes.scene;
  const ecs::Entity moved = boxes.first;
  GpuScene gpu(context, s.meshes, 1);
  gpu.gather(s.world);
  const scene::Aabb before = gpu.instance_bounds()[0];

  s.world.advance_tick();
  gpu.gather(s.world);
  EXPECT_EQ(gpu.instance_bounds()[0].min, before.min);

  const ecs::Tick since = s.world.tick();
  s.world.get_mut<ecs::LocalTransform>(moved).translation.y = 2.0f;
  ecs::update_world_transforms(s.world, since - 1);
  s.world.advance_tick();
  gpu.gather(s.world);
  EXPECT_FLOAT_EQ(gpu.instance_bounds()[0].min.y, before.min.y + 2.0f) << "a move is seen the next frame";
  EXPECT_FLOAT_EQ(gpu.bounds().max.y, before.max.y + 2.0f) << "and grows the scene's bounds";
}

// The scene's bounds follow moves without reading every instance (only the chunks of the moved
// ones): a box moving inside them leaves them as they were; a box that held a face and moves in
// shrinks them, in the first chunk of instances or the last; a box that moved before but not
// this frame still holds its face.
TEST_F(GpuSceneTest, SceneBoundsShrinkWhenABoxThatHeldAFaceMovesIn) {
  scene::Scene s;
  const uint32_t box = scene::add_box_mesh(s.meshes);
  std::vector<ecs::Entity> fillers;  // more instances than one chunk holds, inside the others
  for (int i = 0; i < 5000; ++i) {
    const glm::vec3 at(float(i % 50) * 0.1f - 2.5f, float(i / 50 % 10) * 0.1f, float(i / 500) * 0.1f - 0.5f);
    fillers.push_back(scene::add_instance(s, box, {at}, scene::Material{}));
  }
  const ecs::Entity left = scene::add_instance(s, box, {{-10.0f, 0.0f, 0.0f}}, scene::Material{});
  const ecs::Entity middle = scene::add_instance(s, box, {{0.0f, 0.0f, 0.0f}}, scene::Material{});
  scene::add_instance(s, box, {{10.0f, 0.0f, 0.0f}}, scene::Material{});
  scene::add_instance(s, box, {{0.0f, 10.0f, 0.0f}}, scene::Material{});
  scene::add_instance(s, box, {{0.0f, -10.0f, 5.0f}}, scene::Material{});
  scene::add_instance(s, box, {{0.0f, 0.0f, -5.0f}}, scene::Material{});
  ecs::Tick transforms_at = 0;
  const auto move = [&](ecs::Entity entity, glm::vec3 to) {
    s.world.get_mut<ecs::LocalTransform>(entity).translation = to;
    ecs::update_world_transforms(s.world, transforms_at);
    transforms_at = s.world.tick();
    s.world.advance_tick();
  };
  ecs::update_world_transforms(s.world, transforms_at);
  transforms_at = s.world.tick();
  s.world.advance_tick();
  GpuScene kept(context, s.meshes, 1);
  kept.gather(s.world);
  const scene::Aabb start = kept.bounds();

  const auto expect_fresh_bounds = [&](const char* step) {
    GpuScene fresh(context, s.meshes, 1);
    fresh.gather(s.world);
    EXPECT_EQ(kept.bounds().min, fresh.bounds().min) << step;
    EXPECT_EQ(kept.bounds().max, fresh.bounds().max) << step;
  };
  move(middle, {1.0f, 1.0f, 0.0f});
  kept.gather(s.world);
  EXPECT_FALSE(kept.laid_out_in_last_gather());
  EXPECT_EQ(kept.bounds().min, start.min);
  EXPECT_EQ(kept.bounds().max, start.max);
  expect_fresh_bounds("a move inside");
  move(left, {-3.0f, 0.0f, 0.0f});
  kept.gather(s.world);
  EXPECT_FALSE(kept.laid_out_in_last_gather());
  EXPECT_GT(kept.bounds().min.x, start.min.x + 6.0f);
  expect_fresh_bounds("the box holding the -x face moved in");
  move(middle, {0.0f, 20.0f, 0.0f});
  kept.gather(s.world);
  EXPECT_GT(kept.bounds().max.y, start.max.y + 9.0f);
  expect_fresh_bounds("a move out of the bounds");
  move(left, {-4.0f, 0.0f, 0.0f});
  kept.gather(s.world);
  EXPECT_GT(kept.bounds().max.y, start.max.y + 9.0f);
  expect_fresh_bounds("another moving box moved");
  move(middle, {0.0f, 0.0f, 0.0f});
  move(fillers.front(), {0.0f, 0.0f, 30.0f});
  kept.gather(s.world);
  EXPECT_GT(kept.bounds().max.z, start.max.z + 20.0f);
  expect_fresh_bounds("the first instance out of the bounds");
  move(fillers.front(), {0.0f, 0.0f, 0.0f});
  kept.gather(s.world);
  EXPECT_EQ(kept.bounds().max, start.max);
  expect_fresh_bounds("the first instance back in");
}

// Instances are drawn class by class: a material edit within a class re-places the instance
// alone, one that makes it masked or double-sided lays the instances out again, into that class.
TEST_F(GpuSceneTest, AMaterialThatChangesDrawClassLaysTheInstancesOutAgain) {
  TwoBoxes boxes = two_boxes();
  scene::Scene& s = boxes.scene;
  const ecs::Entity card = boxes.first;
  GpuScene gpu(context, s.meshes, 1);
  gpu.gather(s.world);
  EXPECT_TRUE(gpu.has_draw_class(0));
  EXPECT_FALSE(gpu.has_draw_class(draw_masked));
  const auto edit = [&](auto&& change) {
    change(s.world.get_mut<scene::Material>(card));
    s.world.advance_tick();
    gpu.gather(s.world);
  };
  edit([](scene::Material& m) { m.base_color = glm::vec4(1, 0, 0, 1); });
  EXPECT_FALSE(gpu.laid_out_in_last_gather()) << "a new color stays in its class";
  edit([](scene::Material& m) { m.alpha_mode = scene::AlphaMode::mask; });
  EXPECT_TRUE(gpu.laid_out_in_last_gather());
  EXPECT_TRUE(gpu.has_draw_class(draw_masked));
  edit([](scene::Material& m) { m.double_sided = true; });
  EXPECT_TRUE(gpu.laid_out_in_last_gather());
  EXPECT_TRUE(gpu.has_draw_class(draw_masked | draw_double_sided));
  EXPECT_FALSE(gpu.has_draw_class(draw_masked));
  EXPECT_TRUE(gpu.has_draw_class(0)) << "the other box";
}

// An instance whose bounds change becomes moving, and stays so until the next layout; a material
// edit alone moves nothing.
TEST_F(GpuSceneTest, MovedInstancesAreMovingUntilTheNextLayout) {
  TwoBoxes boxes = two_boxes();
  scene::Scene& s = boxes.scene;
  const ecs::Entity moved = boxes.first;
  const ecs::Entity painted = boxes.second;
  GpuScene gpu(context, s.meshes, 1);
  gpu.gather(s.world);
  EXPECT_TRUE(gpu.moving_instances().empty());
  const auto frame = [&](auto&& edit) {
    const ecs::Tick since = s.world.tick();
    edit();
    ecs::update_world_transforms(s.world, since - 1);
    s.world.advance_tick();
    gpu.gather(s.world);
  };
  const auto instance_of = [&](ecs::Entity entity) {
    const auto keys = gpu.instance_keys();
    return static_cast<uint32_t>(std::find(keys.begin(), keys.end(), ecs::entity_key(entity)) - keys.begin());
  };
  frame([&] { s.world.get_mut<scene::Material>(painted).base_color = glm::vec4(1, 0, 0, 1); });
  EXPECT_TRUE(gpu.moving_instances().empty()) << "a new color moves nothing";
  frame([&] { s.world.get_mut<ecs::LocalTransform>(moved).translation.y = 2.0f; });
  const uint32_t m = instance_of(moved);
  EXPECT_TRUE(gpu.moving(m));
  EXPECT_TRUE(gpu.first_moved_in_last_gather(m));
  EXPECT_FALSE(gpu.moving(instance_of(painted)));
  frame([&] { s.world.get_mut<ecs::LocalTransform>(moved).translation.y = 3.0f; });
  EXPECT_TRUE(gpu.moving(m));
  EXPECT_FALSE(gpu.first_moved_in_last_gather(m)) << "it was moving already";
  EXPECT_EQ(std::vector<uint32_t>(gpu.moving_instances().begin(), gpu.moving_instances().end()),
            std::vector<uint32_t>{m});

  frame([&] { scene::add_instance(s, boxes.box, {{8.0f, 0.0f, 0.0f}}, scene::Material{}); });
  ASSERT_TRUE(gpu.laid_out_in_last_gather());
  EXPECT_TRUE(gpu.moving_instances().empty()) << "a new layout makes every instance still";
  EXPECT_FALSE(gpu.moving(instance_of(moved)));
}

}  // namespace
}  // namespace sg::test
