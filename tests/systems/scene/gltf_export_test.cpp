// SPDX-License-Identifier: MIT
// glTF export: a scene written and loaded back has the same lights, shadow settings, drawables,
// materials and view (the rendered round trip is tests/sandbox's export test).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/camera.h"
#include "systems/scene/gltf_export.h"
#include "systems/scene/gltf_import.h"
#include "systems/scene/lights.h"
#include "systems/scene/material.h"
#include "systems/scene/mesh_instance.h"
#include "systems/scene/scene_queries.h"
#include "systems/scene/shadow_settings.h"
#include "tests/support/gltf_writer.h"

namespace sg::scene {
namespace {

using test::TempDir;

// Every light by name: its world position and the settings that shape its picture.
struct LightFacts {
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f};
  float intensity = 0.0f;
  float size = 0.0f;  // range, or a cylinder's outer radius
  int falloff = -1;
  ShadowSettings shadow;
};

std::map<std::string, LightFacts> lights_of(const Scene& scene) {
  std::map<std::string, LightFacts> lights;
  scene.world.query<const ShadowSettings, const ecs::WorldTransform>().for_each(
      [&](ecs::Entity entity, const ShadowSettings& shadow, const ecs::WorldTransform& world) {
        LightFacts facts{light_position(world), light_direction(world), 0.0f, 0.0f, -1, shadow};
        if (const auto* point = scene.world.try_get<PointLight>(entity)) {
          facts.intensity = point->intensity;
          facts.size = point->range;
          facts.falloff = int(point->falloff);
        } else if (const auto* spot = scene.world.try_get<SpotLight>(entity)) {
          facts.intensity = spot->intensity;
          facts.size = spot->outer_cone * 1000.0f + spot->range;
          facts.falloff = int(spot->falloff);
        } else if (const auto* sun = scene.world.try_get<DirectionalLight>(entity)) {
          facts.intensity = sun->intensity;
        } else if (const auto* beam = scene.world.try_get<CylinderLight>(entity)) {
          facts.intensity = beam->intensity;
          facts.size = beam->outer_radius * 1000.0f + beam->inner_radius;
        }
        lights[scene.world.get<Name>(entity).value] = facts;
      });
  return lights;
}

void expect_near(const glm::vec3& a, const glm::vec3& b, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, 1e-4f) << what;
  EXPECT_NEAR(a.y, b.y, 1e-4f) << what;
  EXPECT_NEAR(a.z, b.z, 1e-4f) << what;
}

TEST(GltfExport, TheDefaultSceneComesBackWithItsLightsDrawablesAndView) {
  TempDir dir;
  Scene scene = build_scene("default");
  // Edits as the panels make them: a light's shadow settings, a drawable that casts no shadow.
  ecs::Entity spot = ecs::null_entity;
  scene.world.query<const SpotLight>().for_each([&](ecs::Entity e, const SpotLight&) { spot = e; });
  ASSERT_NE(spot, ecs::null_entity);
  ShadowSettings& edited = scene.world.get_mut<ShadowSettings>(spot);
  edited.algorithm = ShadowAlgorithm::pcss_noise;
  edited.light_size = 0.7f;
  edited.shadow_color = {0.2f, 0.1f, 0.0f};
  edited.caster_mask = 0x0C;
  edited.contact_length = 0.4f;
  edited.kernel = {2, 6, 20, 8};
  edited.light_mask = 0x03;
  ecs::Entity drawable = ecs::null_entity;
  scene.world.query<const MeshInstance>().for_each([&](ecs::Entity e, const MeshInstance&) { drawable = e; });
  scene.world.get_mut<MeshInstance>(drawable).casts_shadow = false;
  scene.world.get_mut<MeshInstance>(drawable).receives_shadow = false;
  scene.world.get_mut<MeshInstance>(drawable).light_layers = 0x06;
  scene.world.get_mut<MeshInstance>(drawable).shadow_layers = 0x08;
  const ExportView view{{{1, 5, 6}, {0, 1, 0}, {0, 1, 0}}, Camera{0.9f, 0.1f, 80.0f, 0.0f}};

  for (const char* file : {"default.gltf", "default.glb"}) {
    const ExportReport report = export_gltf(scene, view, dir.path(file).string());
    EXPECT_EQ(report.lights, 6u);
    Scene loaded = load_gltf(dir.path(file).string());
    EXPECT_TRUE(loaded.warnings.empty())
        << file << ": " << (loaded.warnings.empty() ? "" : loaded.warnings[0]);

    const SceneStats before = scene_stats(scene);
    const SceneStats after = scene_stats(loaded);
    EXPECT_EQ(after.mesh_instances, before.mesh_instances) << file;
    EXPECT_EQ(after.triangles, before.triangles) << file;
    EXPECT_EQ(after.point_lights, before.point_lights) << file;
    EXPECT_EQ(after.spot_lights, before.spot_lights) << file;
    EXPECT_EQ(after.directional_lights, before.directional_lights) << file;
    EXPECT_EQ(after.cylinder_lights, before.cylinder_lights) << file;

    const auto original = lights_of(scene);
    const auto back = lights_of(loaded);
    ASSERT_EQ(back.size(), original.size()) << file;
    for (const auto& [name, facts] : original) {
      ASSERT_TRUE(back.contains(name)) << file << ": " << name;
      const LightFacts& other = back.at(name);
      expect_near(other.position, facts.position, std::string(file) + ": " + name);
      expect_near(other.direction, facts.direction, std::string(file) + ": " + name);
      EXPECT_FLOAT_EQ(other.intensity, facts.intensity) << file << ": " << name;
      EXPECT_FLOAT_EQ(other.size, facts.size) << file << ": " << name;
      EXPECT_EQ(other.falloff, facts.falloff) << file << ": " << name;
      EXPECT_EQ(other.shadow.algorithm, facts.shadow.algorithm) << file << ": " << name;
      EXPECT_FLOAT_EQ(other.shadow.light_size, facts.shadow.light_size) << file << ": " << name;
      EXPECT_EQ(other.shadow.shadow_color, facts.shadow.shadow_color) << file << ": " << name;
      EXPECT_EQ(other.shadow.resolution, facts.shadow.resolution) << file << ": " << name;
      EXPECT_EQ(other.shadow.caster_mask, facts.shadow.caster_mask) << file << ": " << name;
      EXPECT_FLOAT_EQ(other.shadow.contact_length, facts.shadow.contact_length) << file << ": " << name;
      EXPECT_EQ(other.shadow.kernel, facts.shadow.kernel) << file << ": " << name;
      EXPECT_EQ(other.shadow.light_mask, facts.shadow.light_mask) << file << ": " << name;
    }

    int not_casting = 0, not_receiving = 0, layered = 0;
    std::multiset<std::pair<float, float>> terms_before, terms_after;
    scene.world.query<const Material>().for_each(
        [&](ecs::Entity, const Material& m) { terms_before.emplace(m.specular, m.shininess); });
    loaded.world.query<const Material>().for_each(
        [&](ecs::Entity, const Material& m) { terms_after.emplace(m.specular, m.shininess); });
    loaded.world.query<const MeshInstance>().for_each([&](ecs::Entity, const MeshInstance& instance) {
      not_casting += instance.casts_shadow ? 0 : 1;
      not_receiving += instance.receives_shadow ? 0 : 1;
      layered += instance.light_layers == 0x06 && instance.shadow_layers == 0x08;
    });
    EXPECT_EQ(layered, 1) << file;
    EXPECT_EQ(not_casting, 1) << file;
    EXPECT_EQ(not_receiving, 1) << file;
    EXPECT_EQ(terms_after, terms_before) << file << ": specular and shininess";
    const auto camera = first_camera(loaded);
    ASSERT_TRUE(camera.has_value()) << file;
    const CameraPose pose = camera_pose(loaded.world.get<ecs::WorldTransform>(*camera));
    expect_near(pose.eye, view.pose.eye, std::string(file) + ": view eye");
    const glm::vec3 forward = glm::normalize(pose.target - pose.eye);
    expect_near(forward, glm::normalize(view.pose.target - view.pose.eye),
                std::string(file) + ": view direction");
    EXPECT_FLOAT_EQ(loaded.world.get<Camera>(*camera).yfov, 0.9f) << file;
  }
}

// A material's texture goes out as a PNG image and comes back pixel for pixel.
TEST(GltfExport, TexturesComeBackPixelForPixel) {
  TempDir dir;
  Scene scene = build_scene("default");
  Texture checker{"checker", 4, 2, {}};
  for (int i = 0; i < 8; ++i) {
    const std::uint8_t value = i % 2 ? 230 : 20;
    checker.pixels.insert(checker.pixels.end(), {value, std::uint8_t(255 - value), 128, 255});
  }
  scene.textures.textures.push_back(checker);
  scene.world.query<Material>().for_each(
      [&](ecs::Entity, Material& material) { material.base_color_texture = 0; });
  export_gltf(scene, std::nullopt, dir.path("textured.glb").string());
  const Scene loaded = load_gltf(dir.path("textured.glb").string());
  ASSERT_EQ(loaded.textures.textures.size(), 1u);
  const Texture& back = loaded.textures.textures[0];
  EXPECT_EQ(back.width, 4u);
  EXPECT_EQ(back.height, 2u);
  EXPECT_EQ(back.pixels, checker.pixels);
  int textured = 0;
  loaded.world.query<const Material>().for_each(
      [&](ecs::Entity, const Material& material) { textured += material.base_color_texture == 0 ? 1 : 0; });
  EXPECT_EQ(textured, int(scene_stats(loaded).mesh_instances));
}

}  // namespace
}  // namespace sg::scene
