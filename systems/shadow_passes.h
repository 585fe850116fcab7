#pragma once
// The per-light shadow passes, the baseline ShadowViewBatch is measured against
// (--shadow-views per-light): one pass per 2D shadow (spot, directional, cylinder light) due this
// frame, drawing into that light's atlas tile, and per point-light shadow either one pass for all
// six faces (shadows::CubeShadowMode::layered: shadow_cube_layered.vert moves each face into its
// tile) or six passes, one per face. Each pass clears its tiles and keeps the rest of the atlas
// layer. Every pass draws the casters within its light's reach (ShadowCasterLists, culled on the
// CPU) with one indirect call.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/unique_handle.h"
#include "systems/gpu_scene.h"
#include "systems/shadow_caster_lists.h"
#include "systems/shadows/cube_shadow_mode.h"
#include "systems/shadows/frame_lights.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg {

class ShadowPasses {
 public:
  ShadowPasses(vk::VulkanContext& context, uint32_t frames_in_flight);

  // CPU side of a frame, after FrameRing::begin_frame returned `slot`: culls the casters of each
  // view that renders (or, without cull_casters, gives every view every caster), writes them and
  // the point lights' faces (matrices and tiles in an atlas of `page_size` texels a page), and
  // points the slot's descriptor set at this frame's buffers. `mode` must be the one add_to gets.
  void prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene, uint32_t page_size,
               shadows::CubeShadowMode mode, bool cull_casters = true);

  // Adds the passes of the views of `lights` (as given to prepare) that render, and returns the
  // atlas's newest version. `lights` and `scene` are read when the passes record.
  //
  // kept_casters() says how many caster instances the views kept after culling.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle atlas, const shadows::FrameLights& lights,
                         const GpuScene& scene, uint32_t slot, shadows::CubeShadowMode mode) const;

  uint64_t kept_casters() const { return casters_.kept_instances(); }

 private:
  void draw_casters(VkCommandBuffer cmd, uint32_t slot, VkPipeline pipeline, const glm::mat4& view_projection,
                    const glm::vec4& position_far, uint32_t cube_faces_offset, const GpuScene& scene,
                    CasterView view) const;

  vk::PipelineLayout layout_;
  vk::DescriptorSets slot_sets_;
  vk::UniquePipeline map_pipeline_;
  vk::UniquePipeline face_pipeline_;
  vk::UniquePipeline layered_pipeline_;
  ShadowCasterLists casters_;
  std::vector<CasterView> map_casters_;   // per shadows::FrameLights::maps entry (empty unless it renders)
  std::vector<CasterView> cube_casters_;  // per shadows::FrameLights::cubes entry
  vk::FrameBuffers cube_faces_;           // per point light: its CubeFaces block, at cube_faces_stride_
  VkDeviceSize cube_faces_stride_ = 0;
  std::vector<std::byte> cube_faces_scratch_;
};

}  // namespace sg
