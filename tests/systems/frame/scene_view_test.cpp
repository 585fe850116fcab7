// SPDX-License-Identifier: MIT
// Which scene the sandbox loads and which view it starts from.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "systems/frame/scene_view.h"
#include "systems/gpu/camera.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene_error.h"
#include "systems/scene/scene_queries.h"
#include "tests/support/gltf_writer.h"

namespace sg::test {
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

TEST(SceneView, UsesTheGltfCamera) {
  TempDir dir;
  FrameSettings options;
  options.scene = write_scene(dir, true, "Overview");
  const SceneView loaded = load_scene_view(options, 16.0f / 9.0f);
  EXPECT_EQ(loaded.camera_source, "glTF camera 'Overview'");
  expect_near(loaded.pose.eye, {1, 2, 3});
  expect_near(loaded.pose.target, {0, 2, 3});
  EXPECT_FLOAT_EQ(loaded.lens.yfov, 0.7f);
  EXPECT_FLOAT_EQ(loaded.lens.zfar, 50.0f);
  EXPECT_EQ(loaded.scene.name, options.scene);
}

// --camera NAME picks one of the scene's cameras: a glTF camera by its node's name, or the stress
// scene's street camera at eye height among the lights; an unknown name lists the known ones.
TEST(SceneView, CamerasAreChosenByName) {
  TempDir dir;
  FrameSettings options;
  options.scene = write_scene(dir, true, "Overview");
  options.camera_name = "Overview";
  const SceneView named = load_scene_view(options, 16.0f / 9.0f);
  EXPECT_EQ(named.camera_source, "--camera Overview");
  expect_near(named.pose.eye, {1, 2, 3});
  EXPECT_FLOAT_EQ(named.lens.yfov, 0.7f);

  FrameSettings stress;
  stress.scene = "stress";
  stress.scene_params.triangles = 20'000;
  stress.camera_name = "street";
  const SceneView street = load_scene_view(stress, 16.0f / 9.0f);
  EXPECT_FLOAT_EQ(street.pose.eye.y, 1.7f);
  const glm::vec3 along = glm::normalize(street.pose.target - street.pose.eye);
  EXPECT_GT(along.z, 0.99f) << "it looks along the hall, nearly level";
  stress.camera_name = "overview";
  EXPECT_EQ(load_scene_view(stress, 16.0f / 9.0f).camera_source, "--camera overview");

  stress.camera_name = "balcony";
  try {
    load_scene_view(stress, 16.0f / 9.0f);
    FAIL() << "an unknown camera name was accepted";
  } catch (const scene::SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("overview, street"), std::string::npos) << error.what();
  }
}

// A scene whose camera node has rotation `rotation` (x, y, z, w) at (0, 5, 0).
std::string write_scene_with_camera_rotation(const TempDir& dir, const glm::quat& rotation,
                                             const char* name) {
  GltfWriter file;
  const int mesh = file.add_mesh({{"POSITION", file.add_triangle_positions()}});
  file.add_node({{"mesh", mesh}});
  file.document["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 50}}}}};
  file.add_node({{"camera", 0},
                 {"translation", {0, 5, 0}},
                 {"rotation", {rotation.x, rotation.y, rotation.z, rotation.w}}});
  return file.write_gltf(dir, name).string();
}

// The sandbox's view matrix of `loaded` sends points where the camera node's own frame puts
// them: the inverse of its world transform (glTF cameras look down -Z, +Y up, roll included).
void expect_view_of_camera_node(const SceneView& loaded) {
  const std::optional<ecs::Entity> camera = scene::first_camera(loaded.scene);
  ASSERT_TRUE(camera.has_value());
  const glm::mat4 node = loaded.scene.world.get<ecs::WorldTransform>(*camera).matrix;
  const glm::mat4 expected = glm::inverse(node);
  const glm::mat4 view = view_matrix(loaded.pose);
  for (const glm::vec3 point :
       {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 2), glm::vec3(-1, 3, 1)}) {
    expect_near(glm::vec3(view * glm::vec4(point, 1.0f)), glm::vec3(expected * glm::vec4(point, 1.0f)));
  }
}

TEST(SceneView, ARolledGltfCameraKeepsItsRoll) {
  TempDir dir;
  FrameSettings options;
  // Looking down -Z, rolled 90 degrees: the picture's top is world -X.
  options.scene = write_scene_with_camera_rotation(
      dir, glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1)), "rolled");
  const SceneView loaded = load_scene_view(options, 1.0f);
  expect_near(loaded.pose.up, {-1, 0, 0});
  expect_view_of_camera_node(loaded);
}

TEST(SceneView, AGltfCameraLookingStraightDownIsNotTurned) {
  TempDir dir;
  FrameSettings options;
  // Pitched down 90 degrees: looking down world -Y, the picture's top towards world -Z.
  options.scene =
      write_scene_with_camera_rotation(dir, glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0)), "down");
  const SceneView loaded = load_scene_view(options, 1.0f);
  expect_near(glm::normalize(loaded.pose.target - loaded.pose.eye), {0, -1, 0});
  expect_near(loaded.pose.up, {0, 0, -1});
  expect_view_of_camera_node(loaded);
}

// --camera looking straight down has no +Y to roll around: the view picks another up and still
// sees what lies below, instead of a degenerate matrix and a blank picture.
TEST(SceneView, ACommandLineCameraLookingStraightDownSeesTheGround) {
  const scene::CameraPose pose = scene::parse_camera("0,12,0,0,0,0");
  const glm::mat4 clip = projection_matrix(scene::Camera{}, 1.0f) * view_matrix(pose);
  const glm::vec4 below = clip * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  ASSERT_GT(below.w, 0.0f);
  expect_near(glm::vec3(below) / below.w, {0.0f, 0.0f, glm::vec3(below).z / below.w});  // the centre
  const glm::vec4 aside = clip * glm::vec4(2.0f, 0.0f, 1.0f, 1.0f);
  EXPECT_TRUE(std::isfinite(aside.x / aside.w) && std::isfinite(aside.y / aside.w));
  EXPECT_LT(std::abs(aside.x / aside.w), 1.0f);  // two metres aside, 12 below: in the picture
}

TEST(SceneView, AFileWithoutLightsGetsTheSandboxSun) {
  TempDir dir;
  FrameSettings options;
  options.scene = write_scene(dir, false);
  SceneView loaded = load_scene_view(options, 1.0f);
  const scene::SceneStats stats = scene::scene_stats(loaded.scene);
  EXPECT_EQ(stats.directional_lights, 1u);
  EXPECT_EQ(stats.shadow_casting_lights, 1u);
  ASSERT_FALSE(loaded.scene.warnings.empty());
  EXPECT_NE(loaded.scene.warnings.back().find("no lights"), std::string::npos);

  // The built-in scenes bring their own lights and get none added.
  options.scene = "default";
  SceneView builtin = load_scene_view(options, 1.0f);
  EXPECT_EQ(scene::scene_stats(builtin.scene).directional_lights, 1u);
}

TEST(SceneView, UnnamedGltfCamera) {
  TempDir dir;
  FrameSettings options;
  options.scene = write_scene(dir, true);
  EXPECT_EQ(load_scene_view(options, 1.0f).camera_source, "glTF camera");
}

TEST(SceneView, CommandLineCameraWinsAndKeepsTheSceneLens) {
  TempDir dir;
  FrameSettings options;
  options.scene = write_scene(dir, true, "Overview");
  options.camera = scene::CameraPose{{5, 6, 7}, {0, 1, 0}};
  const SceneView loaded = load_scene_view(options, 1.0f);
  EXPECT_EQ(loaded.camera_source, "--camera");
  EXPECT_EQ(loaded.pose.eye, glm::vec3(5, 6, 7));
  EXPECT_EQ(loaded.pose.target, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(loaded.lens.yfov, 0.7f);
}

TEST(SceneView, FramesTheBoundsWithoutACamera) {
  TempDir dir;
  FrameSettings options;
  options.scene = write_scene(dir, false);
  const float aspect = 2.0f;
  SceneView loaded = load_scene_view(options, aspect);
  EXPECT_EQ(loaded.camera_source, "framed bounds");
  EXPECT_FLOAT_EQ(loaded.lens.yfov, scene::Camera{}.yfov);
  expect_near(loaded.pose.target, {0.5f, 0.5f, 0.0f});  // the triangle's box centre
  const scene::CameraPose expected =
      scene::frame_bounds(scene::scene_bounds(loaded.scene), scene::Camera{}.yfov, aspect);
  expect_near(loaded.pose.eye, expected.eye);
}

TEST(SceneView, BuiltinSceneBringsItsCamera) {
  FrameSettings options;  // --scene default
  const SceneView loaded = load_scene_view(options, 1.0f);
  EXPECT_EQ(loaded.scene.name, "default");
  EXPECT_EQ(loaded.camera_source, "built-in camera");
  expect_near(loaded.pose.eye, {0, 5, 9});  // default_scene.cpp's camera
}

TEST(SceneView, StressParametersReachTheScene) {
  FrameSettings options;
  options.scene = "stress";
  options.scene_params.triangles = 2000;
  options.scene_params.point_lights = 3;
  options.scene_params.spot_lights = 2;
  SceneView loaded = load_scene_view(options, 1.0f);
  const scene::SceneStats stats = scene::scene_stats(loaded.scene);
  EXPECT_EQ(stats.point_lights, 3u);
  EXPECT_EQ(stats.spot_lights, 2u);
  EXPECT_GE(stats.triangles, 2000u);
}

TEST(SceneView, LoadErrorsPropagate) {
  FrameSettings options;
  options.scene = "/no/such/dir/missing.gltf";
  try {
    load_scene_view(options, 1.0f);
    ADD_FAILURE() << "loaded a missing file";
  } catch (const scene::SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.gltf"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sg::test
