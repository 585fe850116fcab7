#include "systems/tiled_lighting_pass.h"

#include <string>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "shaders/lighting_ambient.comp.spv.h"
#include "shaders/tiled_lighting.comp.spv.h"
#include "systems/scene_gpu_types.h"
#include "systems/shader_bindings.h"

namespace sg {
namespace {

using namespace bindings;
constexpr VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;

struct AmbientConstants {
  glm::vec4 background_ambient;  // rgb: the background colour; w: the ambient term
  glm::uvec4 screen;             // width, height
};

struct LightingConstants {
  glm::mat4 inverse_view_projection;
  glm::vec4 camera_position;
  glm::uvec4 screen;  // width, height, tiles across, tiles in all
};

std::string group_name(uint32_t group) {
  switch (shadows::group_shadow_kind(group)) {
    case shadows::ShadowKind::none: return "unshadowed";
    case shadows::ShadowKind::map:
      return "2d " + std::string(scene::to_string(shadows::group_algorithm(group)));
    case shadows::ShadowKind::cube:
      return "cube " + std::string(scene::to_string(shadows::group_algorithm(group)));
  }
  return "group " + std::to_string(group);
}

}  // namespace

TiledLightingPass::TiledLightingPass(vk::VulkanContext& context)
    : context_(context),
      light_resources_(context),
      nearest_(vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
      ambient_layout_(context.device(),
                      {{gbuffer_albedo_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute},
                       {scene_depth_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute},
                       {hdr_binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, compute}},
                      vk::push_constants<AmbientConstants>(compute)),
      ambient_pipeline_(vk::create_compute_pipeline(
          context, {lighting_ambient_comp, {}, ambient_layout_.get(), "lighting ambient"})),
      layout_(context.device(),
              LightResources::bindings(
                  compute, {{scene_depth_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute},
                            {gbuffer_normal_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute},
                            {gbuffer_albedo_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, compute},
                            {hdr_binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, compute},
                            {tile_lights_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute},
                            {tile_ranges_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute},
                            {group_tiles_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, compute}}),
              vk::push_constants<LightingConstants>(compute)) {}

void TiledLightingPass::prepare(const std::array<uint32_t, shadows::light_group_count + 1>& group_begin,
                                LightingView view) {
  view_ = view;
  auto& pipelines = pipelines_[static_cast<uint32_t>(view)];
  for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
    if (group_begin[group + 1] == group_begin[group] || pipelines[group]) continue;
    pipelines[group] = vk::create_compute_pipeline(context_, {tiled_lighting_comp,
                                                              {group, static_cast<uint32_t>(view)},
                                                              layout_.get(),
                                                              "tiled lighting " + group_name(group)});
  }
}

rg::ImageHandle TiledLightingPass::add_to(
    rg::RenderGraph& graph, const GBuffer& gbuffer, const LightTiles& tiles, rg::ImageHandle atlas,
    const vk::Buffer& lights, const std::array<uint32_t, shadows::light_group_count + 1>& group_begin,
    const glm::mat4& view_projection, const glm::vec3& camera_position, float ambient) const {
  // A copy: declaring images may move the graph's resource list.
  const rg::ImageDesc screen = graph.resources()[gbuffer.albedo.index].image;
  const LightTileGrid grid = LightTileGrid::of(screen.width, screen.height);
  const LightingConstants constants{glm::inverse(view_projection),
                                    glm::vec4(camera_position, 0.0f),
                                    {screen.width, screen.height, grid.across, grid.count()}};
  rg::ImageHandle lit_sum;
  graph.add_pass(
      "lighting ambient",
      [&](rg::PassBuilder& b) {
        b.read(gbuffer.albedo, rg::Usage::sampled_compute);
        b.read(gbuffer.depth, rg::Usage::sampled_compute);
        lit_sum = b.write(b.create_image("lit sum", {screen.width, screen.height, lit_sum_format}),
                          rg::Usage::storage_compute);
        return lit_sum;
      },
      [this, albedo = gbuffer.albedo, depth = gbuffer.depth,
       constants =
           AmbientConstants{glm::vec4(background_colour, ambient), {screen.width, screen.height, 0, 0}}](
          rg::ImageHandle lit_sum, const vk::PassRecorder& rec) {
        const VkDescriptorSet set =
            ambient_layout_.write(rec.allocate_set(ambient_layout_))
                .image(gbuffer_albedo_binding, rec.view(albedo), nearest_.get())
                .image(scene_depth_binding, rec.view(depth), nearest_.get())
                .image(hdr_binding, rec.view(lit_sum), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL)
                .update();
        vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, ambient_pipeline_.get());
        ambient_layout_.bind_compute(rec.cmd(), set);
        ambient_layout_.push(rec.cmd(), constants);
        vkCmdDispatch(rec.cmd(), (constants.screen.x + 15) / 16, (constants.screen.y + 15) / 16, 1);
      });
  for (uint32_t group = 0; group < shadows::light_group_count; ++group) {
    if (group_begin[group + 1] == group_begin[group]) continue;  // no light of the group this frame
    graph.add_pass(
        "lighting " + group_name(group),
        [&](rg::PassBuilder& b) {
          for (const rg::ImageHandle image : {atlas, gbuffer.depth, gbuffer.normal, gbuffer.albedo}) {
            b.read(image, rg::Usage::sampled_compute);
          }
          b.read(tiles.lights, rg::Usage::storage_compute);
          b.read(tiles.ranges, rg::Usage::storage_compute);
          b.read(tiles.tiles, rg::Usage::storage_compute);
          b.read(tiles.dispatch, rg::Usage::indirect);
          lit_sum = b.write(lit_sum, rg::Usage::storage_compute);
        },
        [this, group, gbuffer, tiles, atlas, lit_sum, &lights, constants,
         pipeline = pipelines_[static_cast<uint32_t>(view_)][group].get()](const vk::PassRecorder& rec) {
          const VkSampler nearest = nearest_.get();
          vk::DescriptorWriter writer = layout_.write(rec.allocate_set(layout_));
          writer.image(scene_depth_binding, rec.view(gbuffer.depth), nearest)
              .image(gbuffer_normal_binding, rec.view(gbuffer.normal), nearest)
              .image(gbuffer_albedo_binding, rec.view(gbuffer.albedo), nearest)
              .image(hdr_binding, rec.view(lit_sum), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_GENERAL)
              .buffer(tile_lights_binding, rec.buffer(tiles.lights))
              .buffer(tile_ranges_binding, rec.buffer(tiles.ranges))
              .buffer(group_tiles_binding, rec.buffer(tiles.tiles));
          const VkDescriptorSet set =
              light_resources_.write(writer, lights.texel_view(), rec, atlas).update();
          vkCmdBindPipeline(rec.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
          layout_.bind_compute(rec.cmd(), set);
          layout_.push(rec.cmd(), constants);
          vkCmdDispatchIndirect(rec.cmd(), rec.buffer(tiles.dispatch), group * sizeof(glm::uvec4));
        });
  }
  return lit_sum;
}

}  // namespace sg
