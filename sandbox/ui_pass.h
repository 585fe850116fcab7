// SPDX-License-Identifier: MIT
#pragma once
// Draws Dear ImGui's output over the frame as one render-graph pass: the library builds the
// windows and their triangles on the CPU (sandbox/ui.h); this pass uploads them and draws them
// with the engine's own pipeline, under dynamic rendering like every other pass.
//
// Contract: an ImGui context must exist when the pass is made (its font atlas is uploaded then)
// and stays the one whose draw data prepare() gets.
#include <cstdint>
#include <span>
#include <vector>

#include <imgui.h>

#include "rendergraph/core/render_graph.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/frame_buffers.h"
#include "rendergraph/device/fwd.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/unique_handle.h"
#include "sandbox/ui.h"

namespace sg::sandbox {

class UiPass {
 public:
  UiPass(vk::VulkanContext& context, rg::Format color_format, uint32_t frames_in_flight);

  // Copies the frame's triangles into the slot's buffers; `draw_data` (ImGui::GetDrawData after
  // ImGui::Render) and `depth_views` (texture ids 1, 2, ...: SandboxUi::depth_views) are read
  // now and when the pass records.
  void prepare(uint32_t slot, const ImDrawData* draw_data, std::span<const UiDepthView> depth_views);

  // Draws over `color`, reading `shadow_atlas` for the shadow maps shown, and returns
  // `color`'s new version; nothing when there is nothing to draw.
  rg::ImageHandle add_to(rg::RenderGraph& graph, rg::ImageHandle color, rg::ImageHandle shadow_atlas,
                         uint32_t slot) const;

 private:
  vk::Image font_atlas_;
  vk::UniqueSampler sampler_;
  vk::PipelineLayout layout_;
  VkDescriptorSet font_set_ = VK_NULL_HANDLE;
  vk::DescriptorSets sets_;
  vk::UniquePipeline pipeline_;
  vk::UniquePipeline depth_pipeline_;
  vk::UniqueSampler nearest_;
  vk::FrameBuffers vertices_;
  vk::FrameBuffers indices_;
  const ImDrawData* draw_data_ = nullptr;
  std::vector<UiDepthView> depth_views_;
  std::vector<ImDrawVert> vertex_scratch_;
  std::vector<ImDrawIdx> index_scratch_;
};

}  // namespace sg::sandbox
