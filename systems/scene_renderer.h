#pragma once
// Renders an ECS scene through the render graph: the shadow maps of every shadow-casting light,
// then the lighting pass. It takes three of the frame's phases (SandboxFrame::record names all
// five):
//
//   renderer.gather(world);          // read the world: drawables and lights, on the CPU
//   renderer.prepare(slot);          // shadow storage, caster culling, this slot's GPU buffers
//   ForwardTargets t = renderer.add_passes(graph, imports, colour, slot, pose, lens);
//
// `colour` is any colour image of ForwardPass::colour_format (imported or transient); the
// returned handles let later passes (overlays, copies, presentation) read the results. The
// shadow images are imported through `imports` as "shadow maps" and "shadow cubes".
#include <cstdint>

#include "ecs/world.h"
#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/vulkan/graph_imports.h"
#include "systems/forward_pass.h"
#include "systems/gpu_scene.h"
#include "systems/gpu_textures.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"
#include "systems/shadow_map_arrays.h"
#include "systems/shadow_passes.h"
#include "systems/shadows/cube_shadow_mode.h"
#include "systems/shadows/frame_lights.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

struct RendererSettings {
  shadows::LightOverrides lights;
  shadows::CubeShadowMode cube_shadows = shadows::CubeShadowMode::layered;
};

class SceneRenderer {
 public:
  // ALGORITHMS.md section 2's default ambient term kA * IA.
  static constexpr float ambient = 0.15f;

  // Uploads `scene`'s meshes and textures; the scene's world is read by gather() each frame.
  SceneRenderer(vk::VulkanContext& context, const scene::Scene& scene, uint32_t frames_in_flight,
                const RendererSettings& settings = {});

  // Reads the world's drawables and lights into CPU lists. Transforms must be up to date.
  void gather(const ecs::World& world);
  // Fits the shadow storage to the gathered lights and writes everything the frame's passes read
  // into the slot's buffers and descriptor sets. Call after FrameRing::begin_frame gave `slot`.
  void prepare(uint32_t slot);
  // Declares the shadow passes and the lighting pass.
  ForwardTargets add_passes(rg::RenderGraph& graph, vk::GraphImports& imports, rg::ImageHandle colour,
                            uint32_t slot, const scene::CameraPose& pose, const scene::Camera& lens);

  const GpuScene& gpu_scene() const { return gpu_scene_; }
  const shadows::FrameLights& lights() const { return lights_; }
  const ShadowMapArrays& shadow_maps() const { return shadow_maps_; }
  const RendererSettings& settings() const { return settings_; }

 private:
  RendererSettings settings_;
  GpuScene gpu_scene_;
  GpuTextures textures_;
  ShadowMapArrays shadow_maps_;
  ShadowPasses shadow_passes_;
  ForwardPass forward_;
  vk::FrameBuffers light_records_;
  shadows::FrameLights lights_;
};

}  // namespace sg
