// SPDX-License-Identifier: MIT
#include "rendergraph/device/pipeline.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/vulkan_error.h"

namespace sg::vk {

UniqueShaderModule create_shader_module(VulkanContext& context, std::span<const uint32_t> spirv) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module;
  check(vkCreateShaderModule(context.device(), &info, nullptr, &module), "vkCreateShaderModule");
  return UniqueShaderModule(context.device(), module);
}

namespace {

// Specialization constants 0..n-1 from 32-bit values, for one shader stage.
struct Specialization {
  std::vector<VkSpecializationMapEntry> entries;
  VkSpecializationInfo info{};

  explicit Specialization(const std::vector<uint32_t>& values) {
    for (uint32_t id = 0; id < values.size(); ++id) {
      entries.push_back({id, id * static_cast<uint32_t>(sizeof(uint32_t)), sizeof(uint32_t)});
    }
    info = {static_cast<uint32_t>(entries.size()), entries.data(), values.size() * sizeof(uint32_t),
            values.data()};
  }
  Specialization(const Specialization&) = delete;  // info points into entries
  const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
};

VkPipelineColorBlendAttachmentState attachment_blend(Blend blend) {
  VkPipelineColorBlendAttachmentState a{};
  a.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                     VK_COLOR_COMPONENT_A_BIT;
  if (blend == Blend::none) return a;
  const bool alpha = blend == Blend::alpha;
  a.blendEnable = VK_TRUE;
  a.srcColorBlendFactor = alpha ? VK_BLEND_FACTOR_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
  a.dstColorBlendFactor = alpha ? VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
  a.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  a.dstAlphaBlendFactor = a.dstColorBlendFactor;
  a.colorBlendOp = VK_BLEND_OP_ADD;
  a.alphaBlendOp = VK_BLEND_OP_ADD;
  return a;
}

// The pipelines' create flags: capture statistics where the context keeps them.
VkPipelineCreateFlags create_flags(const VulkanContext& context) {
  return context.pipeline_statistics() ? VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR : 0;
}

// Names the pipeline and adds its statistics to the context's log, where it keeps one.
void describe(VulkanContext& context, VkPipeline pipeline, const std::string& name) {
  if (!name.empty())
    context.set_name(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(pipeline), name.c_str());
  if (PipelineStatisticsLog* log = context.pipeline_statistics()) log->capture(pipeline, name);
}

}  // namespace

UniquePipeline create_graphics_pipeline(VulkanContext& context, const GraphicsPipelineDesc& desc) {
  const UniqueShaderModule vertex = create_shader_module(context, desc.vertex_spirv);
  UniqueShaderModule fragment;
  const Specialization fragment_specialization(desc.fragment_specialization);
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  VkPipelineShaderStageCreateInfo stage{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
  stage.module = vertex.get();
  stage.pName = "main";
  stages.push_back(stage);
  if (!desc.fragment_spirv.empty()) {
    fragment = create_shader_module(context, desc.fragment_spirv);
    stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stage.module = fragment.get();
    stage.pSpecializationInfo = fragment_specialization.get();
    stages.push_back(stage);
  }

  VkPipelineVertexInputStateCreateInfo vertex_input{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = static_cast<uint32_t>(desc.vertex_bindings.size());
  vertex_input.pVertexBindingDescriptions = desc.vertex_bindings.data();
  vertex_input.vertexAttributeDescriptionCount = static_cast<uint32_t>(desc.vertex_attributes.size());
  vertex_input.pVertexAttributeDescriptions = desc.vertex_attributes.data();

  VkPipelineInputAssemblyStateCreateInfo input_assembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  input_assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = desc.cull_mode;
  raster.frontFace = desc.front_face;
  raster.lineWidth = 1.0f;

  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = desc.depth_format != VK_FORMAT_UNDEFINED;
  depth.depthWriteEnable = desc.depth_write && depth.depthTestEnable;
  depth.depthCompareOp = desc.depth_compare;

  std::vector<VkPipelineColorBlendAttachmentState> blend_attachments(desc.color_formats.size(),
                                                                     attachment_blend(desc.blend));
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = static_cast<uint32_t>(blend_attachments.size());
  blend.pAttachments = blend_attachments.data();

  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;

  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<uint32_t>(desc.color_formats.size());
  rendering.pColorAttachmentFormats = desc.color_formats.data();
  rendering.depthAttachmentFormat = desc.depth_format;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &input_assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = desc.layout;
  info.flags = create_flags(context);
  VkPipeline pipeline;
  check(vkCreateGraphicsPipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines " + desc.name);
  describe(context, pipeline, desc.name);
  return UniquePipeline(context.device(), pipeline);
}

UniquePipeline create_compute_pipeline(VulkanContext& context, const ComputePipelineDesc& desc) {
  const UniqueShaderModule module = create_shader_module(context, desc.spirv);
  const Specialization specialization(desc.specialization);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.get();
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = specialization.get();
  info.layout = desc.layout;
  info.flags = create_flags(context);
  VkPipeline pipeline;
  check(vkCreateComputePipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateComputePipelines " + desc.name);
  describe(context, pipeline, desc.name);
  return UniquePipeline(context.device(), pipeline);
}

}  // namespace sg::vk
