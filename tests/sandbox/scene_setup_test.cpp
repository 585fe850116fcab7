// Which scene the sandbox loads and which view it starts from.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sandbox/scene_setup.h"
#include "systems/scene/scene_error.h"
#include "systems/scene/scene_queries.h"
#include "tests/scene/gltf_writer.h"

namespace sg::sandbox {
namespace {

using scene::test::GltfWriter;
using scene::test::TempDir;

void expect_near(const glm::vec3& actual, const glm::vec3& expected) {
  EXPECT_LT(glm::length(actual - expected), 1e-5f)
      << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", "
      << expected.y << ", " << expected.z << ")";
}

// One triangle at the origin, and optionally a perspective camera node at (1, 2, 3) turned
// 90 degrees about +Y, so it looks down world -X.
std::string write_scene(const TempDir& dir, bool with_camera, const char* camera_name = nullptr) {
  GltfWriter file;
  const int mesh = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  file.add_node({{"mesh", mesh}});
  if (with_camera) {
    file.document["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 50}}}}};
    const float half = std::sqrt(0.5f);
    nlohmann::json node = {{"camera", 0}, {"translation", {1, 2, 3}}, {"rotation", {0, half, 0, half}}};
    if (camera_name) node["name"] = camera_name;
    file.add_node(node);
  }
  return file.write_gltf(dir, with_camera ? "with_camera" : "no_camera").string();
}

TEST(SandboxScene, UsesTheGltfCamera) {
  TempDir dir;
  Options options;
  options.scene = write_scene(dir, true, "Overview");
  const SandboxScene loaded = load_sandbox_scene(options, 16.0f / 9.0f);
  EXPECT_EQ(loaded.camera_source, "glTF camera 'Overview'");
  expect_near(loaded.pose.eye, {1, 2, 3});
  expect_near(loaded.pose.target, {0, 2, 3});
  EXPECT_FLOAT_EQ(loaded.lens.yfov, 0.7f);
  EXPECT_FLOAT_EQ(loaded.lens.zfar, 50.0f);
  EXPECT_EQ(loaded.scene.name, options.scene);
}

TEST(SandboxScene, AFileWithoutLightsGetsTheSandboxSun) {
  TempDir dir;
  Options options;
  options.scene = write_scene(dir, false);
  SandboxScene loaded = load_sandbox_scene(options, 1.0f);
  const scene::SceneStats stats = scene::scene_stats(loaded.scene);
  EXPECT_EQ(stats.directional_lights, 1u);
  EXPECT_EQ(stats.shadow_casting_lights, 1u);
  ASSERT_FALSE(loaded.scene.warnings.empty());
  EXPECT_NE(loaded.scene.warnings.back().find("no lights"), std::string::npos);

  // The built-in scenes bring their own lights and get none added.
  options.scene = "default";
  SandboxScene builtin = load_sandbox_scene(options, 1.0f);
  EXPECT_EQ(scene::scene_stats(builtin.scene).directional_lights, 1u);
}

TEST(SandboxScene, UnnamedGltfCamera) {
  TempDir dir;
  Options options;
  options.scene = write_scene(dir, true);
  EXPECT_EQ(load_sandbox_scene(options, 1.0f).camera_source, "glTF camera");
}

TEST(SandboxScene, CommandLineCameraWinsAndKeepsTheSceneLens) {
  TempDir dir;
  Options options;
  options.scene = write_scene(dir, true, "Overview");
  options.camera = scene::CameraPose{{5, 6, 7}, {0, 1, 0}};
  const SandboxScene loaded = load_sandbox_scene(options, 1.0f);
  EXPECT_EQ(loaded.camera_source, "--camera");
  EXPECT_EQ(loaded.pose.eye, glm::vec3(5, 6, 7));
  EXPECT_EQ(loaded.pose.target, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(loaded.lens.yfov, 0.7f);
}

TEST(SandboxScene, FramesTheBoundsWithoutACamera) {
  TempDir dir;
  Options options;
  options.scene = write_scene(dir, false);
  const float aspect = 2.0f;
  SandboxScene loaded = load_sandbox_scene(options, aspect);
  EXPECT_EQ(loaded.camera_source, "framed bounds");
  EXPECT_FLOAT_EQ(loaded.lens.yfov, scene::Camera{}.yfov);
  expect_near(loaded.pose.target, {0.5f, 0.5f, 0.0f});  // the triangle's box centre
  const scene::CameraPose expected =
      scene::frame_bounds(scene::scene_bounds(loaded.scene), scene::Camera{}.yfov, aspect);
  expect_near(loaded.pose.eye, expected.eye);
}

TEST(SandboxScene, BuiltinSceneBringsItsCamera) {
  Options options;  // --scene default
  const SandboxScene loaded = load_sandbox_scene(options, 1.0f);
  EXPECT_EQ(loaded.scene.name, "default");
  EXPECT_EQ(loaded.camera_source, "built-in camera");
  expect_near(loaded.pose.eye, {0, 5, 9});  // default_scene.cpp's camera
}

TEST(SandboxScene, StressParametersReachTheScene) {
  Options options;
  options.scene = "stress";
  options.scene_params.triangles = 2000;
  options.scene_params.point_lights = 3;
  options.scene_params.spot_lights = 2;
  SandboxScene loaded = load_sandbox_scene(options, 1.0f);
  const scene::SceneStats stats = scene::scene_stats(loaded.scene);
  EXPECT_EQ(stats.point_lights, 3u);
  EXPECT_EQ(stats.spot_lights, 2u);
  EXPECT_GE(stats.triangles, 2000u);
}

TEST(SandboxScene, LoadErrorsPropagate) {
  Options options;
  options.scene = "/no/such/dir/missing.gltf";
  try {
    load_sandbox_scene(options, 1.0f);
    ADD_FAILURE() << "loaded a missing file";
  } catch (const scene::SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.gltf"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sg::sandbox
