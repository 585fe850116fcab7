#include "sandbox/depth_overlay_pass.h"

#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/pipeline.h"
#include "rendergraph/vulkan/vulkan_error.h"
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
  VkSamplerCreateInfo sampler_info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler_info.magFilter = VK_FILTER_NEAREST;
  sampler_info.minFilter = VK_FILTER_NEAREST;
  sampler_info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler_info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler_info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSampler sampler = VK_NULL_HANDLE;
  vk::check(vkCreateSampler(device, &sampler_info, nullptr, &sampler), "vkCreateSampler");
  sampler_ = vk::UniqueSampler(device, sampler);

  const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                             VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = 1;
  set_info.pBindings = &binding;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  vk::check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout),
            "vkCreateDescriptorSetLayout");
  set_layout_ = vk::UniqueDescriptorSetLayout(device, set_layout);

  const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(LensConstants)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vk::check(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout), "vkCreatePipelineLayout");
  pipeline_layout_ = vk::UniquePipelineLayout(device, layout);

  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = depth_overlay_vert;
  desc.fragment_spirv = depth_overlay_frag;
  desc.color_formats = {static_cast<VkFormat>(colour_format)};
  desc.cull_mode = VK_CULL_MODE_NONE;
  desc.layout = layout;
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
