#include "sandbox/scene_setup.h"

#include <cstdio>
#include <filesystem>

#include "sandbox/scene_sidecar.h"

#include <algorithm>

#include "ecs/transform.h"
#include "ecs/transform_system.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/scene_queries.h"

namespace sg::sandbox {
namespace {

std::string scene_camera_source(const Options& options, const scene::Scene& scene, ecs::Entity camera) {
  const auto& builtin = scene::builtin_scene_names;
  if (std::find(builtin.begin(), builtin.end(), options.scene) != builtin.end()) {
    return "built-in camera";
  }
  const scene::Name* name = scene.world.try_get<scene::Name>(camera);
  return name ? "glTF camera '" + name->value + "'" : "glTF camera";
}

// A scene that brings no light (many glTF files) would show ambient only: give it a sun from
// above and in front of the camera's side, casting a shadow, and say so.
void add_default_light(scene::Scene& scene) {
  const scene::SceneStats stats = scene::scene_stats(scene);
  if (stats.point_lights + stats.spot_lights + stats.directional_lights + stats.cylinder_lights > 0) {
    return;
  }
  const glm::vec3 direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.6f));
  const scene::Aabb bounds = scene::scene_bounds(scene);
  const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const glm::vec3 position = centre - direction;
  scene::add_light(scene, scene::DirectionalLight{glm::vec3(1.0f), 1.0f},
                   {position, scene::look_rotation(position, centre), glm::vec3(1.0f)},
                   scene::ShadowSettings{}, "sandbox sun");
  ecs::update_world_transforms(scene.world, 0);
  scene::warn(scene, "the scene has no lights: the sandbox added a directional light with a shadow");
}

}  // namespace

SandboxScene load_sandbox_scene(const Options& options, float aspect) {
  SandboxScene result{scene::load_scene(options.scene, options.scene_params), {}, {}, {}};
  add_default_light(result.scene);
  const std::optional<ecs::Entity> camera = scene::first_camera(result.scene);
  if (camera) result.lens = result.scene.world.get<scene::Camera>(*camera);

  if (options.camera) {
    result.pose = *options.camera;
    result.camera_source = "--camera";
  } else if (camera) {
    result.pose = scene::camera_pose(result.scene.world.get<ecs::WorldTransform>(*camera));
    result.camera_source = scene_camera_source(options, result.scene, *camera);
  } else {
    result.pose = scene::frame_bounds(scene::scene_bounds(result.scene), result.lens.yfov, aspect);
    result.camera_source = "framed bounds";
  }
  // The user's saved edits, unless the command line names the camera or asks for the scene as is.
  const std::filesystem::path sidecar = sidecar_path(options.scene);
  if (options.sidecar && std::filesystem::exists(sidecar)) {
    scene::CameraPose pose = result.pose;
    apply_sidecar(sidecar, result.scene, pose);
    if (!options.camera) {
      result.pose = pose;
      result.camera_source = sidecar.string();
    }
    std::printf("shadowgraph: lights%s from %s (--sidecar off ignores it)\n",
                options.camera ? "" : " and camera", sidecar.string().c_str());
  }
  return result;
}

}  // namespace sg::sandbox
