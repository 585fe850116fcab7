// SPDX-License-Identifier: MIT
#pragma once
// The engine's shadow of one light at a time, measured from the engine's own frame: the
// shadow-only view (LightingView::shadows: white diffuse surfaces, no ambient, the shadow at full
// density) rendered with every other light dark, once with the light's shadow and once without.
// In linear light the ratio of the two is the light's visibility, 1 - shade, at every pixel the
// light reaches, whatever its falloff, cone or N.L.
#include <cstdint>
#include <memory>
#include <vector>

#include "rendergraph/device/frame_ring.h"
#include "rendergraph/device/readback.h"
#include "systems/frame/frame.h"
#include "systems/frame/frame_settings.h"
#include "systems/frame/scene_view.h"
#include "systems/scene/shadow_settings.h"
#include "tools/reference/reference_lights.h"

namespace sg::reference {

struct EngineVisibility {
  std::vector<float> visibility;  // 1 lit .. 0 shadowed; 0 where not measured
  std::vector<bool> measured;     // the light adds enough, without tone compression, to measure
  uint32_t resolution = 0;        // the light's shadow map (a cube face's) side in this frame
};

class EngineShade {
 public:
  // Renders `scene` (animation off) at settings.width x settings.height. The scene's lights are
  // changed while a light is isolated and restored when this is destroyed.
  EngineShade(vk::VulkanContext& context, SceneView& scene, const FrameSettings& settings);
  ~EngineShade();
  EngineShade(const EngineShade&) = delete;
  EngineShade& operator=(const EngineShade&) = delete;

  // The camera's depth buffer of the scene's frame, every light as the scene has it.
  vk::DepthImage depth();

  // Makes `light` the only one shining, at an intensity that keeps its brightest pixels below the
  // tone curve's knee, and renders it without a shadow.
  void isolate(const ReferenceLight& light);
  // The isolated light's shadow settings as the scene has them.
  const scene::ShadowSettings& isolated_settings() const;
  // The isolated light's visibility with `shadow` as its settings.
  EngineVisibility visibility(const scene::ShadowSettings& shadow);

 private:
  // Renders one frame and returns the linear (pre-tone-map) shadow-only picture.
  std::vector<float> render();

  vk::VulkanContext& context_;
  SceneView& scene_;
  vk::FrameRing ring_;
  std::unique_ptr<Frame> frame_;
  uint64_t frames_ = 0;
  struct SavedLight {
    ecs::Entity entity;
    float intensity;
    scene::ShadowSettings shadow;
  };
  std::vector<SavedLight> saved_;  // every light as the scene had it
  const ReferenceLight* isolated_ = nullptr;
  std::vector<float> unshadowed_;
};

}  // namespace sg::reference
