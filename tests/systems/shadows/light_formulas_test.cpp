// SPDX-License-Identifier: MIT
// shaders/light_formulas.glsl, compiled as C++, against docs/ALGORITHMS.md's formulas and against
// the light views' actual projections.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "systems/shadows/light_formulas.h"
#include "systems/shadows/light_views.h"

namespace sg::shadows {
namespace {

using namespace glsl;

TEST(LightFormulas, LinearWindowFalloff) {
  // A = max(1 - d / R, 0)
  EXPECT_FLOAT_EQ(falloff_linear_window(0.0f, 8.0f), 1.0f);
  EXPECT_FLOAT_EQ(falloff_linear_window(2.0f, 8.0f), 0.75f);
  EXPECT_FLOAT_EQ(falloff_linear_window(8.0f, 8.0f), 0.0f);
  EXPECT_FLOAT_EQ(falloff_linear_window(12.0f, 8.0f), 0.0f);
}

TEST(LightFormulas, GltfPunctualFalloff) {
  // A = clamp(1 - (d/R)^4, 0, 1)^2 / d^2
  const float d = 2.0f, range = 4.0f;
  const float expected = std::pow(1.0f - std::pow(d / range, 4.0f), 2.0f) / (d * d);
  EXPECT_NEAR(falloff_gltf_punctual(d, range), expected, 1e-6f);
  EXPECT_NEAR(falloff_gltf_punctual(0.5f, 100.0f), 4.0f, 1e-4f) << "inverse square well inside R";
  EXPECT_FLOAT_EQ(falloff_gltf_punctual(4.0f, range), 0.0f);
  EXPECT_FLOAT_EQ(falloff_gltf_punctual(5.0f, range), 0.0f);
  EXPECT_TRUE(std::isfinite(falloff_gltf_punctual(0.0f, range)));
  // The window alone (the shadow color's fade): 1 at the light, 0 from R on.
  EXPECT_NEAR(gltf_range_window(d, range) / (d * d), expected, 1e-6f);
  EXPECT_FLOAT_EQ(gltf_range_window(0.0f, range), 1.0f);
  EXPECT_FLOAT_EQ(gltf_range_window(range, range), 0.0f);
}

TEST(LightFormulas, SmoothSpotCone) {
  // clamp((cos_angle - cos(outer)) / (cos(inner) - cos(outer)), 0, 1)
  const float cos_inner = std::cos(glm::radians(20.0f)), cos_outer = std::cos(glm::radians(30.0f));
  EXPECT_FLOAT_EQ(spot_cone(1.0f, cos_inner, cos_outer), 1.0f);
  EXPECT_FLOAT_EQ(spot_cone(cos_inner, cos_inner, cos_outer), 1.0f);
  EXPECT_NEAR(spot_cone(0.5f * (cos_inner + cos_outer), cos_inner, cos_outer), 0.5f, 1e-4f);
  EXPECT_FLOAT_EQ(spot_cone(cos_outer, cos_inner, cos_outer), 0.0f);
  EXPECT_FLOAT_EQ(spot_cone(0.0f, cos_inner, cos_outer), 0.0f);
}

TEST(LightFormulas, CylinderLambda) {
  // 1 within r, (R - delta) / (R - r) between, 0 beyond R and behind the light.
  EXPECT_FLOAT_EQ(cylinder_lambda(3.0f, 0.2f, 0.5f, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(cylinder_lambda(3.0f, 0.5f, 0.5f, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(cylinder_lambda(3.0f, 0.75f, 0.5f, 1.0f), 0.5f);
  EXPECT_FLOAT_EQ(cylinder_lambda(3.0f, 1.0f, 0.5f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(cylinder_lambda(3.0f, 2.0f, 0.5f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(cylinder_lambda(-0.1f, 0.0f, 0.5f, 1.0f), 0.0f);
}

TEST(LightFormulas, SlopeScaledBias) {
  // max(b1 * (1 - dot(N, L)), b0)
  EXPECT_FLOAT_EQ(shadow_bias(1.0f, 0.001f, 0.01f), 0.001f);
  EXPECT_FLOAT_EQ(shadow_bias(0.0f, 0.001f, 0.01f), 0.01f);
  EXPECT_FLOAT_EQ(shadow_bias(0.5f, 0.001f, 0.01f), 0.005f);
}

TEST(LightFormulas, PerspectiveDepthRoundTripsThroughTheSpotProjection) {
  const glm::vec3 position(0.0f, 2.0f, 0.0f), direction(0.0f, 0.0f, -1.0f);
  const LightView spot = spot_light_view(position, direction, glm::radians(35.0f), 15.0f);
  const float n = spot.near, f = spot.far;
  for (const float z : {n, 0.3f, 1.0f, 4.0f, 9.5f, f}) {
    const glm::vec4 clip = spot.view_projection() * glm::vec4(position + direction * z, 1.0f);
    const float stored = clip.z / clip.w;
    EXPECT_NEAR(perspective_view_depth(stored, n, f), z, 1e-4f * z) << "view depth " << z;
    // The slope against a central difference of the projection's depth.
    const float h = 1e-2f * z;
    const auto stored_at = [&](float depth) {
      const glm::vec4 c = spot.view_projection() * glm::vec4(position + direction * depth, 1.0f);
      return c.z / c.w;
    };
    EXPECT_NEAR(perspective_stored_depth_slope(z, n, f), (stored_at(z + h) - stored_at(z - h)) / (2.0f * h),
                1e-2f * perspective_stored_depth_slope(z, n, f))
        << "view depth " << z;
    // docs/ALGORITHMS.md 4.4's form for this projection: zView = Py / (d - Px).
    const float px = f / (f - n), py = -n * f / (f - n);
    EXPECT_NEAR(py / (stored - px), z, 1e-4f * z);
  }
}

TEST(LightFormulas, PcssPenumbraWidth) {
  // w = (zReceiver - zBlocker) / zBlocker * lightSize
  EXPECT_FLOAT_EQ(pcss_penumbra_width(4.0f, 2.0f, 0.3f), 0.3f);
  EXPECT_FLOAT_EQ(pcss_penumbra_width(4.0f, 4.0f, 0.3f), 0.0f);
  // A blocker lifted off the receiver (towards the light) widens the penumbra.
  EXPECT_GT(pcss_penumbra_width(4.0f, 3.0f, 0.3f), pcss_penumbra_width(4.0f, 3.5f, 0.3f));
  EXPECT_FLOAT_EQ(orthographic_penumbra_width(7.0f, 5.0f, 0.1f), 0.2f);
}

// Map uv of a world point.
glm::vec2 map_uv(const glm::mat4& view_projection, glm::vec3 world) {
  const glm::vec4 clip = view_projection * glm::vec4(world, 1.0f);
  return (glm::vec2(clip) / clip.w + 1.0f) * 0.5f;
}

TEST(LightFormulas, WorldToUvScaleMatchesThePerspectiveProjection) {
  const glm::vec3 position(1.0f, 3.0f, 0.0f), direction = glm::normalize(glm::vec3(0, -1, -1));
  const LightView spot = spot_light_view(position, direction, glm::radians(25.0f), 20.0f);
  const glm::mat4 vp = spot.view_projection();
  const float scale = projection_x_scale(vp);
  const glm::vec3 across = glm::normalize(glm::cross(direction, glm::vec3(1, 0, 0)));
  for (const float z : {1.0f, 5.0f, 12.0f}) {
    const glm::vec3 centre = position + direction * z;
    const float moved = glm::length(map_uv(vp, centre + across * 0.01f) - map_uv(vp, centre));
    EXPECT_NEAR(map_uv_per_world_unit(scale, z, false) * 0.01f, moved, 1e-3f * moved) << z;
  }
}

TEST(LightFormulas, WorldToUvScaleMatchesTheOrthographicProjection) {
  scene::Aabb bounds;
  scene::grow(bounds, glm::vec3(-3.0f, 0.0f, -2.0f));
  scene::grow(bounds, glm::vec3(4.0f, 2.0f, 5.0f));
  const glm::vec3 direction = glm::normalize(glm::vec3(1, -3, 2));
  const LightView light = directional_light_view(direction, bounds);
  const glm::mat4 vp = light.view_projection();
  const glm::vec3 across = glm::normalize(glm::cross(direction, glm::vec3(0, 1, 0)));
  const glm::vec3 centre = bounds.center();
  const float moved = glm::length(map_uv(vp, centre + across) - map_uv(vp, centre));
  EXPECT_NEAR(map_uv_per_world_unit(projection_x_scale(vp), 123.0f, true), moved, 1e-4f);
}

TEST(LightFormulas, CubeTexelWorldSizeIsOneTexelOfAFaceCentre) {
  const glm::vec3 light(0.0f, 1.0f, 0.0f);
  const CubeViews cube = point_light_cube(light, 10.0f);
  const float texel_uv = 1.0f / 512.0f, distance = 3.0f;
  const glm::vec3 centre = light + glm::vec3(0, 0, -distance);  // face 5 (-Z)
  const glm::vec3 next = centre + glm::vec3(cube_texel_world_size(distance, texel_uv), 0, 0);
  EXPECT_NEAR(glm::length(map_uv(cube.view_projection[5], next) - map_uv(cube.view_projection[5], centre)),
              texel_uv, 1e-6f);
}

TEST(LightFormulas, CellRandomIsStableUniformAndPerSample) {
  const glm::uvec2 pixel(640, 360);
  EXPECT_EQ(cell_random(pixel, 3), cell_random(pixel, 3)) << "same pixel, same numbers";
  EXPECT_NE(cell_random(pixel, 3), cell_random(pixel, 4));
  EXPECT_NE(cell_random(pixel, 3), cell_random(pixel + glm::uvec2(1, 0), 3));
  EXPECT_NE(cell_random(pixel, 3), cell_random(pixel + glm::uvec2(0, 1), 3));
  glm::vec3 sum(0.0f);
  const int n = 30000;
  for (int i = 0; i < n; ++i) {  // neighbouring pixels, as a screen has them
    const glm::vec3 u = cell_random(glm::uvec2(i % 200, i / 200), std::uint32_t(i % 16));
    ASSERT_TRUE(glm::all(glm::greaterThan(u, glm::vec3(0.0f))) &&
                glm::all(glm::lessThanEqual(u, glm::vec3(1.0f))));
    sum += u;
  }
  const glm::vec3 mean = sum / float(n);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 0.5f, 0.01f) << "component " << c;
}

TEST(LightFormulas, GaussianPairIsStandardNormal) {
  // Box-Muller over the pixel hash: mean 0, variance 1, uncorrelated components.
  const int n = 30000;
  glm::dvec2 sum(0.0), squares(0.0);
  double product = 0.0;
  for (int i = 0; i < n; ++i) {
    const glm::vec2 g = gaussian_pair(glm::vec2(cell_random(glm::uvec2(i % 300, i / 300), 0)));
    sum += glm::dvec2(g);
    squares += glm::dvec2(g * g);
    product += double(g.x) * double(g.y);
  }
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(sum[c] / n, 0.0, 0.03) << "component " << c;
    EXPECT_NEAR(squares[c] / n, 1.0, 0.05) << "component " << c;
  }
  EXPECT_NEAR(product / n, 0.0, 0.03);
}

}  // namespace
}  // namespace sg::shadows
