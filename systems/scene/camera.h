// SPDX-License-Identifier: MIT
#pragma once
// The camera component and the helpers that place one: from a "--camera ex,ey,ez,tx,ty,tz"
// string, or framing the scene's bounds when the scene brings no camera.
#include <string_view>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "ecs/entity.h"
#include "ecs/transform.h"
#include "ecs/world.h"
#include "systems/scene/aabb.h"

namespace sg::scene {

// A perspective camera looking down its entity's world -Z with +Y up (the glTF convention).
struct Camera {
  float yfov = glm::radians(60.0f);  // vertical field of view, radians
  float znear = 0.05f;
  float zfar = 500.0f;  // always finite: glTF's infinite projection gets a far plane on import
  float aspect = 0.0f;  // width / height; 0 means "use the viewport's"
};

struct CameraPose {
  glm::vec3 eye{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
  // The direction the top of the picture points to (a rolled camera's is not +Y); when it is
  // parallel to the view direction, an axis perpendicular to it is used instead (camera_up).
  glm::vec3 up{0.0f, 1.0f, 0.0f};
};

// `up`, or when it is (nearly) parallel to unit `forward`, an axis perpendicular to forward:
// looking straight up or down, +Y cannot say where the top of the picture is.
glm::vec3 camera_up(const glm::vec3& forward, const glm::vec3& up);

// The pose of a camera node as glTF defines it: its world position, looking down its world -Z,
// the top of the picture along its world +Y, roll included.
CameraPose camera_pose(const ecs::WorldTransform& world);

// Parses "ex,ey,ez,tx,ty,tz" (six finite numbers; spaces allowed around them). Throws
// SceneError naming the text and what is wrong; eye == target is refused (no direction).
CameraPose parse_camera(std::string_view text);

// A pose that shows all of `bounds` with a vertical field of view `yfov` and the given aspect:
// looking at the centre from above and in front (+Z), far enough that the bounding sphere fits
// the narrower field. An empty box gives a pose looking at the origin from (0, 2, 5).
CameraPose frame_bounds(const Aabb& bounds, float yfov, float aspect);

// The local rotation that makes an entity at `eye` look at `target` (-Z forward), its +Y along
// camera_up(forward, up).
glm::quat look_rotation(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up = {0, 1, 0});

// Creates a root entity with Camera, LocalTransform (from the pose) and WorldTransform.
ecs::Entity add_camera(ecs::World& world, const CameraPose& pose, const Camera& camera = {});

}  // namespace sg::scene
