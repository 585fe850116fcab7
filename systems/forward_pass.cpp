#include "systems/forward_pass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "rendergraph/device/resources.h"
#include "shaders/scene.frag.spv.h"
#include "shaders/scene.vert.spv.h"
#include "systems/gpu_scene.h"
#include "systems/gpu_textures.h"
#include "systems/scene/mesh_library.h"
#include "systems/shadow_atlas.h"

namespace sg {
namespace {

constexpr VkShaderStageFlags shader_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

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

ForwardPass::ForwardPass(vk::VulkanContext& context, uint32_t frames_in_flight,
                         const GpuTextures& textures)
    : context_(context) {
  const VkDevice device = context.device();
  nearest_ = vk::create_sampler(device, VK_FILTER_NEAREST);
  compare_ = vk::create_sampler(device, compare_filter(context), true);
  // glTF's default wrapping.
  material_ = vk::create_sampler(device, VK_FILTER_LINEAR, false, VK_SAMPLER_ADDRESS_MODE_REPEAT);

  // shaders/scene_interface.glsl and shaders/lights_interface.glsl.
  const VkDescriptorSetLayoutBinding bindings[] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, shader_stages, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {7, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  set_layout_ = vk::create_set_layout(device, bindings);
  slot_sets_ = vk::allocate_sets(device, set_layout_.get(), bindings, frames_in_flight);
  // The textures never change: bind them once in every slot's set.
  const VkDescriptorImageInfo texture_array{material_.get(), textures.array().view(),
                                            VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL};
  for (const VkDescriptorSet set : slot_sets_.sets) {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.dstBinding = 7;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &texture_array;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
  }
  pipeline_layout_ = vk::create_pipeline_layout(device, set_layout_.get(),
                                                {shader_stages, 0, sizeof(FrameConstants)});

  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = scene_vert;
  desc.fragment_spirv = scene_frag;
  desc.vertex_bindings = {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, position))},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, normal))},
      {2, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, uv))}};
  desc.color_formats = {vk::to_vk(colour_format)};
  desc.depth_format = vk::to_vk(depth_format);
  desc.layout = pipeline_layout_.get();
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
    write.dstSet = slot_sets_.sets[slot];
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
                                &slot_sets_.sets[slot], 0, nullptr);
        vkCmdPushConstants(cmd, pipeline_layout_.get(), shader_stages, 0, sizeof(constants), &constants);
        scene.draw_all(cmd, slot);
      });
  return targets;
}

}  // namespace sg
