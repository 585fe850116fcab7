#pragma once
// Tiled forward lighting (shaders/scene_tiled.frag): after a depth prepass (DepthPrepass) and
// light culling on it (LightTilesPass), every drawable shaded once with the lights of its pixel's tile, group
// by group. The pipeline is specialized on the light groups the frame has (bit g for group g), so it holds
// only their shadow code; one is compiled per set of groups, when first needed.
#include <array>
#include <cstdint>
#include <unordered_map>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "systems/camera_pipelines.h"
#include "systems/forward_pass.h"
#include "systems/light_resources.h"
#include "systems/light_tiles_pass.h"
#include "systems/lighting_path.h"
#include "systems/scene_gpu_types.h"
#include "systems/shadows/light_groups.h"

namespace sg::vk {
class Buffer;
class VulkanContext;
}  // namespace sg::vk

namespace sg {

class GpuScene;
class GpuTextures;

class TiledForwardPass {
 public:
  // `textures` must outlive the pass.
  TiledForwardPass(vk::VulkanContext& context, const GpuTextures& textures);

  // Makes the pipelines for the groups that have lights (group_begin as in shadows::FrameLights),
  // `view` and the draw classes `scene` has.
  void prepare(const std::array<uint32_t, shadows::light_group_count + 1>& group_begin, LightingView view,
               const GpuScene& scene);

  // Shades every drawable where the prepass left it, into a new lit sum. `constants.counts.y`
  // must be the tiles across the screen. `lights` and `scene` are read when the pass records.
  ForwardTargets add_to(rg::RenderGraph& graph, rg::ImageHandle depth, const LightTiles& tiles,
                        rg::ImageHandle atlas, const vk::Buffer& lights, const GpuScene& scene, uint32_t slot,
                        const FrameConstants& constants) const;

 private:
  vk::VulkanContext& context_;
  const GpuTextures& textures_;
  LightResources light_resources_;
  vk::PipelineLayout layout_;
  std::unordered_map<uint32_t, CameraPipelines> pipelines_;  // by pipeline_key
  uint32_t groups_present_ = 0;
  LightingView view_ = LightingView::lit;
};

}  // namespace sg
