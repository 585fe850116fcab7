#include "sandbox/scene_setup.h"

#include <algorithm>

#include "ecs/transform.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_queries.h"

namespace sg::sandbox {
namespace {

std::string scene_camera_source(const Options& options, const scene::Scene& scene,
                                ecs::Entity camera) {
  const auto& builtin = scene::builtin_scene_names;
  if (std::find(builtin.begin(), builtin.end(), options.scene) != builtin.end()) {
    return "built-in camera";
  }
  const scene::Name* name = scene.world.try_get<scene::Name>(camera);
  return name ? "glTF camera '" + name->value + "'" : "glTF camera";
}

}  // namespace

SandboxScene load_sandbox_scene(const Options& options, float aspect) {
  SandboxScene result{scene::load_scene(options.scene, options.scene_params), {}, {}, {}};
  const std::optional<ecs::Entity> camera = scene::first_camera(result.scene);
  if (camera) result.lens = result.scene.world.get<scene::Camera>(*camera);

  if (options.camera) {
    result.pose = *options.camera;
    result.camera_source = "--camera";
  } else if (camera) {
    // Cameras follow the lights' convention (lights.h): position = world translation,
    // forward = world -Z.
    const auto& world = result.scene.world.get<ecs::WorldTransform>(*camera);
    result.pose.eye = scene::light_position(world);
    result.pose.target = result.pose.eye + scene::light_direction(world);
    result.camera_source = scene_camera_source(options, result.scene, *camera);
  } else {
    result.pose = scene::frame_bounds(scene::scene_bounds(result.scene), result.lens.yfov, aspect);
    result.camera_source = "framed bounds";
  }
  return result;
}

}  // namespace sg::sandbox
