// SPDX-License-Identifier: MIT
// The camera's reversed depth (systems/gpu/camera.h): 1 at the near plane, 0 at the far plane, and
// world positions rebuilt from a stored depth, as deferred lighting does, stay on their surface
// far from the camera.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "systems/gpu/camera.h"

namespace sg {
namespace {

TEST(CameraDepth, IsOneAtTheNearPlaneAndZeroAtTheFarPlane) {
  const scene::Camera lens;
  const glm::mat4 clip = projection_matrix(lens, 16.0f / 9.0f) * view_matrix({{0, 0, 0}, {0, 0, -1}});
  const auto depth = [&](float distance) {
    const glm::vec4 p = clip * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
    return p.z / p.w;
  };
  EXPECT_NEAR(depth(lens.znear), camera_near_depth, 1e-6f);
  EXPECT_NEAR(depth(lens.zfar), camera_far_depth, 1e-6f);
  EXPECT_GT(depth(1.0f), depth(2.0f)) << "nearer is greater";
}

// A floor point 100 to 250 units away, its depth stored as a float and brought back through the
// inverse view-projection (float, as the shaders do): it lands within a millimetre of the floor.
// With depth 0 at znear 0.05 it landed up to about 5 cm off at 250 units, more than a spot
// light's constant bias (issue 35's acne).
TEST(CameraDepth, DistantSurfacesComeBackOnTheirPlane) {
  const scene::CameraPose pose{{0.0f, 60.0f, 0.0f}, {0.0f, 0.0f, -150.0f}};
  const glm::mat4 view_projection = projection_matrix(scene::Camera{}, 16.0f / 9.0f) * view_matrix(pose);
  const glm::mat4 inverse = glm::inverse(view_projection);
  float worst = 0.0f;
  for (float z = -90.0f; z > -240.0f; z -= 0.37f) {
    const glm::vec4 clip = view_projection * glm::vec4(3.0f, 0.0f, z, 1.0f);
    const float stored = clip.z / clip.w;  // what a D32_SFLOAT depth buffer keeps
    const glm::vec4 world = inverse * glm::vec4(clip.x / clip.w, clip.y / clip.w, stored, 1.0f);
    worst = std::max(worst, std::abs(world.y / world.w));
  }
  EXPECT_LT(worst, 1e-3f);
}

}  // namespace
}  // namespace sg
