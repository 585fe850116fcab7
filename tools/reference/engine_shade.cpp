// SPDX-License-Identifier: MIT
#include "tools/reference/engine_shade.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <glm/glm.hpp>

#include "ecs/query.h"
#include "systems/gpu/camera.h"
#include "systems/scene/lights.h"
#include "systems/shadows/frame_lights.h"

namespace sg::reference {

// The tone curve (shaders/tone_map.glsl, compiled here as C++): below its knee the picture is the
// linear lit sum. Outside the anonymous namespace: the tool uses only the knee.
namespace glsl {
using namespace glm;
#include "shaders/tone_map.glsl"
}  // namespace glsl

namespace {
// Below this linear value a pixel is too dark for its 8-bit shadowed/unshadowed ratio to mean
// much (one sRGB step is about 5% of it): it is not measured.
constexpr float min_light = 0.03f;
// The isolated light's brightest pixels (this quantile of the lit ones) are scaled to this, below
// the tone curve's knee, where the picture is still linear.
constexpr float target_peak = 0.7f;
constexpr float peak_quantile = 0.995f;
// A saturated picture is dimmed by this and looked at again, at most this many times: over nine
// orders of magnitude, beyond any scene's lights seen so far.
constexpr float saturated_step = 1.0f / 16.0f;
constexpr int max_exposure_attempts = 8;

// The peak_quantile of the lit surface pixels of `picture` (0 if none is lit). Surfaces only: the
// background's clear color is no light's.
float bright_quantile(const std::vector<float>& picture, const vk::DepthImage& depth) {
  std::vector<float> lit;
  for (size_t i = 0; i < picture.size(); ++i) {
    if (depth.depths[i] > camera_far_depth && picture[i] > 0.0f) lit.push_back(picture[i]);
  }
  if (lit.empty()) return 0.0f;
  const auto quantile = lit.begin() + std::ptrdiff_t(double(lit.size() - 1) * peak_quantile);
  std::nth_element(lit.begin(), quantile, lit.end());
  return *quantile;
}

FrameSettings shadow_view(FrameSettings settings) {
  settings.renderer.view = LightingView::shadows;
  settings.animate = false;  // the reference is traced against the scene as it stands
  return settings;
}

}  // namespace

EngineShade::EngineShade(vk::VulkanContext& context, SceneView& scene, const FrameSettings& settings)
    : context_(context), scene_(scene), ring_(context) {
  frame_ = std::make_unique<Frame>(context, scene, shadow_view(settings), ring_.frames_in_flight());
  frame_->resize({settings.width, settings.height});
  frame_->capture_depth();
  const ecs::World& world = scene.scene.world;
  world.query<const scene::ShadowSettings>().for_each(
      [&](ecs::Entity entity, const scene::ShadowSettings& shadow) {
        with_light(world, entity, [&](const auto& light) {
          saved_.push_back({entity, light.intensity, shadow});
        });
      });
}

EngineShade::~EngineShade() {
  ecs::World& world = scene_.scene.world;
  for (const SavedLight& light : saved_) {
    set_intensity(world, light.entity, light.intensity);
    world.get_mut<scene::ShadowSettings>(light.entity) = light.shadow;
  }
}

std::vector<float> EngineShade::render() {
  vk::FrameSlot& slot = ring_.begin_frame();
  frame_->record(slot, double(frames_++) / 60.0);
  ring_.submit();
  ring_.wait_idle();
  const vk::Rgba8Image image = vk::read_rgba8(context_, frame_->image());
  std::vector<float> out(size_t{image.width} * image.height);
  // White light on white surfaces: every channel holds the same value.
  for (size_t i = 0; i < out.size(); ++i) out[i] = vk::srgb_to_linear(image.pixels[i * 4 + 1]);
  return out;
}

vk::DepthImage EngineShade::depth() {
  render();
  return frame_->read_captured_depth();
}

void EngineShade::isolate(const ReferenceLight& light) {
  ecs::World& world = scene_.scene.world;
  float intensity = 0.0f;
  for (const SavedLight& saved : saved_) {
    set_intensity(world, saved.entity, 0.0f);
    if (saved.entity == light.entity) intensity = saved.intensity;
  }
  isolated_ = &light;
  scene::ShadowSettings& shadow = world.get_mut<scene::ShadowSettings>(light.entity);
  shadow.casts_shadow = false;
  set_intensity(world, light.entity, intensity);
  // Scale the light so that its brightest pixels sit below the knee: the ratio of two pictures is
  // only the visibility where the tone curve is the identity. A saturated picture says nothing of
  // how far above the knee it is, so that case steps down by a fixed factor and looks again.
  float scale = 1.0f;
  for (int attempt = 0;; ++attempt) {
    unshadowed_ = render();
    const float peak = bright_quantile(unshadowed_, frame_->read_captured_depth());
    if (peak <= 0.0f || attempt == max_exposure_attempts) break;
    const float factor = peak >= glsl::TONE_KNEE ? saturated_step : target_peak / peak;
    if (factor > 0.8f && factor < 1.25f) break;
    scale *= factor;
    set_intensity(world, light.entity, intensity * scale);
  }
}

const scene::ShadowSettings& EngineShade::isolated_settings() const {
  for (const SavedLight& saved : saved_) {
    if (saved.entity == isolated_->entity) return saved.shadow;
  }
  throw std::logic_error("EngineShade: the isolated light is not one of the scene's");
}

EngineVisibility EngineShade::visibility(const scene::ShadowSettings& shadow) {
  ecs::World& world = scene_.scene.world;
  world.get_mut<scene::ShadowSettings>(isolated_->entity) = shadow;
  const std::vector<float> shadowed = render();
  EngineVisibility out;
  out.visibility.assign(shadowed.size(), 0.0f);
  out.measured.assign(shadowed.size(), false);
  for (size_t i = 0; i < shadowed.size(); ++i) {
    const float unshadowed = unshadowed_[i];
    if (unshadowed < min_light || unshadowed >= glsl::TONE_KNEE) continue;
    out.measured[i] = true;
    out.visibility[i] = std::clamp(shadowed[i] / unshadowed, 0.0f, 1.0f);
  }
  const uint64_t key = shadows::light_key(isolated_->entity);
  const shadows::FrameLights& lights = frame_->renderer().lights();
  for (const shadows::ShadowMapView& map : lights.maps) {
    if (map.key == key) out.resolution = map.resolution;
  }
  for (const shadows::ShadowCubeView& cube : lights.cubes) {
    if (cube.key == key) out.resolution = cube.resolution;
  }
  return out;
}

}  // namespace sg::reference
