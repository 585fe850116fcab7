#pragma once
// Renders an ECS scene through the render graph. Each frame:
//
//   renderer.update(slot);                         // CPU: world -> this slot's GPU buffers
//   ForwardTargets t = renderer.add_passes(graph, colour, slot, pose, lens);
//
// `colour` is any colour image of ForwardPass::colour_format (imported or transient); the
// returned handles let later passes (overlays, copies, presentation) read the results.
#include <cstdint>

#include "rendergraph/core/render_graph.h"
#include "systems/forward_pass.h"
#include "systems/gpu_scene.h"
#include "systems/scene/camera.h"
#include "systems/scene/scene.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

class SceneRenderer {
 public:
  // ALGORITHMS.md section 2's default ambient term kA * IA.
  static constexpr float ambient = 0.15f;

  // `scene` must outlive the renderer; its mesh library is uploaded now.
  SceneRenderer(vk::VulkanContext& context, scene::Scene& scene, uint32_t frames_in_flight);

  // Gathers the world's drawables into the slot's buffers. Call after FrameRing::begin_frame
  // returned `slot` and after the frame's transform update.
  void update(uint32_t slot);

  ForwardTargets add_passes(rg::RenderGraph& graph, rg::ImageHandle colour, uint32_t slot,
                            const scene::CameraPose& pose, const scene::Camera& lens) const;

  const GpuScene& gpu_scene() const { return gpu_scene_; }

 private:
  scene::Scene& scene_;
  GpuScene gpu_scene_;
  ForwardPass forward_;
};

}  // namespace sg
