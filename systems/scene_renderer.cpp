#include "systems/scene_renderer.h"

#include <array>
#include <span>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>

#include "rendergraph/vulkan/barriers.h"
#include "rendergraph/vulkan/context.h"
#include "rendergraph/vulkan/pipeline.h"
#include "rendergraph/vulkan/upload.h"
#include "rendergraph/vulkan/vulkan_error.h"
#include "shaders/scene.frag.spv.h"
#include "shaders/scene.vert.spv.h"
#include "systems/scene/primitive_meshes.h"
#include "systems/scene_gpu_types.h"

namespace sg {

SceneRenderer::SceneRenderer(vk::VulkanContext& context, const BuiltinScene& scene)
    : context_(context), sun_(scene.sun), ambient_(scene.ambient) {
  const VkDevice device = context.device();
  scene::MeshLibrary meshes;
  box_ = meshes.meshes[scene::add_box_mesh(meshes)];
  std::vector<GpuInstance> instances;
  for (const BoxInstance& b : scene.boxes) {
    const glm::mat4 model = model_matrix(b);
    instances.push_back({model, glm::inverseTranspose(model),
                         glm::vec4(b.material.base_color, b.material.specular),
                         glm::vec4(b.material.shininess, 0.0f, 0.0f, 0.0f)});
  }
  instance_count_ = static_cast<uint32_t>(instances.size());

  constexpr VkBufferUsageFlags dst = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  vertices_ = vk::Buffer(context, {meshes.vertices.size() * sizeof(scene::Vertex), dst | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                   vk::MemoryUsage::gpu_only, "box vertices"});
  indices_ = vk::Buffer(context, {meshes.indices.size() * sizeof(uint32_t), dst | VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                  vk::MemoryUsage::gpu_only, "box indices"});
  instances_ = vk::Buffer(context, {instances.size() * sizeof(GpuInstance),
                                    dst | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    vk::MemoryUsage::gpu_only, "scene instances"});
  vk::UploadBatch upload(context);
  upload.copy(vertices_, std::span<const scene::Vertex>(meshes.vertices));
  upload.copy(indices_, std::span<const uint32_t>(meshes.indices));
  upload.copy(instances_, std::span<const GpuInstance>(instances));
  upload.submit();

  VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                       nullptr};
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = 1;
  set_info.pBindings = &binding;
  VkDescriptorSetLayout set_layout;
  vk::check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout),
            "vkCreateDescriptorSetLayout");
  set_layout_ = vk::UniqueDescriptorSetLayout(device, set_layout);

  VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &pool_size;
  VkDescriptorPool pool;
  vk::check(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool), "vkCreateDescriptorPool");
  descriptor_pool_ = vk::UniqueDescriptorPool(device, pool);

  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout;
  vk::check(vkAllocateDescriptorSets(device, &alloc, &descriptor_set_), "vkAllocateDescriptorSets");
  VkDescriptorBufferInfo buffer_info{instances_.handle(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = descriptor_set_;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &buffer_info;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);

  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(FrameConstants)};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout;
  vk::check(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout), "vkCreatePipelineLayout");
  pipeline_layout_ = vk::UniquePipelineLayout(device, layout);

  vk::GraphicsPipelineDesc desc;
  desc.vertex_spirv = scene_vert;
  desc.fragment_spirv = scene_frag;
  desc.vertex_bindings = {{0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, position))},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<uint32_t>(offsetof(scene::Vertex, normal))}};
  desc.color_formats = {color_format};
  desc.depth_format = depth_format;
  desc.layout = layout;
  desc.name = "scene";
  pipeline_ = vk::create_graphics_pipeline(context, desc);
}

void SceneRenderer::resize(VkExtent2D extent) {
  color_ = vk::Image(context_, {extent, color_format,
                                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                1, 1, VK_IMAGE_VIEW_TYPE_2D, "scene colour"});
  depth_ = vk::Image(context_, {extent, depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, 1,
                                1, VK_IMAGE_VIEW_TYPE_2D, "scene depth"});
}

void SceneRenderer::record(VkCommandBuffer cmd, const scene::CameraPose& pose,
                           const scene::Camera& lens) const {
  const VkExtent2D extent = color_.extent();
  context_.begin_label(cmd, "scene");

  // Both targets are fully overwritten: discard old contents (UNDEFINED), but wait for the
  // previous frame's blit of the colour target and depth writes before writing again.
  vk::transition(cmd, {color_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                       VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
  constexpr VkPipelineStageFlags2 depth_stages =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  constexpr VkAccessFlags2 depth_access =
      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  vk::transition(cmd, {depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, depth_stages,
                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depth_stages, depth_access});

  VkRenderingAttachmentInfo color_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color_attachment.imageView = color_.view();
  color_attachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color_attachment.clearValue.color = {{0.02f, 0.02f, 0.03f, 1.0f}};
  VkRenderingAttachmentInfo depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth_attachment.imageView = depth_.view();
  depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth_attachment.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, extent};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color_attachment;
  rendering.pDepthAttachment = &depth_attachment;
  vkCmdBeginRendering(cmd, &rendering);

  const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout_.get(), 0, 1,
                          &descriptor_set_, 0, nullptr);
  const float aspect = float(extent.width) / float(extent.height);
  const FrameConstants constants{projection_matrix(lens, aspect) * view_matrix(pose),
                                 glm::vec4(pose.eye, 1.0f),
                                 glm::vec4(sun_.direction, sun_.intensity),
                                 glm::vec4(sun_.color, ambient_)};
  vkCmdPushConstants(cmd, pipeline_layout_.get(),
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(constants), &constants);
  const VkBuffer vertex_buffer = vertices_.handle();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
  vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, box_.index_count, instance_count_, box_.first_index,
                   static_cast<int32_t>(box_.vertex_offset), 0);
  vkCmdEndRendering(cmd);

  vk::transition(cmd, {color_.handle(), VK_IMAGE_ASPECT_COLOR_BIT,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                       VK_ACCESS_2_TRANSFER_READ_BIT});
  context_.end_label(cmd);
}

}  // namespace sg
