#pragma once
// Renders an ECS scene through the render graph: the shadow maps of every shadow-casting light,
// then the lighting pass. Each frame:
//
//   renderer.update(slot);                     // CPU: world -> this slot's GPU buffers
//   ForwardTargets t = renderer.add_passes(graph, states, colour, slot, pose, lens);
//   ... compile, execute, states.remember(plan) ...
//
// `colour` is any colour image of ForwardPass::colour_format (imported or transient); the
// returned handles let later passes (overlays, copies, presentation) read the results. The
// shadow images are imported as "shadow atlas" and "shadow cubes"; `states` carries their
// layouts between frames (the renderer forgets them itself when it recreates an image).
#include <cstdint>

#include "rendergraph/core/imported_states.h"
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/vulkan/graph_executor.h"
#include "systems/forward_pass.h"
#include "systems/frame_lights.h"
#include "systems/gpu_scene.h"
#include "systems/gpu_textures.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"
#include "systems/shadow_atlas.h"
#include "systems/shadow_passes.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

struct RendererSettings {
  LightOverrides lights;
  CubeShadowMode cube_shadows = CubeShadowMode::layered;
};

class SceneRenderer {
 public:
  // ALGORITHMS.md section 2's default ambient term kA * IA.
  static constexpr float ambient = 0.15f;

  // `scene` must outlive the renderer; its mesh library is uploaded now.
  SceneRenderer(vk::VulkanContext& context, scene::Scene& scene, uint32_t frames_in_flight,
                const RendererSettings& settings = {});

  // Gathers the world's drawables and lights into the slot's buffers and fits the shadow
  // storage to the lights. Call after FrameRing::begin_frame returned `slot` and after the
  // frame's transform update.
  void update(uint32_t slot);

  ForwardTargets add_passes(rg::RenderGraph& graph, rg::ImportedStates& states,
                            rg::ImageHandle colour, uint32_t slot, const scene::CameraPose& pose,
                            const scene::Camera& lens);

  // Binds the shadow images imported by the last add_passes.
  void bind_imports(vk::ImportedResources& imports) const;

  const GpuScene& gpu_scene() const { return gpu_scene_; }
  const FrameLights& lights() const { return lights_; }
  const ShadowAtlas& atlas() const { return atlas_; }
  const RendererSettings& settings() const { return settings_; }

 private:
  scene::Scene& scene_;
  RendererSettings settings_;
  GpuScene gpu_scene_;
  GpuTextures textures_;
  ShadowAtlas atlas_;
  ShadowPasses shadow_passes_;
  ForwardPass forward_;
  vk::FrameBuffers light_records_;
  FrameLights lights_;
  ShadowAtlas::Changes recreated_;  // since the last add_passes
  ShadowPasses::Targets imported_;  // the last add_passes's imports
};

}  // namespace sg
