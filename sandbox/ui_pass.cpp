// SPDX-License-Identifier: MIT
#include "sandbox/ui_pass.h"

#include <algorithm>
#include <cstddef>
#include <span>

#include <glm/glm.hpp>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/upload.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "sandbox_shaders/ui.frag.spv.h"
#include "sandbox_shaders/ui.vert.spv.h"
#include "sandbox_shaders/ui_depth.frag.spv.h"

namespace sg::sandbox {
namespace {

constexpr uint32_t font_binding = 0;

// ui.vert's UiTransform (pixels -> clip space), then ui_depth.frag's DepthView.
struct UiConstants {
  glm::vec2 scale;
  glm::vec2 translate;
  glm::vec4 depth;  // atlas layer, near, far, 1 when linear
};

vk::Image upload_font_atlas(vk::VulkanContext& context) {
  unsigned char* pixels = nullptr;
  int width = 0;
  int height = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  vk::Image atlas(context, {{uint32_t(width), uint32_t(height)},
                            VK_FORMAT_R8G8B8A8_UNORM,
                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                            1,
                            1,
                            VK_IMAGE_VIEW_TYPE_2D,
                            "ui font atlas"});
  vk::UploadBatch upload(context);
  upload.copy_to_image(atlas, 1, std::as_bytes(std::span(pixels, size_t(width) * height * 4)));
  upload.submit();
  return atlas;
}

}  // namespace

UiPass::UiPass(vk::VulkanContext& context, rg::Format color_format, uint32_t frames_in_flight)
    : font_atlas_(upload_font_atlas(context)),
      sampler_(vk::create_sampler(context.device(), VK_FILTER_LINEAR)),
      layout_(context.device(),
              {{font_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<UiConstants>(VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT)),
      sets_(layout_.allocate_sets(1)),
      vertices_(context, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, frames_in_flight, "ui vertices"),
      indices_(context, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, frames_in_flight, "ui indices") {
  font_set_ = sets_.sets[0];
  layout_.write(font_set_).image(font_binding, font_atlas_.view(), sampler_.get()).update();
  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = ui_vert;
  desc.fragment_spirv = ui_frag;
  desc.vertex_bindings = {{0, sizeof(ImDrawVert), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ImDrawVert, pos)},
                            {1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ImDrawVert, uv)},
                            {2, 0, VK_FORMAT_R8G8B8A8_UNORM, offsetof(ImDrawVert, col)}};
  desc.color_formats = {vk::to_vk(color_format)};
  desc.cull_mode = VK_CULL_MODE_NONE;
  desc.blend = vk::Blend::alpha;
  desc.layout = layout_.get();
  desc.name = "ui";
  pipeline_ = vk::create_graphics_pipeline(context, desc);
  desc.fragment_spirv = ui_depth_frag;
  desc.name = "ui shadow map";
  depth_pipeline_ = vk::create_graphics_pipeline(context, desc);
  nearest_ = vk::create_sampler(context.device(), VK_FILTER_NEAREST);
}

void UiPass::prepare(uint32_t slot, const ImDrawData* draw_data, std::span<const UiDepthView> depth_views) {
  draw_data_ = draw_data;
  depth_views_.assign(depth_views.begin(), depth_views.end());
  vertex_scratch_.clear();
  index_scratch_.clear();
  if (draw_data != nullptr) {
    for (int l = 0; l < draw_data->CmdListsCount; ++l) {
      const ImDrawList* list = draw_data->CmdLists[l];
      vertex_scratch_.insert(vertex_scratch_.end(), list->VtxBuffer.begin(), list->VtxBuffer.end());
      index_scratch_.insert(index_scratch_.end(), list->IdxBuffer.begin(), list->IdxBuffer.end());
    }
  }
  vertices_.write(slot, std::span<const ImDrawVert>(vertex_scratch_));
  indices_.write(slot, std::span<const ImDrawIdx>(index_scratch_));
}

rg::ImageHandle UiPass::add_to(rg::RenderGraph& graph, rg::ImageHandle color, rg::ImageHandle shadow_atlas,
                               uint32_t slot) const {
  if (draw_data_ == nullptr || draw_data_->TotalIdxCount == 0) return color;
  const bool maps = !depth_views_.empty();
  graph.add_pass(
      "ui",
      [&](rg::PassBuilder& b) {
        if (maps) b.read(shadow_atlas, rg::Usage::sampled_fragment);
        color = b.write(color, rg::Usage::color_attachment);  // no clear: over the frame
      },
      [this, slot, maps, shadow_atlas](const vk::PassRecorder& rec) {
        VkDescriptorSet atlas_set = VK_NULL_HANDLE;
        if (maps) {
          atlas_set =
              layout_.write(rec.allocate_set(layout_))
                  .image(font_binding,
                         rec.view(shadow_atlas, rg::SubresourceRange::all(), VK_IMAGE_VIEW_TYPE_2D_ARRAY),
                         nearest_.get())
                  .update();
        }
        const ImDrawData& data = *draw_data_;
        const VkExtent2D extent = rec.render_extent();
        rec.set_full_viewport();
        const glm::vec2 scale(2.0f / data.DisplaySize.x, 2.0f / data.DisplaySize.y);
        const glm::vec2 translate =
            glm::vec2(-1.0f) - glm::vec2(data.DisplayPos.x, data.DisplayPos.y) * scale;
        // Texture id 0 is the font atlas; k > 0 the shadow map depth_views_[k - 1].
        intptr_t bound = -1;
        const auto bind = [&](intptr_t texture) {
          if (texture == bound) return;
          bound = texture;
          const bool map = texture > 0 && size_t(texture) <= depth_views_.size();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS,
                            map ? depth_pipeline_.get() : pipeline_.get());
          layout_.bind(rec.cmd(), map ? atlas_set : font_set_);
          glm::vec4 depth(0.0f);
          if (map) {
            const UiDepthView& view = depth_views_[size_t(texture) - 1];
            depth = {float(view.layer), view.near, view.far, view.linear ? 1.0f : 0.0f};
          }
          layout_.push(rec.cmd(), UiConstants{scale, translate, depth});
        };
        const VkBuffer vertex_buffer = vertices_.buffer(slot).handle();
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(rec.cmd(), 0, 1, &vertex_buffer, &zero);
        vkCmdBindIndexBuffer(rec.cmd(), indices_.buffer(slot).handle(), 0,
                             sizeof(ImDrawIdx) == 2 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32);
        int32_t vertex_base = 0;
        uint32_t index_base = 0;
        for (int l = 0; l < data.CmdListsCount; ++l) {
          const ImDrawList* list = data.CmdLists[l];
          for (const ImDrawCmd& command : list->CmdBuffer) {
            // The command's clip rectangle, in framebuffer pixels (the window's points times its
            // framebuffer scale on high-density displays), within the frame.
            const ImVec2 to_pixels = data.FramebufferScale;
            const float x0 = std::max((command.ClipRect.x - data.DisplayPos.x) * to_pixels.x, 0.0f);
            const float y0 = std::max((command.ClipRect.y - data.DisplayPos.y) * to_pixels.y, 0.0f);
            const float x1 =
                std::min((command.ClipRect.z - data.DisplayPos.x) * to_pixels.x, float(extent.width));
            const float y1 =
                std::min((command.ClipRect.w - data.DisplayPos.y) * to_pixels.y, float(extent.height));
            if (x1 <= x0 || y1 <= y0) continue;
            const VkRect2D scissor{{int32_t(x0), int32_t(y0)}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};
            vkCmdSetScissor(rec.cmd(), 0, 1, &scissor);
            bind(reinterpret_cast<intptr_t>(command.TextureId));
            vkCmdDrawIndexed(rec.cmd(), command.ElemCount, 1, index_base + command.IdxOffset,
                             vertex_base + int32_t(command.VtxOffset), 0);
          }
          vertex_base += list->VtxBuffer.Size;
          index_base += uint32_t(list->IdxBuffer.Size);
        }
      });
  return color;
}

}  // namespace sg::sandbox
