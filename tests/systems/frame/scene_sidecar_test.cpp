// SPDX-License-Identifier: MIT
// The lights and camera saved beside a scene, and applied to it again.
#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "shadowgraph/version.h"

#include "ecs/query.h"
#include "ecs/transform.h"
#include "systems/frame/scene_sidecar.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/scene_queries.h"
#include "systems/scene/shadow_settings.h"
#include "tests/support/gltf_writer.h"

namespace sg::test {
namespace {

ecs::Entity named(const scene::Scene& scene, const std::string& name) {
  ecs::Entity found = ecs::null_entity;
  scene.world.query<const scene::Name, const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const scene::Name& n, const scene::ShadowSettings&) {
        if (n.value == name) found = entity;
      });
  return found;
}

TEST(SceneSidecar, EditedLightsAndCameraComeBack) {
  scene::test::TempDir dir;
  const std::filesystem::path path = dir.path("default.shadowgraph.json");
  {
    scene::Scene edited = scene::build_scene("default");
    const ecs::Entity spot = named(edited, "spot east");
    ASSERT_NE(spot, ecs::null_entity);
    edited.world.get_mut<scene::ShadowSettings>(spot).algorithm = scene::ShadowAlgorithm::hard;
    edited.world.get_mut<ecs::LocalTransform>(spot).translation = {3, 3, 1};
    edited.world.get_mut<scene::SpotLight>(spot).outer_cone = 0.5f;
    edited.world.destroy(named(edited, "beam"));
    edited.world.get_mut<scene::ShadowSettings>(named(edited, "sun")).cascades = 2;
    edited.world.get_mut<scene::ShadowSettings>(spot).update = scene::ShadowUpdate::every_frame;
    edited.world.get_mut<scene::ShadowSettings>(spot).priority = 2.5f;
    edited.world.get_mut<scene::ShadowSettings>(spot).caster_mask = 0x81;
    edited.world.get_mut<scene::ShadowSettings>(spot).light_mask = 0;
    edited.world.get_mut<scene::ShadowSettings>(spot).contact_length = 0.25f;
    edited.world.get_mut<scene::ShadowSettings>(spot).kernel = {3, 2, 9, 4};
    scene::add_light(edited, scene::PointLight{glm::vec3(1, 0, 0), 2.0f, 4.0f},
                     ecs::LocalTransform{{1, 2, 3}}, {}, "added");
    save_sidecar(path, edited, {{1, 5, 6}, {0, 0, 0}, {0, 1, 0}});
  }
  scene::Scene fresh = scene::build_scene("default");
  scene::CameraPose pose;
  apply_sidecar(path, fresh, pose);
  EXPECT_EQ(pose.eye, glm::vec3(1, 5, 6));
  const ecs::Entity spot = named(fresh, "spot east");
  ASSERT_NE(spot, ecs::null_entity);
  EXPECT_EQ(fresh.world.get<scene::ShadowSettings>(spot).algorithm, scene::ShadowAlgorithm::hard);
  EXPECT_EQ(fresh.world.get<ecs::LocalTransform>(spot).translation, glm::vec3(3, 3, 1));
  EXPECT_FLOAT_EQ(fresh.world.get<scene::SpotLight>(spot).outer_cone, 0.5f);
  EXPECT_EQ(fresh.world.get<scene::ShadowSettings>(spot).update, scene::ShadowUpdate::every_frame);
  EXPECT_FLOAT_EQ(fresh.world.get<scene::ShadowSettings>(spot).priority, 2.5f);
  EXPECT_EQ(fresh.world.get<scene::ShadowSettings>(spot).caster_mask, 0x81);
  EXPECT_EQ(fresh.world.get<scene::ShadowSettings>(spot).light_mask, 0);
  EXPECT_FLOAT_EQ(fresh.world.get<scene::ShadowSettings>(spot).contact_length, 0.25f);
  EXPECT_EQ(fresh.world.get<scene::ShadowSettings>(spot).kernel, (scene::ShadowKernel{3, 2, 9, 4}));
  EXPECT_EQ(named(fresh, "beam"), ecs::null_entity);
  EXPECT_EQ(fresh.world.get<scene::ShadowSettings>(named(fresh, "sun")).cascades, 2u);
  const ecs::Entity added = named(fresh, "added");
  ASSERT_NE(added, ecs::null_entity);
  EXPECT_FLOAT_EQ(fresh.world.get<scene::PointLight>(added).range, 4.0f);
  EXPECT_EQ(scene::scene_stats(fresh).cylinder_lights, 0u);
}

TEST(SceneSidecar, MalformedFilesAreRefusedLeavingTheSceneAsItWas) {
  scene::test::TempDir dir;
  const auto refusal = [&](const std::string& text) {
    const std::filesystem::path path = dir.path("bad.json");
    std::ofstream(path) << text;
    scene::Scene scene = scene::build_scene("default");
    scene::CameraPose pose;
    const scene::SceneStats before = scene::scene_stats(scene);
    try {
      apply_sidecar(path, scene, pose);
    } catch (const std::runtime_error& error) {
      EXPECT_EQ(scene::scene_stats(scene).shadow_casting_lights, before.shadow_casting_lights);
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal("{ not json").find("bad.json: not JSON"), std::string::npos);
  EXPECT_NE(
      refusal(R"({"lights": [{"name": "x", "type": "torch"}]})").find("bad.json: lights[0].type: is not"),
      std::string::npos);
  // A light's bad value, and the entry the message names.
  const std::pair<const char*, const char*> bad_lights[] = {
      {R"({"name": "x", "type": "spot", "range": -1})", "lights[0].range"},
      {R"({"name": "x", "type": "point", "shadow": {"algorithm": "soft"}})", "lights[0].shadow.algorithm"},
      {R"({"name": "x", "type": "directional", "shadow": {"cascades": 5}})",
       "lights[0].shadow.cascades: is not within 1 .. 4"},
      {R"({"name": "x", "type": "point", "shadow": {"update": "often"}})",
       "lights[0].shadow.update: is not one of auto, every_frame, on_demand"},
      {R"({"name": "x", "type": "point", "shadow": {"priority": -5}})",
       "lights[0].shadow.priority: is not within -4 .. 4"},
      {R"({"name": "x", "type": "spot", "shadow": {"caster_mask": 1.5}})",
       "lights[0].shadow.caster_mask: is not a layer mask (an integer from 0 to 255)"},
      {R"({"name": "x", "type": "spot", "shadow": {"light_mask": -1}})",
       "lights[0].shadow.light_mask: is not"},
      {R"({"name": "x", "type": "spot", "shadow": {"noise_taps": 6}})",
       "lights[0].shadow.noise_taps: is not 4, 8 or 16"},
      {R"({"name": "x", "type": "spot", "shadow": {"pcf_half_width": 4}})",
       "lights[0].shadow.pcf_half_width: is not a whole number from 1 to 3"},
      {R"({"name": "x", "type": "spot", "shadow": {"contact_length": 11}})",
       "lights[0].shadow.contact_length: is not within 0 .. 10"},
  };
  for (const auto& [light, message] : bad_lights) {
    EXPECT_NE(refusal(std::string(R"({"lights": [)") + light + "]}").find(message), std::string::npos)
        << light;
  }
  EXPECT_NE(refusal(R"({"camera": {"eye": [1, 1, 1], "target": [1, 1, 1]}})").find("camera"),
            std::string::npos);
  // A file of a newer form than this engine reads is refused by name, not misread.
  const std::string newer = "{\"schema_version\": " + std::to_string(sidecar_schema_version + 1) + "}";
  EXPECT_NE(refusal(newer).find("schema_version: is " + std::to_string(sidecar_schema_version + 1) +
                                ": written by a newer Shadowgraph"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"schema_version": "one"})").find("schema_version: is not a whole number"),
            std::string::npos);
}

// A saved sidecar says its form and its writer; one without schema_version is read as the first.
TEST(SceneSidecar, SavedFilesSayTheirSchemaVersion) {
  scene::test::TempDir dir;
  const std::filesystem::path path = dir.path("default.shadowgraph.json");
  save_sidecar(path, scene::build_scene("default"), {{1, 5, 6}, {0, 0, 0}, {0, 1, 0}});
  nlohmann::json document = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(document.at("schema_version"), sidecar_schema_version);
  EXPECT_EQ(document.at("generator"), "Shadowgraph " SHADOWGRAPH_VERSION);
  document.erase("schema_version");
  std::ofstream(path) << document.dump();
  scene::Scene scene = scene::build_scene("default");
  scene::CameraPose pose;
  apply_sidecar(path, scene, pose);
  EXPECT_EQ(pose.eye, glm::vec3(1, 5, 6));
}

}  // namespace
}  // namespace sg::test
