// Renders the built-in scene offscreen and checks floor pixels against the lighting formula
// of ALGORITHMS.md section 2, evaluated here on the CPU from the scene's parameters.
#include <cmath>
#include <optional>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "rendergraph/vulkan/frame_ring.h"
#include "rendergraph/vulkan/readback.h"
#include "systems/scene_renderer.h"
#include "vulkan_test_context.h"

namespace sg::test {
namespace {

constexpr uint32_t width = 160;
constexpr uint32_t height = 120;
// 8-bit quantization (half a step) plus float rounding differences between CPU and shader.
constexpr int tolerance = 3;

float srgb_encode(float linear) {
  linear = glm::clamp(linear, 0.0f, 1.0f);
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Distance along the ray to an oriented box grown by `margin`, if hit.
std::optional<float> hit_box(const BoxInstance& box, glm::vec3 origin, glm::vec3 dir, float margin) {
  BoxInstance grown = box;
  grown.half_extent += glm::vec3(margin);
  const glm::mat4 to_local = glm::inverse(model_matrix(grown));
  const glm::vec3 o = glm::vec3(to_local * glm::vec4(origin, 1.0f));
  const glm::vec3 d = glm::vec3(to_local * glm::vec4(dir, 0.0f));
  constexpr float h = 0.5f;  // model_matrix maps the cube [-h, h]^3 onto the box
  float t_near = -INFINITY, t_far = INFINITY;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-8f) {
      if (std::abs(o[axis]) > h) return std::nullopt;
      continue;
    }
    float t0 = (-h - o[axis]) / d[axis], t1 = (h - o[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  if (t_near > t_far || t_far < 0.0f) return std::nullopt;
  return t_near;
}

glm::vec3 expected_floor_color(const BuiltinScene& scene, glm::vec3 point) {
  const Material& m = scene.boxes[0].material;
  const glm::vec3 n(0.0f, 1.0f, 0.0f);
  const glm::vec3 l = -scene.sun.direction;
  const glm::vec3 v = glm::normalize(scene.camera.eye - point);
  const glm::vec3 h = glm::normalize(l + v);
  const glm::vec3 radiance = scene.sun.color * scene.sun.intensity;
  const float n_dot_l = std::max(glm::dot(n, l), 0.0f);
  const float spec = n_dot_l > 0.0f ? std::pow(std::max(glm::dot(n, h), 0.0f), m.shininess) : 0.0f;
  return scene.ambient * m.base_color + m.base_color * radiance * n_dot_l + m.specular * radiance * spec;
}

using OffscreenRender = GpuTest;

TEST_F(OffscreenRender, FloorMatchesLightingFormula) {
  const BuiltinScene scene = make_builtin_scene();
  SceneRenderer renderer(context, scene);
  renderer.resize({width, height});
  {
    vk::FrameRing frames(context);
    for (int i = 0; i < 2; ++i) {  // a second frame exercises the between-frame barriers
      vk::FrameSlot& frame = frames.begin_frame();
      renderer.record(frame.cmd, scene.camera, scene.lens);
      frames.submit();
    }
  }
  const vk::Rgba8Image image = vk::read_rgba8(context, renderer.color_target());
  ASSERT_EQ(image.width, width);

  const glm::mat4 inverse_view_proj =
      glm::inverse(projection_matrix(scene.lens, float(width) / float(height)) * view_matrix(scene.camera));
  int checked = 0, mismatched = 0;
  for (uint32_t y = 0; y < height; y += 3) {
    for (uint32_t x = 0; x < width; x += 3) {
      const glm::vec2 ndc((x + 0.5f) / width * 2.0f - 1.0f, (y + 0.5f) / height * 2.0f - 1.0f);
      const glm::vec4 near_h = inverse_view_proj * glm::vec4(ndc, 0.0f, 1.0f);
      const glm::vec4 far_h = inverse_view_proj * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 origin = glm::vec3(near_h) / near_h.w;
      const glm::vec3 dir = glm::normalize(glm::vec3(far_h) / far_h.w - origin);
      if (dir.y >= -1e-4f) continue;
      const float t_floor = -origin.y / dir.y;
      const glm::vec3 point = origin + t_floor * dir;
      if (std::abs(point.x) > 9.5f || std::abs(point.z) > 9.5f) continue;
      bool occluded = false;  // by a box, or too close to one's silhouette to be sure
      for (size_t b = 1; b < scene.boxes.size(); ++b) {
        const auto t = hit_box(scene.boxes[b], origin, dir, 0.05f);
        occluded = occluded || (t && *t < t_floor);
      }
      if (occluded) continue;

      const glm::vec3 expected = expected_floor_color(scene, point);
      const uint8_t* pixel = image.at(x, y);
      ++checked;
      for (int c = 0; c < 3; ++c) {
        const int want = static_cast<int>(std::lround(srgb_encode(expected[c]) * 255.0f));
        if (std::abs(int(pixel[c]) - want) > tolerance) {
          ++mismatched;
          ADD_FAILURE() << "pixel (" << x << ", " << y << ") channel " << c << ": got "
                        << int(pixel[c]) << ", formula gives " << want;
          break;
        }
      }
    }
  }
  EXPECT_GT(checked, 300) << "too few unoccluded floor pixels were checked to mean anything";
  EXPECT_EQ(mismatched, 0);
}

}  // namespace
}  // namespace sg::test
