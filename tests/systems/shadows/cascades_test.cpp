// SPDX-License-Identifier: MIT
// Cascaded maps of directional lights: every visible point of the scene lies in a cascade, a
// camera's turn leaves the maps' sizes alone and its move shifts them by whole texels, and a
// camera far from the scene gets the one fitted map. Then the cascades through the frame's
// lights: views, keys, records and the schedule's maps.
#include <cmath>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "ecs/transform_system.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene_builder.h"
#include "systems/shadows/cascades.h"
#include "systems/shadows/frame_lights.h"
#include "systems/shadows/shadow_schedule.h"

namespace sg::shadows {
namespace {

const glm::vec3 sun = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
const scene::Aabb hall{glm::vec3(-100.0f, 0.0f, -100.0f), glm::vec3(100.0f, 20.0f, 100.0f)};

CascadeCamera street_camera(glm::vec3 eye = {0.0f, 1.7f, 60.0f}, glm::vec3 forward = {0.0f, -0.1f, -1.0f}) {
  CascadeCamera camera;
  camera.eye = eye;
  camera.forward = glm::normalize(forward);
  camera.yfov = glm::radians(60.0f);
  camera.aspect = 16.0f / 9.0f;
  camera.near = 0.05f;
  camera.far = 500.0f;
  return camera;
}

glm::vec3 map_coords(const LightView& view, glm::vec3 world) {
  const glm::vec4 clip = view.view_projection() * glm::vec4(world, 1.0f);
  return {(clip.x / clip.w + 1.0f) * 0.5f, (clip.y / clip.w + 1.0f) * 0.5f, clip.z / clip.w};
}

float map_width(const LightView& view) { return 2.0f / std::abs(view.projection[0][0]); }

TEST(Cascades, EveryVisiblePointOfTheSceneLiesInsideItsSlicesMap) {
  const CascadeCamera camera = street_camera();
  const CascadeFit fit = fit_cascades(sun, hall, camera, max_cascades);
  ASSERT_GE(fit.count, 3u);
  for (uint32_t k = 0; k < fit.count; ++k) EXPECT_LT(fit.splits[k], fit.splits[k + 1]);
  // Nearer maps are smaller: that is what they are for.
  for (uint32_t k = 1; k < fit.count; ++k) EXPECT_LT(map_width(fit.views[k - 1]), map_width(fit.views[k]));

  const glm::vec3 right = glm::normalize(glm::cross(camera.forward, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, camera.forward);
  const float tan_y = std::tan(0.5f * camera.yfov);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_real_distribution<float> fraction(0.0f, 1.0f);
  int tested = 0;
  while (tested < 2000) {
    // A point of the frustum, at a depth spread over the splits on a log scale.
    const float depth = fit.splits[0] * std::pow(fit.splits[fit.count] / fit.splits[0], fraction(rng));
    const float across = unit(rng);  // drawn in turn: a sum's operands have no order
    const float upward = unit(rng);
    const glm::vec3 p = camera.eye + camera.forward * depth +
                        right * (across * tan_y * camera.aspect * depth) + up * (upward * tan_y * depth);
    if (glm::any(glm::lessThan(p, hall.min)) || glm::any(glm::greaterThan(p, hall.max))) continue;
    ++tested;
    uint32_t slice = 0;
    while (slice + 1 < fit.count && depth > fit.splits[slice + 1]) ++slice;
    const glm::vec3 uvz = map_coords(fit.views[slice], p);
    for (int axis = 0; axis < 2; ++axis) {
      EXPECT_GE(uvz[axis], cascade_edge_uv) << "slice " << slice << " depth " << depth;
      EXPECT_LE(uvz[axis], 1.0f - cascade_edge_uv) << "slice " << slice << " depth " << depth;
    }
    EXPECT_GE(uvz.z, 0.0f);
    EXPECT_LE(uvz.z, 1.0f);
  }
}

// The slices follow the distances the scene spans from the eye, not the view's depths.
TEST(Cascades, TurningTheCameraKeepsEveryMapsSize) {
  const CascadeFit ahead = fit_cascades(sun, hall, street_camera(), max_cascades);
  const CascadeFit aside =
      fit_cascades(sun, hall, street_camera({0.0f, 1.7f, 60.0f}, {1.0f, -0.3f, -0.2f}), max_cascades);
  ASSERT_EQ(ahead.count, aside.count);
  for (uint32_t k = 0; k + 1 < ahead.count; ++k) {
    EXPECT_FLOAT_EQ(map_width(ahead.views[k]), map_width(aside.views[k])) << k;
  }
}

TEST(Cascades, AMovingCameraShiftsTheMapsByWholeTexelsOfTheSmallestTile) {
  const CascadeFit first = fit_cascades(sun, hall, street_camera(), max_cascades);
  for (float step : {0.001f, 0.37f, 1.9f, 13.0f}) {
    const CascadeFit moved =
        fit_cascades(sun, hall, street_camera({step, 1.7f, 60.0f - 0.5f * step}), max_cascades);
    ASSERT_EQ(first.count, moved.count);
    for (uint32_t k = 0; k + 1 < first.count; ++k) {
      // The same size, and a fixed point's place in the map moved by whole texels of a 16-texel
      // map, so by whole texels of every tile.
      EXPECT_EQ(first.views[k].projection, moved.views[k].projection);
      const glm::vec3 point(3.0f, 0.0f, 40.0f);
      const glm::vec2 texels =
          (glm::vec2(map_coords(moved.views[k], point)) - glm::vec2(map_coords(first.views[k], point))) *
          16.0f;
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_NEAR(texels[axis], std::round(texels[axis]), 1e-3f) << "cascade " << k << " step " << step;
      }
    }
  }
  // A step well within a lattice cell leaves every map exactly as it was, so it stays cached.
  const CascadeFit nudged = fit_cascades(sun, hall, street_camera({0.0f, 1.7f, 60.0f - 1e-4f}), max_cascades);
  for (uint32_t k = 0; k < first.count; ++k) {
    EXPECT_EQ(first.views[k].view_projection(), nudged.views[k].view_projection());
  }
}

TEST(Cascades, ACameraFarFromTheSceneGetsTheOneFittedMap) {
  const CascadeCamera far = street_camera({0.0f, 400.0f, 900.0f}, {0.0f, -0.4f, -1.0f});
  const CascadeFit fit = fit_cascades(sun, hall, far, max_cascades);
  EXPECT_EQ(fit.count, 1u);
  const LightView whole = directional_light_view(sun, hall);
  EXPECT_EQ(fit.views[0].view_projection(), whole.view_projection());
  // And one cascade asked for is that map, wherever the camera is.
  EXPECT_EQ(fit_cascades(sun, hall, street_camera(), 1).views[0].view_projection(), whole.view_projection());
}

// The shaders' copies of the fit's edge and blend bands.
TEST(Cascades, TheShadersBandsAreTheFitsBands) {
  std::ifstream file(SHADOWGRAPH_SHADOW_SAMPLING_GLSL);
  std::stringstream text;
  text << file.rdbuf();
  const std::string glsl = text.str();
  std::smatch match;
  ASSERT_TRUE(std::regex_search(glsl, match, std::regex(R"(CASCADE_EDGE_UV = 1\.0 / (\d+)\.0;)")));
  EXPECT_FLOAT_EQ(1.0f / std::stof(match[1]), cascade_edge_uv);
  ASSERT_TRUE(std::regex_search(glsl, match, std::regex(R"(CASCADE_BLEND_UV = 1\.0 / (\d+)\.0;)")));
  EXPECT_FLOAT_EQ(1.0f / std::stof(match[1]), cascade_blend_uv);
}

TEST(Cascades, ACascadedSunHasAViewAndARecordPerCascade) {
  scene::Scene scene;
  scene::ShadowSettings three;
  three.cascades = 3;
  scene::add_light(scene, scene::SpotLight{}, {glm::vec3(0.0f, 5.0f, 0.0f)}, scene::ShadowSettings{}, "lamp");
  const ecs::Entity entity =
      scene::add_light(scene, scene::DirectionalLight{},
                       {glm::vec3(0.0f), scene::look_rotation(glm::vec3(0.0f), sun)}, three, "sun");
  ecs::update_world_transforms(scene.world, 0);
  FrameLights lights;
  gather_lights(scene.world, hall, {}, lights);
  ASSERT_EQ(lights.maps.size(), 4u);
  ASSERT_EQ(lights.cascades.size(), 3u);
  ASSERT_EQ(lights.cascaded.size(), 1u);
  const FrameLights::CascadedLight& cascaded = lights.cascaded[0];
  EXPECT_EQ(cascaded.views, 3u);
  for (uint32_t k = 0; k < 3; ++k) {
    const ShadowMapView& map = lights.maps[cascaded.first_view + k];
    EXPECT_EQ(map.light, cascaded.record);
    EXPECT_EQ(map.cascade, k);
    EXPECT_EQ(map.key, cascade_key(entity, k));
    EXPECT_EQ(map.name, "shadow sun cascade " + std::to_string(k + 1));
  }
  EXPECT_NE(cascade_key(entity, 0), light_key(entity));
  // The record finds its cascades after the frame's records.
  EXPECT_EQ(lights.records[cascaded.record].shape.x, float(lights.records.size()));

  place_cascades(lights, street_camera(), hall);
  const GpuLight& record = lights.records[cascaded.record];
  EXPECT_EQ(record.shape.y, 3.0f);
  for (uint32_t k = 0; k < 3; ++k) EXPECT_TRUE(lights.maps[cascaded.first_view + k].needed);

  ShadowSchedule schedule({1024, 4, min_shadow_resolution});
  const glm::mat4 view =
      glm::lookAtRH(glm::vec3(0.0f, 1.7f, 60.0f), glm::vec3(0.0f, 1.6f, 59.0f), glm::vec3(0, 1, 0));
  const ShadowCamera camera{glm::vec3(0.0f, 1.7f, 60.0f),
                            glm::perspectiveRH_ZO(glm::radians(60.0f), 16.0f / 9.0f, 0.05f, 500.0f) * view,
                            600.0f};
  schedule.schedule(lights, camera, {}, 0);
  EXPECT_EQ(schedule.stats().cascades, 3u);
  EXPECT_EQ(record.info.w, cascaded_shadow_maps);
  for (uint32_t k = 0; k < 3; ++k) {
    const ShadowMapView& map = lights.maps[cascaded.first_view + k];
    ASSERT_GT(map.resolution, 0u);
    EXPECT_EQ(lights.cascades[k].info.w, map.tile.page);
    EXPECT_EQ(lights.cascades[k].shadow_matrix, map.view.view_projection());
  }
  std::vector<GpuLight> sorted(lights.records.size());
  sort_by_group(lights, sorted);
  EXPECT_EQ(sorted[lights.sorted_place[lights.cascaded[0].record]].info.x,
            uint32_t(GpuLightType::directional));

  // Far away, the sun needs one cascade: the others ask for no tile and count for nothing.
  gather_lights(scene.world, hall, {}, lights);
  place_cascades(lights, street_camera({0.0f, 400.0f, 900.0f}, {0.0f, -0.4f, -1.0f}), hall);
  EXPECT_EQ(lights.records[lights.cascaded[0].record].shape.y, 1.0f);
  schedule.schedule(lights, camera, {}, 0);
  EXPECT_EQ(schedule.stats().cascades, 1u);
  EXPECT_EQ(schedule.stats().lights_without_shadow, 0u);
  EXPECT_EQ(lights.maps[lights.cascaded[0].first_view + 1].resolution, 0u);
  EXPECT_EQ(lights.cascades[1].info.w, no_shadow_map);
}

}  // namespace
}  // namespace sg::shadows
