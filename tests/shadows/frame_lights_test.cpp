// Gathering a frame's lights from the ECS world and placing their maps, without a GPU.
#include <gtest/gtest.h>

#include "ecs/transform_system.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_builder.h"
#include "systems/shadows/frame_lights.h"

namespace sg::shadows {
namespace {

scene::ShadowSettings shadow_at(uint32_t resolution, bool casts = true) {
  scene::ShadowSettings shadow;
  shadow.resolution = resolution;
  shadow.casts_shadow = casts;
  return shadow;
}

const ecs::LocalTransform above{glm::vec3(0.0f, 5.0f, 0.0f)};
const scene::Aabb bounds{glm::vec3(-10.0f), glm::vec3(10.0f)};

// Two spot lights (one without a shadow), a directional light and two point lights.
scene::Scene five_lights() {
  scene::Scene scene;
  scene::add_light(scene, scene::SpotLight{}, above, shadow_at(512), "key");
  scene::add_light(scene, scene::SpotLight{}, above, shadow_at(512, false), "fill");
  scene::add_light(scene, scene::DirectionalLight{}, above, shadow_at(100'000), "");
  scene::add_light(scene, scene::PointLight{}, above, shadow_at(3), "bulb");
  scene::add_light(scene, scene::PointLight{}, above, shadow_at(256), "lamp");
  ecs::update_world_transforms(scene.world, 0);
  return scene;
}

TEST(FrameLights, EveryLightGetsARecordAndShadowCastersGetViews) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);  // a const World is enough

  EXPECT_EQ(lights.records.size(), 5u);
  ASSERT_EQ(lights.maps.size(), 2u);  // "fill" casts none
  ASSERT_EQ(lights.cubes.size(), 2u);
  EXPECT_EQ(lights.maps[0].name, "shadow key");
  EXPECT_EQ(lights.maps[1].name, "shadow directional 1");  // unnamed: kind and map index
  EXPECT_EQ(lights.maps[0].layer, 0u);
  EXPECT_EQ(lights.maps[1].layer, 1u);
  EXPECT_EQ(lights.cubes[1].cube, 1u);
  // Each view points at its own record, of its own type.
  EXPECT_EQ(lights.records[lights.maps[1].light].info.x, uint32_t(GpuLightType::directional));
  EXPECT_EQ(lights.records[lights.cubes[0].light].info.x, uint32_t(GpuLightType::point));
  // Views carry the reach casters are culled against: the spot's sphere, none for the sun.
  EXPECT_GT(lights.maps[0].reach.w, 0.0f);
  EXPECT_LT(lights.maps[1].reach.w, 0.0f);
}

TEST(FrameLights, ResolutionsAreClampedAndTheStorageFitsTheLargest) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);

  EXPECT_EQ(lights.maps[0].resolution, 512u);
  EXPECT_EQ(lights.maps[1].resolution, max_map_resolution);
  EXPECT_EQ(lights.cubes[0].requested_resolution, min_shadow_resolution);
  EXPECT_EQ(lights.map_size, max_map_resolution);
  EXPECT_EQ(lights.cube_size, 256u);
  const ShadowStorageSize needed = needed_storage(lights);
  EXPECT_EQ(needed.maps, (ShadowArraySize{max_map_resolution, 2}));
  EXPECT_EQ(needed.cubes, (ShadowArraySize{256, 2}));
}

TEST(FrameLights, OverridesApplyToEveryLight) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {scene::ShadowAlgorithm::pcss, true}, lights);
  for (const GpuLight& record : lights.records) {
    EXPECT_EQ(record.info.z, uint32_t(scene::ShadowAlgorithm::pcss));
  }

  gather_lights(scene.world, bounds, {std::nullopt, false}, lights);  // reuses the storage
  EXPECT_EQ(lights.records.size(), 5u);
  EXPECT_TRUE(lights.maps.empty());
  EXPECT_TRUE(lights.cubes.empty());
  EXPECT_EQ(needed_storage(lights).maps.count, 0u);
}

TEST(FrameLights, PlacingMapsGivesEachRecordItsRegionOfTheStorage) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  for (const GpuLight& record : lights.records) EXPECT_EQ(record.info.w, no_shadow_map);

  place_shadow_maps(lights, 2048, 512);
  const GpuLight& key = lights.records[lights.maps[0].light];
  EXPECT_EQ(key.info.w, 0u);
  EXPECT_FLOAT_EQ(key.shadow_rect.z, 512.0f / 2048.0f);  // its 512 texels of a 2048 layer
  EXPECT_FLOAT_EQ(key.shadow_rect.w, 512.0f / 2048.0f);
  EXPECT_EQ(lights.records[lights.maps[1].light].info.w, 1u);
  EXPECT_EQ(lights.records[lights.cubes[1].light].info.w, 1u);
  EXPECT_EQ(lights.records[0].info.w, no_shadow_map);  // "fill" (unshadowed: group 0) has none
}

TEST(FrameLights, RecordsAreOrderedByLightGroup) {
  const scene::Scene scene = five_lights();
  FrameLights lights;
  gather_lights(scene.world, bounds, {}, lights);
  // Every light here uses pcf: "fill" is unshadowed, key and the sun have 2D maps, two cubes.
  const uint32_t map_pcf = light_group(ShadowKind::map, scene::ShadowAlgorithm::pcf);
  const uint32_t cube_pcf = light_group(ShadowKind::cube, scene::ShadowAlgorithm::pcf);
  EXPECT_EQ(lights.group_begin[0], 0u);
  EXPECT_EQ(lights.group_begin[1], 1u);  // one unshadowed light
  EXPECT_EQ(lights.group_begin[map_pcf + 1] - lights.group_begin[map_pcf], 2u);
  EXPECT_EQ(lights.group_begin[cube_pcf + 1] - lights.group_begin[cube_pcf], 2u);
  EXPECT_EQ(lights.group_begin[light_group_count], 5u);
  for (const ShadowMapView& map : lights.maps) {
    EXPECT_GE(map.light, lights.group_begin[map_pcf]);
    EXPECT_LT(map.light, lights.group_begin[map_pcf + 1]);
  }
  for (const ShadowCubeView& cube : lights.cubes) {
    EXPECT_EQ(lights.records[cube.light].info.x, uint32_t(GpuLightType::point));
    EXPECT_GE(cube.light, lights.group_begin[cube_pcf]);
  }
  // Groups number the same on both sides of the shader boundary.
  for (uint32_t group = 0; group < light_group_count; ++group) {
    if (group_shadow_kind(group) == ShadowKind::none) continue;
    EXPECT_EQ(light_group(group_shadow_kind(group), group_algorithm(group)), group);
  }
}

}  // namespace
}  // namespace sg::shadows
