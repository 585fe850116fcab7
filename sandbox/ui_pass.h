#pragma once
// Draws Dear ImGui's output over the frame as one render-graph pass: the library builds the
// windows and their triangles on the CPU (sandbox/ui.h); this pass uploads them and draws them
// with the engine's own pipeline, under dynamic rendering like every other pass.
//
// Contract: an ImGui context must exist when the pass is made (its font atlas is uploaded then)
// and stays the one whose draw data prepare() gets.
#include <cstdint>
#include <vector>

#include <imgui.h>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/unique_handle.h"

namespace sg::vk {
class VulkanContext;
}

namespace sg::sandbox {

class UiPass {
 public:
  UiPass(vk::VulkanContext& context, rg::Format colour_format, uint32_t frames_in_flight);

  // Copies the frame's triangles into the slot's buffers; `draw_data` (ImGui::GetDrawData after
  // ImGui::Render) is read now and when the pass records.
  void prepare(uint32_t slot, const ImDrawData* draw_data);

  // Draws over `colour` and returns its new version; nothing when there is nothing to draw.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle colour, uint32_t slot) const;

 private:
  vk::Image font_atlas_;
  vk::UniqueSampler sampler_;
  vk::PipelineLayout layout_;
  VkDescriptorSet font_set_ = VK_NULL_HANDLE;
  vk::DescriptorSets sets_;
  vk::UniquePipeline pipeline_;
  vk::FrameBuffers vertices_;
  vk::FrameBuffers indices_;
  const ImDrawData* draw_data_ = nullptr;
  std::vector<ImDrawVert> vertex_scratch_;
  std::vector<ImDrawIdx> index_scratch_;
};

}  // namespace sg::sandbox
