// SPDX-License-Identifier: MIT
// Shadow-map cameras: points that must be in a map land in [0, 1], Vulkan's conventions hold,
// and a point light's cube faces agree with Vulkan's cube-map addressing.
#include <random>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "systems/gpu/camera.h"
#include "systems/shadows/light_formulas.h"
#include "systems/shadows/light_views.h"

namespace sg::shadows {
namespace {

// Map uv (as the rasterizer lays NDC onto the image: row 0 at NDC y = -1) and depth.
glm::vec3 map_coords(const glm::mat4& view_projection, glm::vec3 world) {
  const glm::vec4 clip = view_projection * glm::vec4(world, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x + 1.0f) * 0.5f, (ndc.y + 1.0f) * 0.5f, ndc.z};
}

bool inside_unit_cube(glm::vec3 p) {
  return glm::all(glm::greaterThanEqual(p, glm::vec3(0.0f))) &&
         glm::all(glm::lessThanEqual(p, glm::vec3(1.0f)));
}

glm::vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> normal;
  return glm::normalize(glm::vec3{normal(rng), normal(rng), normal(rng)});  // braces: drawn left to right
}

// Any unit vector perpendicular to `v`.
glm::vec3 perpendicular(glm::vec3 v) {
  const glm::vec3 other = std::abs(v.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(v, other));
}

TEST(ShadowNearPlane, IsRangeOver200WithinOneToTenCentimetres) {
  EXPECT_FLOAT_EQ(shadow_near_plane(10.0f), 0.05f);
  EXPECT_FLOAT_EQ(shadow_near_plane(0.5f), 0.01f);
  EXPECT_FLOAT_EQ(shadow_near_plane(1000.0f), 0.1f);
}

TEST(SpotLightView, IsTheCameraOfTheSameLensButForDepth) {
  // The receiver reads spot maps with the camera's conventions, y flip included; only depth
  // differs: the camera's runs from 1 at near to 0 at far, a map's from 0 to 1 (the receiver's
  // biases and PCSS's blocker depths are worked out in that direction).
  const glm::vec3 position(1.0f, 4.0f, 2.0f), target(0.0f, 0.0f, -1.0f);
  const LightView spot =
      spot_light_view(position, glm::normalize(target - position), glm::radians(30.0f), 12.0f);
  const scene::Camera lens{glm::radians(60.0f), spot.near, 12.0f, 1.0f};
  const glm::mat4 camera = projection_matrix(lens, 1.0f) * view_matrix({position, target});
  const glm::mat4 light = spot.view_projection();
  for (int c = 0; c < 4; ++c) {
    for (const int r : {0, 1, 3}) EXPECT_NEAR(light[c][r], camera[c][r], 1e-5f) << c << "," << r;
  }
  // The light's view comes from lookAt, the camera's from its orientation's quaternion: they
  // round apart by about a micrometre, which depth at the near plane (6 cm) magnifies to 1e-5.
  for (const float distance : {spot.near, 5.0f, 12.0f}) {
    const glm::vec4 point(position + distance * glm::normalize(target - position), 1.0f);
    const glm::vec4 in_map = light * point, in_camera = camera * point;
    EXPECT_NEAR(in_map.z / in_map.w, 1.0f - in_camera.z / in_camera.w, 1e-4f) << distance;
  }
  EXPECT_FALSE(spot.orthographic);
  EXPECT_FLOAT_EQ(spot.far, 12.0f);
}

TEST(SpotLightView, AxisIsTheMapCentreAndDepthRunsNearToFar) {
  const glm::vec3 position(0.0f, 3.0f, 0.0f), direction = glm::normalize(glm::vec3(1, -1, 0));
  const LightView spot = spot_light_view(position, direction, glm::radians(40.0f), 10.0f);
  const glm::mat4 vp = spot.view_projection();
  const glm::vec3 mid = map_coords(vp, position + direction * 5.0f);
  EXPECT_NEAR(mid.x, 0.5f, 1e-5f);
  EXPECT_NEAR(mid.y, 0.5f, 1e-5f);
  EXPECT_NEAR(map_coords(vp, position + direction * spot.near).z, 0.0f, 1e-5f);
  EXPECT_NEAR(map_coords(vp, position + direction * 10.0f).z, 1.0f, 1e-5f);
  EXPECT_LT(mid.z, map_coords(vp, position + direction * 6.0f).z);
}

TEST(SpotLightView, WorldUpIsTheTopOfTheMap) {
  // Vulkan images have row 0 at the top: above the axis is v < 0.5, as in a camera image.
  const glm::vec3 position(0.0f, 1.0f, 0.0f), direction(0.0f, 0.0f, -1.0f);
  const LightView spot = spot_light_view(position, direction, glm::radians(45.0f), 10.0f);
  const glm::vec3 above = map_coords(spot.view_projection(), position + glm::vec3(0, 1, -5));
  const glm::vec3 right = map_coords(spot.view_projection(), position + glm::vec3(1, 0, -5));
  EXPECT_LT(above.y, 0.5f);
  EXPECT_GT(right.x, 0.5f);
}

TEST(SpotLightView, EveryPointOfTheConeWithinRangeIsInsideTheMap) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    const glm::vec3 position{unit(rng) * 4.0f, unit(rng) * 4.0f, unit(rng) * 4.0f};
    const glm::vec3 direction = random_unit(rng);
    const float outer = glm::radians(10.0f + 75.0f * unit(rng));
    const float range = 2.0f + 20.0f * unit(rng);
    const LightView spot = spot_light_view(position, direction, outer, range);
    const glm::vec3 side = perpendicular(direction);
    for (int i = 0; i < 50; ++i) {
      // A point at angle <= outer from the axis, at view depth within [near, far].
      const float angle = outer * unit(rng) * 0.999f;
      const float along_cross = unit(rng) - 0.5f;  // drawn in turn: a sum's operands have no order
      const glm::vec3 around =
          glm::normalize(glm::cross(direction, side) * along_cross + side * (unit(rng) - 0.5f));
      const glm::vec3 ray = direction * std::cos(angle) + around * std::sin(angle);
      const float depth = spot.near + (range - spot.near) * unit(rng);
      const glm::vec3 point = position + ray * (depth / std::cos(angle));
      EXPECT_TRUE(inside_unit_cube(map_coords(spot.view_projection(), point)))
          << "trial " << trial << " point " << i;
    }
  }
}

TEST(SpotLightView, HemisphereConeIsCappedAtTheWidestMap) {
  const LightView spot = spot_light_view({}, {0, 0, -1}, glm::radians(90.0f), 5.0f);
  // projection[0][0] = 1 / tan(fov / 2)
  EXPECT_NEAR(spot.projection[0][0], 1.0f / std::tan(max_spot_shadow_fov / 2.0f), 1e-5f);
}

TEST(PointLightCube, FaceImagesLineUpWithVulkanCubeLookups) {
  std::mt19937 rng(66);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const glm::vec3 light(1.5f, 2.0f, -0.5f);
  const float range = 8.0f;
  const CubeViews cube = point_light_cube(light, range);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 direction = random_unit(rng);
    const glm::vec3 point = light + direction * (0.5f + 6.0f * unit(rng));
    // The shaders' face selection (light_formulas.glsl), which follows the specification's table.
    const glm::vec3 texel = glsl::cube_face_uv(point - light);
    const int face = static_cast<int>(texel.z);
    const glm::vec3 rendered = map_coords(cube.view_projection[face], point);
    ASSERT_TRUE(inside_unit_cube(rendered)) << "direction " << i << " face " << face;
    ASSERT_NEAR(rendered.x, texel.x, 1e-4f) << "direction " << i << " face " << face;
    ASSERT_NEAR(rendered.y, texel.y, 1e-4f) << "direction " << i << " face " << face;
  }
}

TEST(PointLightCube, FacesLookDownTheSpecAxesWithNearAndRange) {
  const glm::vec3 light(0.0f, 1.0f, 0.0f);
  const CubeViews cube = point_light_cube(light, 10.0f);
  EXPECT_FLOAT_EQ(cube.near, shadow_near_plane(10.0f));
  EXPECT_FLOAT_EQ(cube.far, 10.0f);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    const glm::vec3 centre = map_coords(cube.view_projection[f], light + axes[f] * 5.0f);
    EXPECT_NEAR(centre.x, 0.5f, 1e-5f) << "face " << f;
    EXPECT_NEAR(centre.y, 0.5f, 1e-5f) << "face " << f;
    EXPECT_NEAR(map_coords(cube.view_projection[f], light + axes[f] * 10.0f).z, 1.0f, 1e-5f);
  }
}

scene::Aabb test_bounds() {
  scene::Aabb bounds;
  scene::grow(bounds, glm::vec3(-6.0f, 0.0f, -4.0f));
  scene::grow(bounds, glm::vec3(5.0f, 3.0f, 7.0f));
  return bounds;
}

glm::vec3 corner(const scene::Aabb& box, int index) {
  return {(index & 1) ? box.max.x : box.min.x, (index & 2) ? box.max.y : box.min.y,
          (index & 4) ? box.max.z : box.min.z};
}

TEST(DirectionalLightView, FitsEveryCornerOfTheBoundsTightly) {
  const scene::Aabb bounds = test_bounds();
  for (const glm::vec3 direction :
       {glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, -2, 0.5f)), glm::normalize(glm::vec3(-3, -1, -2))}) {
    const LightView light = directional_light_view(direction, bounds);
    EXPECT_TRUE(light.orthographic);
    glm::vec3 lowest(1.0f), highest(0.0f);
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 p = map_coords(light.view_projection(), corner(bounds, c));
      EXPECT_TRUE(inside_unit_cube(p)) << "corner " << c;
      lowest = glm::min(lowest, p);
      highest = glm::max(highest, p);
    }
    // Tight: the margin (0.5% of the diagonal) is all that is left on each side. The map spans
    // 2 / projection[0][0] and 2 / |projection[1][1]| across, far - near deep.
    const glm::vec3 map_extent(2.0f / light.projection[0][0], 2.0f / -light.projection[1][1],
                               light.far - light.near);
    const float margin = 0.005f * glm::length(bounds.extent());
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(lowest[axis] * map_extent[axis], margin, 1e-4f) << "axis " << axis;
      EXPECT_NEAR((1.0f - highest[axis]) * map_extent[axis], margin, 1e-4f) << "axis " << axis;
    }
    // Depth grows along the light's travel.
    const glm::vec3 centre = bounds.center();
    EXPECT_LT(map_coords(light.view_projection(), centre).z,
              map_coords(light.view_projection(), centre + direction).z);
  }
}

TEST(CylinderLightView, CoversOuterRadiusAroundTheBeamAndDepthToTheBounds) {
  const scene::Aabb bounds = test_bounds();
  const glm::vec3 position(0.0f, 6.0f, 0.0f), direction = glm::normalize(glm::vec3(0.3f, -1, 0));
  const float outer = 1.5f;
  const LightView light = cylinder_light_view(position, direction, outer, bounds);
  const glm::mat4 vp = light.view_projection();
  EXPECT_TRUE(light.orthographic);
  EXPECT_FLOAT_EQ(light.near, 0.0f);

  const glm::vec3 on_axis = map_coords(vp, position + direction * 3.0f);
  EXPECT_NEAR(on_axis.x, 0.5f, 1e-5f);
  EXPECT_NEAR(on_axis.y, 0.5f, 1e-5f);
  EXPECT_NEAR(map_coords(vp, position).z, 0.0f, 1e-5f);
  // The beam's rim is the map's inscribed circle.
  const glm::vec3 side = perpendicular(direction);
  for (const glm::vec3 across :
       {side, -side, glm::cross(direction, side), glm::normalize(side + glm::cross(direction, side))}) {
    const glm::vec3 rim = map_coords(vp, position + direction * 3.0f + across * outer);
    EXPECT_NEAR(glm::length(glm::vec2(rim) - glm::vec2(0.5f)), 0.5f, 1e-4f);
  }
  for (int c = 0; c < 8; ++c) {
    EXPECT_LE(map_coords(vp, corner(bounds, c)).z, 1.0f) << "corner " << c;
  }
  EXPECT_LT(map_coords(vp, position - direction).z, 0.0f) << "behind the light is outside";
}

}  // namespace
}  // namespace sg::shadows
