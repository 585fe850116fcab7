// SPDX-License-Identifier: MIT
#include "systems/lighting/depth_prepass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/alpha_test.frag.spv.h"
#include "shaders/depth_prepass.vert.spv.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {
namespace {

constexpr VkShaderStageFlags both_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

}  // namespace

DepthPrepass::DepthPrepass(vk::VulkanContext& context, const GpuTextures& textures)
    : context_(context),
      textures_(textures),
      layout_(context.device(),
              {{bindings::instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, both_stages},
               {bindings::material_textures_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<FrameConstants>(both_stages)),
      pipelines_([layout = layout_.get(), &textures](uint32_t draw_class) {
        if (draw_class & draw_masked) {
          vk::GraphicsPipelineDesc desc = camera_pipeline_desc(alpha_test_frag, {}, layout, "depth prepass");
          desc.fragment_specialization = material_pass_constants(0, 0, textures);
          return for_draw_class(std::move(desc), draw_class);
        }
        vk::GraphicsPipelineDesc desc;
        desc.vertex_spirv = depth_prepass_vert;
        scene_vertex_input(desc, VertexInput::position);
        desc.depth_format = vk::to_vk(camera_depth_format);
        desc.depth_compare = camera_depth_test;
        desc.cull_mode = draw_class & draw_double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
        desc.layout = layout;
        desc.name = "depth prepass";
        return desc;
      }) {}

void DepthPrepass::prepare(const GpuScene& scene) { pipelines_.prepare(context_, scene); }

rg::ImageHandle DepthPrepass::add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height,
                                     const GpuScene& scene, uint32_t slot,
                                     const FrameConstants& constants) const {
  rg::ImageHandle depth;
  graph.add_pass(
      "depth prepass",
      [&](rg::PassBuilder& b) {
        depth = b.write(b.create_image("depth", {width, height, camera_depth_format}),
                        rg::Usage::depth_attachment, camera_depth_clear);
      },
      [this, &scene, slot, constants](const vk::PassRecorder& rec) {
        const VkDescriptorSet set =
            layout_.write(rec.allocate_set(layout_))
                .buffer(bindings::instances_binding, scene.instances(slot).handle())
                .image(bindings::material_textures_binding, textures_.array().view(), textures_.sampler())
                .update();
        scene.draw_camera_pass(rec, pipelines_.get(), layout_, set, constants, slot);
      });
  return depth;
}

}  // namespace sg
