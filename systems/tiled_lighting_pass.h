#pragma once
// Tiled deferred lighting: a pass starting the lit sum from the ambient term and the background
// (shaders/lighting_ambient.glsl), then for each light group that has lights one pass with that
// group's shadow code compiled in (shaders/tiled_lighting.glsl), over the tiles that have lights
// of the group (an indirect dispatch or draw from LightTilesPass), adding them to the lit sum.
// The passes are compute dispatches or fragment passes (DeferredPasses, lighting_path.h).
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/gbuffer_pass.h"
#include "systems/light_resources.h"
#include "systems/light_tiles_pass.h"
#include "systems/lighting_path.h"
#include "systems/shadows/light_groups.h"

namespace sg::vk {
class Buffer;
class VulkanContext;
}  // namespace sg::vk

namespace sg {

class TiledLightingPass {
 public:
  // `passes` automatic is resolved for the context's device (passes() says how).
  TiledLightingPass(vk::VulkanContext& context, DeferredPasses passes);

  // Compiles the pipelines of the groups that have lights (group_begin as in
  // shadows::FrameLights) and that it has not compiled yet: each holds one algorithm's shadow
  // code, and a scene rarely uses all eleven.
  // The pipelines are made for `view`, which add_to then uses.
  void prepare(const std::array<uint32_t, shadows::light_group_count + 1>& group_begin, LightingView view);

  static constexpr rg::Format lit_sum_format = rg::Format::rgba16_sfloat;

  // Adds the ambient pass, which creates the lit sum, and one pass per group with lights
  // (group_begin as in shadows::FrameLights); returns the lit sum's newest version. `lights` must
  // live until the frame is recorded. Positions come from the depth buffer through the camera's
  // `view_projection`; `ambient` is the ambient term kA * IA.
  rg::ImageHandle add_to(rg::RenderGraph& graph, const GBuffer& gbuffer, const LightTiles& tiles,
                         rg::ImageHandle atlas, const vk::Buffer& lights,
                         const std::array<uint32_t, shadows::light_group_count + 1>& group_begin,
                         const glm::mat4& view_projection, const glm::vec3& camera_position,
                         float ambient) const;

  // compute or fragment.
  DeferredPasses passes() const { return passes_; }

 private:
  bool in_compute() const { return passes_ == DeferredPasses::compute; }

  vk::VulkanContext& context_;
  DeferredPasses passes_;
  VkShaderStageFlags stages_;  // what reads the passes' resources
  LightResources light_resources_;
  vk::UniqueSampler nearest_;  // G-buffer reads
  vk::PipelineLayout ambient_layout_;
  vk::UniquePipeline ambient_pipeline_;
  vk::PipelineLayout layout_;
  // By LightingView, then group.
  std::array<std::array<vk::UniquePipeline, shadows::light_group_count>, 2> pipelines_;
  LightingView view_ = LightingView::lit;
};

}  // namespace sg
