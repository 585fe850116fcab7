#include "systems/forward_pass.h"

#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/pipeline.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "rendergraph/vulkan/resources.h"
#include "rendergraph/vulkan/vulkan_error.h"
#include "shaders/scene.frag.spv.h"
#include "shaders/scene.vert.spv.h"
#include "systems/gpu_scene.h"
#include "systems/scene/mesh_library.h"
#include "systems/shadow_atlas.h"

namespace sg {
namespace {

constexpr VkShaderStageFlags shader_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

vk::UniqueSampler create_sampler(VkDevice device, VkFilter filter, bool compare) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  // shadow_sampling.glsl: the comparison returns 1 where the receiver is lit.
  info.compareEnable = compare ? VK_TRUE : VK_FALSE;
  info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkSampler sampler = VK_NULL_HANDLE;
  vk::check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler");
  return vk::UniqueSampler(device, sampler);
}

// Hardware 2x2 PCF needs linear filtering of the depth format; fall back to one tap without it.
VkFilter compare_filter(const vk::VulkanContext& context) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), vk::to_vk(ShadowAtlas::depth_format),
                                      &properties);
  return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)
             ? VK_FILTER_LINEAR
             : VK_FILTER_NEAREST;
}

}  // namespace

ForwardPass::ForwardPass(vk::VulkanContext& context, uint32_t frames_in_flight)
    : context_(context), slot_sets_(frames_in_flight) {
  const VkDevice device = context.device();
  nearest_ = create_sampler(device, VK_FILTER_NEAREST, false);
  compare_ = create_sampler(device, compare_filter(context), true);

  // shaders/scene_interface.glsl and shaders/lights_interface.glsl.
  const VkDescriptorSetLayoutBinding bindings[] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, shader_stages, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = static_cast<uint32_t>(std::size(bindings));
  set_info.pBindings = bindings;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  vk::check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout),
            "vkCreateDescriptorSetLayout");
  set_layout_ = vk::UniqueDescriptorSetLayout(device, set_layout);

  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2 * frames_in_flight},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * frames_in_flight}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = frames_in_flight;
  pool_info.poolSizeCount = 2;
  pool_info.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  vk::check(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool), "vkCreateDescriptorPool");
  pool_ = vk::UniqueDescriptorPool(device, pool);
  const std::vector<VkDescriptorSetLayout> layouts(frames_in_flight, set_layout);
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = frames_in_flight;
  alloc.pSetLayouts = layouts.data();
  vk::check(vkAllocateDescriptorSets(device, &alloc, slot_sets_.data()), "vkAllocateDescriptorSets");

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

void ForwardPass::prepare(uint32_t slot, const GpuScene& scene, const vk::Buffer& lights,
                          const ShadowAtlas& atlas) {
  const VkDescriptorBufferInfo instances{scene.instances(slot).handle(), 0, VK_WHOLE_SIZE};
  const VkDescriptorBufferInfo light_records{lights.handle(), 0, VK_WHOLE_SIZE};
  const VkImageView maps = atlas.maps().views().get(
      {0, 1, 0, atlas.maps_desc().layers, VK_IMAGE_VIEW_TYPE_2D_ARRAY});
  const VkImageView cubes = atlas.cubes().views().get(
      {0, 1, 0, atlas.cubes_desc().layers, VK_IMAGE_VIEW_TYPE_CUBE_ARRAY});
  // The layout the graph gives sampled images (sync2's generic read-only layout).
  constexpr VkImageLayout sampled = VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL;
  const VkDescriptorImageInfo images[] = {{nearest_.get(), maps, sampled},
                                          {compare_.get(), maps, sampled},
                                          {nearest_.get(), cubes, sampled}};
  VkWriteDescriptorSet writes[5];
  for (uint32_t binding = 0; binding < 5; ++binding) {
    VkWriteDescriptorSet& write = writes[binding];
    write = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = slot_sets_[slot];
    write.dstBinding = binding;
    write.descriptorCount = 1;
    if (binding < 2) {
      write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      write.pBufferInfo = binding == 0 ? &instances : &light_records;
    } else {
      write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      write.pImageInfo = &images[binding - 2];
    }
  }
  vkUpdateDescriptorSets(context_.device(), 5, writes, 0, nullptr);
}

ForwardTargets ForwardPass::add_to(rg::RenderGraph& graph, rg::ImageHandle colour,
                                   rg::ImageHandle maps, rg::ImageHandle cubes,
                                   const GpuScene& scene, uint32_t slot,
                                   const FrameConstants& constants) const {
  ForwardTargets targets;
  graph.add_pass(
      "forward", rg::QueueType::graphics,
      [&](rg::PassBuilder& b) {
        b.read(maps, rg::Usage::sampled_fragment);
        b.read(cubes, rg::Usage::sampled_fragment);
        const rg::ImageDesc& target = graph.resources()[colour.index].image;
        targets.depth = b.create_image("depth", {target.width, target.height, depth_format});
        targets.depth = b.write(targets.depth, rg::Usage::depth_attachment, rg::ClearValue::depth_of(1.0f));
        targets.colour = b.write(colour, rg::Usage::colour_attachment,
                                 rg::ClearValue::colour_of(0.02f, 0.02f, 0.03f));
      },
      [this, &scene, slot, constants](rg::PassContext& ctx) {
        const vk::PassRecorder& rec = ctx.get<vk::PassRecorder>();
        const VkCommandBuffer cmd = rec.cmd();
        rec.set_full_viewport();
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_.get(), 0, 1,
                                &slot_sets_[slot], 0, nullptr);
        vkCmdPushConstants(cmd, pipeline_layout_.get(), shader_stages, 0, sizeof(constants), &constants);
        scene.draw(cmd, slot, DrawSet::all);
      });
  return targets;
}

}  // namespace sg
