#include "sandbox/depth_overlay_pass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/device/pipeline.h"
#include "sandbox_shaders/depth_overlay.frag.spv.h"
#include "sandbox_shaders/depth_overlay.vert.spv.h"

namespace sg::sandbox {
namespace {

struct LensConstants {
  float znear;
  float zfar;
  float shown_distance;
};

// Depths beyond this many metres all show black; a room or a hall reads well at this scale.
constexpr float shown_distance = 40.0f;

}  // namespace

DepthOverlayPass::DepthOverlayPass(vk::VulkanContext& context, rg::Format colour_format) {
  const VkDevice device = context.device();
  sampler_ = vk::create_sampler(device, VK_FILTER_NEAREST);
  const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                             VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  set_layout_ = vk::create_set_layout(device, {&binding, 1});
  pipeline_layout_ = vk::create_pipeline_layout(
      device, set_layout_.get(), {VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(LensConstants)});

  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = depth_overlay_vert;
  desc.fragment_spirv = depth_overlay_frag;
  desc.color_formats = {static_cast<VkFormat>(colour_format)};
  desc.cull_mode = VK_CULL_MODE_NONE;
  desc.layout = pipeline_layout_.get();
  desc.name = "depth overlay";
  pipeline_ = vk::create_graphics_pipeline(context, desc);
}

rg::ImageHandle DepthOverlayPass::add_to(rg::RenderGraph& graph, rg::ImageHandle depth,
                                         rg::ImageHandle colour, const scene::Camera& lens) const {
  graph.add_pass(
      "depth overlay", rg::QueueType::graphics,
      [&](rg::PassBuilder& b) {
        b.read(depth, rg::Usage::sampled_fragment);
        colour = b.write(colour, rg::Usage::colour_attachment);  // no clear: draw over the frame
      },
      [this, depth, lens](rg::PassContext& ctx) {
        const vk::PassRecorder& rec = ctx.get<vk::PassRecorder>();
        const VkDescriptorSet set = rec.allocate_set(set_layout_.get());
        const VkDescriptorImageInfo image{sampler_.get(), rec.view(depth),
                                          VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = set;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        write.pImageInfo = &image;
        vkUpdateDescriptorSets(rec.context().device(), 1, &write, 0, nullptr);

        // The bottom-right quarter of the frame.
        const VkExtent2D full = rec.render_extent();
        const VkExtent2D quarter{full.width / 2, full.height / 2};
        const VkViewport viewport{float(full.width - quarter.width), float(full.height - quarter.height),
                                  float(quarter.width), float(quarter.height), 0.0f, 1.0f};
        const VkRect2D scissor{{int32_t(full.width - quarter.width), int32_t(full.height - quarter.height)},
                               quarter};
        const VkCommandBuffer cmd = rec.cmd();
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_.get(), 0, 1,
                                &set, 0, nullptr);
        const LensConstants constants{lens.znear, lens.zfar, shown_distance};
        vkCmdPushConstants(cmd, pipeline_layout_.get(), VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(constants), &constants);
        vkCmdDraw(cmd, 3, 1, 0, 0);
      });
  return colour;
}

}  // namespace sg::sandbox
