#include "systems/forward_pass.h"

#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/pipeline.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "rendergraph/vulkan/vulkan_error.h"
#include "shaders/scene.frag.spv.h"
#include "shaders/scene.vert.spv.h"
#include "systems/gpu_scene.h"
#include "systems/scene/mesh_library.h"

namespace sg {
namespace {

constexpr VkShaderStageFlags shader_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

}  // namespace

ForwardPass::ForwardPass(vk::VulkanContext& context) {
  const VkDevice device = context.device();
  const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, shader_stages,
                                             nullptr};
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = 1;
  set_info.pBindings = &binding;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  vk::check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout),
            "vkCreateDescriptorSetLayout");
  set_layout_ = vk::UniqueDescriptorSetLayout(device, set_layout);

  const VkPushConstantRange push{shader_stages, 0, sizeof(FrameConstants)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vk::check(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout), "vkCreatePipelineLayout");
  pipeline_layout_ = vk::UniquePipelineLayout(device, layout);

  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = scene_vert;
  desc.fragment_spirv = scene_frag;
  desc.vertex_bindings = {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, position))},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, normal))}};
  desc.color_formats = {vk::to_vk(colour_format)};
  desc.depth_format = vk::to_vk(depth_format);
  desc.layout = layout;
  desc.name = "forward";
  pipeline_ = vk::create_graphics_pipeline(context, desc);
}

ForwardTargets ForwardPass::add_to(rg::RenderGraph& graph, rg::ImageHandle colour,
                                   const GpuScene& scene, uint32_t slot,
                                   const FrameConstants& constants) const {
  ForwardTargets targets;
  graph.add_pass(
      "forward", rg::QueueType::graphics,
      [&](rg::PassBuilder& b) {
        const rg::ImageDesc& target = graph.resources()[colour.index].image;
        targets.depth = b.create_image("depth", {target.width, target.height, depth_format});
        targets.depth = b.write(targets.depth, rg::Usage::depth_attachment, rg::ClearValue::depth_of(1.0f));
        targets.colour = b.write(colour, rg::Usage::colour_attachment,
                                 rg::ClearValue::colour_of(0.02f, 0.02f, 0.03f));
      },
      [this, &scene, slot, constants](rg::PassContext& ctx) {
        const vk::PassRecorder& rec = ctx.get<vk::PassRecorder>();
        const VkDescriptorSet set = rec.allocate_set(set_layout_.get());
        const VkDescriptorBufferInfo instances{scene.instances(slot).handle(), 0, VK_WHOLE_SIZE};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = set;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        write.pBufferInfo = &instances;
        vkUpdateDescriptorSets(rec.context().device(), 1, &write, 0, nullptr);

        const VkCommandBuffer cmd = rec.cmd();
        rec.set_full_viewport();
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_.get(), 0, 1,
                                &set, 0, nullptr);
        vkCmdPushConstants(cmd, pipeline_layout_.get(), shader_stages, 0, sizeof(constants), &constants);
        scene.draw(cmd, slot, DrawSet::all);
      });
  return targets;
}

}  // namespace sg
