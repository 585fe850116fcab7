// SPDX-License-Identifier: MIT
#include "systems/frame/scene_view.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "ecs/query.h"
#include "ecs/transform.h"
#include "ecs/transform_system.h"
#include "systems/frame/scene_sidecar.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/scene/lights.h"
#include "systems/scene/scene_builder.h"
#include "systems/scene/scene_error.h"
#include "systems/scene/scene_queries.h"

namespace sg {
namespace {

std::string scene_camera_source(const FrameSettings& settings, const scene::Scene& scene,
                                ecs::Entity camera) {
  const auto& builtin = scene::builtin_scene_names;
  if (std::find(builtin.begin(), builtin.end(), settings.scene) != builtin.end()) {
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

// The scene's camera named `name`; throws SceneError listing the cameras' names when there is none.
ecs::Entity camera_named(const scene::Scene& scene, const std::string& name) {
  std::optional<ecs::Entity> found;
  std::string names;
  scene.world.query<const scene::Camera, const scene::Name>().for_each(
      [&](ecs::Entity entity, const scene::Camera&, const scene::Name& camera) {
        if (camera.value == name) found = entity;
        if (!names.empty()) names += ", ";
        names += camera.value;
      });
  if (found) return *found;
  throw scene::SceneError(scene.name, "--camera " + name,
                          "the scene has no camera of that name (its named cameras: " +
                              (names.empty() ? std::string("none") : names) + ")");
}

}  // namespace

SceneView load_scene_view(const FrameSettings& settings, float aspect) {
  SceneView result{scene::load_scene(settings.scene, settings.scene_params), {}, {}, {}};
  add_default_light(result.scene);
  const std::optional<ecs::Entity> camera = settings.camera_name.empty()
                                                ? scene::first_camera(result.scene)
                                                : camera_named(result.scene, settings.camera_name);
  if (camera) result.lens = result.scene.world.get<scene::Camera>(*camera);

  if (settings.camera) {
    result.pose = *settings.camera;
    result.camera_source = "--camera";
  } else if (camera) {
    result.pose = scene::camera_pose(result.scene.world.get<ecs::WorldTransform>(*camera));
    result.camera_source = settings.camera_name.empty() ? scene_camera_source(settings, result.scene, *camera)
                                                        : "--camera " + settings.camera_name;
  } else {
    result.pose = scene::frame_bounds(scene::scene_bounds(result.scene), result.lens.yfov, aspect);
    result.camera_source = "framed bounds";
  }
  // The user's saved edits, unless the command line names the camera or asks for the scene as is.
  const std::filesystem::path sidecar = sidecar_path(settings.scene);
  const bool named = settings.camera || !settings.camera_name.empty();
  if (settings.sidecar && std::filesystem::exists(sidecar)) {
    scene::CameraPose pose = result.pose;
    apply_sidecar(sidecar, result.scene, pose);
    if (!named) {
      result.pose = pose;
      result.camera_source = sidecar.string();
    }
    std::printf("shadowgraph: lights%s from %s (--sidecar off ignores it)\n", named ? "" : " and camera",
                sidecar.string().c_str());
  }
  // --algorithm and --contact-shadows set every light's once, here: the panels and scripts may
  // change them afterwards, and a per-frame override would undo their edits.
  if (settings.algorithm || settings.contact_length) {
    result.scene.world.query<scene::ShadowSettings>().for_each([&](scene::ShadowSettings& shadow) {
      shadow.algorithm = settings.algorithm.value_or(shadow.algorithm);
      shadow.contact_length = settings.contact_length.value_or(shadow.contact_length);
    });
  }
  if (settings.cascades) {
    result.scene.world.query<const scene::DirectionalLight, scene::ShadowSettings>().for_each(
        [&](const scene::DirectionalLight&, scene::ShadowSettings& shadow) {
          shadow.cascades = *settings.cascades;
        });
  }
  return result;
}

}  // namespace sg
