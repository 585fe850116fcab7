#pragma once
// The shadow-map passes: one per 2D shadow (spot, directional, cylinder light) writing that
// light's atlas layer, and per point-light shadow either one layered pass writing all six faces
// of its cube (shadows::CubeShadowMode::layered, needs shaderOutputLayer) or six passes, one per face.
// Every pass draws the casters within its light's reach (ShadowCasterLists) with one indirect
// call.
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

  // Whether the device can render a cube in one pass.
  bool layered_supported() const { return layered_pipeline_.get() != VK_NULL_HANDLE; }

  // CPU side of a frame, after FrameRing::begin_frame returned `slot`: culls each view's
  // casters (or, without cull_casters, gives every view every caster), writes them and the point lights' face
  // matrices, and points the slot's descriptor set at this frame's buffers. `mode` must be the one add_to
  // gets.
  void prepare(uint32_t slot, const shadows::FrameLights& lights, const GpuScene& scene,
               shadows::CubeShadowMode mode, bool cull_casters = true);

  struct Targets {
    rg::ImageHandle maps;
    rg::ImageHandle cubes;
  };
  // Adds the passes for `lights` (as given to prepare) and returns the maps' newest versions.
  // `lights` and `scene` are read when the passes record. layered falls back to six passes when
  // the device cannot do it.
  //
  // kept_casters() says how many caster instances the views kept after culling.
  Targets add_to(rg::RenderGraph& graph, Targets targets, const shadows::FrameLights& lights,
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
  std::vector<CasterView> map_casters_;   // per shadows::FrameLights::maps entry
  std::vector<CasterView> cube_casters_;  // per shadows::FrameLights::cubes entry
  vk::FrameBuffers cube_faces_;           // per point light: six face matrices, at cube_faces_stride_
  VkDeviceSize cube_faces_stride_ = 0;
  std::vector<std::byte> cube_faces_scratch_;
};

}  // namespace sg
