// SPDX-License-Identifier: MIT
#include "systems/lighting/gbuffer_pass.h"

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/gbuffer.frag.spv.h"
#include "shaders/gbuffer_lit_sum.frag.spv.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"

namespace sg {
namespace {

using namespace bindings;
constexpr VkShaderStageFlags both_stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr rg::Format normal_format = rg::Format::rgba16_sfloat;
constexpr rg::Format albedo_format = rg::Format::rgba8_unorm;

}  // namespace

GBufferPass::GBufferPass(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures,
                         bool writes_lit_sum)
    : context_(context),
      writes_lit_sum_(writes_lit_sum),
      layout_(context.device(),
              {{instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, both_stages},
               {material_textures_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<FrameConstants>(both_stages)),
      slot_sets_(layout_.allocate_sets(frames_in_flight)),
      pipelines_([writes_lit_sum, layout = layout_.get(), &textures](uint32_t draw_class) {
        std::vector<VkFormat> formats{vk::to_vk(normal_format), vk::to_vk(albedo_format)};
        if (writes_lit_sum) formats.push_back(vk::to_vk(GBuffer::lit_sum_format));
        vk::GraphicsPipelineDesc desc =
            camera_pipeline_desc(writes_lit_sum ? std::span<const uint32_t>(gbuffer_lit_sum_frag)
                                                : std::span<const uint32_t>(gbuffer_frag),
                                 std::move(formats), layout, "g-buffer");
        desc.fragment_specialization = material_pass_constants(0, 0, textures);
        return for_draw_class(std::move(desc), draw_class);
      }) {
  for (const VkDescriptorSet set : slot_sets_.sets) {
    layout_.write(set).image(material_textures_binding, textures.array().view(), textures.sampler()).update();
  }
}

void GBufferPass::prepare(uint32_t slot, const GpuScene& scene) {
  layout_.write(slot_sets_.sets[slot]).buffer(instances_binding, scene.instances(slot).handle()).update();
  pipelines_.prepare(context_, scene);
}

GBuffer GBufferPass::add_to(rg::RenderGraph& graph, uint32_t width, uint32_t height, const GpuScene& scene,
                            uint32_t slot, const FrameConstants& constants) const {
  GBuffer g;
  graph.add_pass(
      "g-buffer",
      [&](rg::PassBuilder& b) {
        const auto screen_image = [&](const char* name, rg::Format format) {
          return b.create_image(name, {width, height, format});
        };
        // Normal and albedo are read only where the depth holds a surface (deferred_surface,
        // lighting_ambient.comp): left uncleared, the background's texels stay undefined. The
        // two clears took 0.44 ms of the H200's 1.20 ms G-buffer of `default` at 1920x1080
        // (2026-12-04, docs/PERFORMANCE.md).
        g.normal = b.write(screen_image("g-buffer normal", normal_format), rg::Usage::color_attachment);
        g.albedo = b.write(screen_image("g-buffer albedo", albedo_format), rg::Usage::color_attachment);
        if (writes_lit_sum_) {
          g.lit_sum = b.write(
              screen_image("lit sum", GBuffer::lit_sum_format), rg::Usage::color_attachment,
              rg::ClearValue::color_of(background_color.r, background_color.g, background_color.b, 1.0f));
        }
        g.depth = b.write(screen_image("depth", camera_depth_format), rg::Usage::depth_attachment,
                          camera_depth_clear);
      },
      [this, &scene, slot, constants](const vk::PassRecorder& rec) {
        scene.draw_camera_pass(rec, pipelines_.get(), layout_, slot_sets_.sets[slot], constants, slot);
      });
  return g;
}

}  // namespace sg
