// SPDX-License-Identifier: MIT
#include "systems/shadow_maps/shadow_passes.h"

#include <array>
#include <cstring>
#include <initializer_list>
#include <span>
#include <string>

#include "rendergraph/device/context.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/vulkan/pass_recorder.h"
#include "rendergraph/vulkan/plan_translation.h"
#include "shaders/shadow_cube.frag.spv.h"
#include "shaders/shadow_cube_cut_out.frag.spv.h"
#include "shaders/shadow_cube_layered.vert.spv.h"
#include "shaders/shadow_cube_layered_cut_out.vert.spv.h"
#include "shaders/shadow_cut_out.frag.spv.h"
#include "shaders/shadow_map.vert.spv.h"
#include "shaders/shadow_map_cut_out.vert.spv.h"
#include "systems/gpu/gpu_scene.h"
#include "systems/gpu/gpu_textures.h"
#include "systems/gpu/shader_bindings.h"
#include "systems/scene/mesh_library.h"
#include "systems/shadow_maps/shadow_atlas.h"
#include "systems/shadows/atlas_tile_coords.h"

namespace sg {
namespace {

using namespace bindings;
using shadows::AtlasTile;
using shadows::CubeShadowMode;
using shadows::FrameLights;
using shadows::ShadowCubeView;
using shadows::ShadowMapView;

constexpr VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// shaders/shadow_pass_constants.glsl: shadow_map.vert reads view_projection; cube faces hand
// light_position_far to shadow_cube.frag.
struct PassConstants {
  glm::mat4 view_projection;
  glm::vec4 light_position_far;
};

// shadow_cube_layered.vert's CubeFaces block (std140).
struct CubeFaces {
  std::array<glm::mat4, 6> view_projection;
  std::array<glm::vec4, 6> tile;  // clip xy -> the layer's: xy scale, zw offset
};

VkRect2D tile_rect(const AtlasTile& tile) {
  return {{int32_t(tile.x), int32_t(tile.y)}, {tile.size, tile.size}};
}

// Clears `tiles` of the pass's single-layer attachment to the far plane.
void clear_tiles(VkCommandBuffer cmd, std::initializer_list<AtlasTile> tiles) {
  const VkClearAttachment far{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {.depthStencil = {1.0f, 0}}};
  std::array<VkClearRect, 6> rects{};
  uint32_t count = 0;
  for (const AtlasTile& tile : tiles) rects[count++] = {tile_rect(tile), 0, 1};
  vkCmdClearAttachments(cmd, 1, &far, count, rects.data());
}

}  // namespace

ShadowPasses::ShadowPasses(vk::VulkanContext& context, uint32_t frames_in_flight, const GpuTextures& textures)
    : context_(context),
      textures_(textures),
      layout_(context.device(),
              {{instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT},
               {cube_faces_binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, VK_SHADER_STAGE_VERTEX_BIT},
               {view_instances_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT},
               {material_textures_binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                VK_SHADER_STAGE_FRAGMENT_BIT}},
              vk::push_constants<PassConstants>(stages)),
      slot_sets_(layout_.allocate_sets(frames_in_flight)),
      casters_(context, frames_in_flight),
      cube_faces_(context, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, frames_in_flight, "cube faces") {
  const VkDeviceSize alignment = context.properties().limits.minUniformBufferOffsetAlignment;
  cube_faces_stride_ = (sizeof(CubeFaces) + alignment - 1) / alignment * alignment;
  opaque_ = make_pipelines(false);
}

ShadowPasses::Pipelines ShadowPasses::make_pipelines(bool cut_out) const {
  using Spirv = std::span<const uint32_t>;
  const Spirv map_vert = cut_out ? Spirv(shadow_map_cut_out_vert) : Spirv(shadow_map_vert);
  const Spirv layered_vert =
      cut_out ? Spirv(shadow_cube_layered_cut_out_vert) : Spirv(shadow_cube_layered_vert);
  const Spirv face_frag = cut_out ? Spirv(shadow_cube_cut_out_frag) : Spirv(shadow_cube_frag);
  const std::string suffix = cut_out ? " cut out" : "";
  vk::GraphicsPipelineDesc desc =
      cut_out ? shadow_cut_out_pipeline_desc(layout_.get(), textures_) : shadow_pipeline_desc(layout_.get());
  Pipelines made;
  desc.vertex_spirv = map_vert;
  if (cut_out) desc.fragment_spirv = shadow_cut_out_frag;  // 2D maps need none otherwise
  desc.name = "shadow map" + suffix;
  made.map = vk::create_graphics_pipeline(context_, desc);
  desc.fragment_spirv = face_frag;
  desc.name = "shadow cube face" + suffix;
  made.face = vk::create_graphics_pipeline(context_, desc);
  desc.vertex_spirv = layered_vert;
  desc.name = "shadow cube layered" + suffix;
  made.layered = vk::create_graphics_pipeline(context_, desc);
  return made;
}

void ShadowPasses::prepare(uint32_t slot, const FrameLights& lights, const GpuScene& scene,
                           uint32_t page_size, CubeShadowMode mode, bool cull_casters) {
  constexpr glm::vec4 everywhere{0.0f, 0.0f, 0.0f, -1.0f};  // a view with no reach keeps every caster
  // Grid cells as large as the rendered lights' mean reach (views without one do not use the grid).
  float reach_sum = 0.0f;
  uint32_t bounded = 0;
  const auto add_reach = [&](const glm::vec4& reach) {
    if (reach.w < 0.0f) return;
    reach_sum += reach.w;
    ++bounded;
  };
  for (const ShadowMapView& map : lights.maps) {
    if (map.render) add_reach(map.reach);
  }
  for (const ShadowCubeView& cube : lights.cubes) {
    if (cube.render) add_reach(cube.position_far);
  }
  if (!cut_out_.map && scene.first_cut_out_group() < scene.caster_groups().size()) {
    cut_out_ = make_pipelines(true);
  }
  casters_.begin_frame(scene, bounded > 0 ? reach_sum / float(bounded) : 0.0f);
  map_casters_.assign(lights.maps.size(), CasterView{});
  for (size_t m = 0; m < lights.maps.size(); ++m) {
    const ShadowMapView& map = lights.maps[m];
    if (map.render)
      map_casters_[m] = casters_.add_view(scene, cull_casters ? map.reach : everywhere, map.caster_mask, 1);
  }
  const uint32_t copies = mode == CubeShadowMode::layered ? 6 : 1;
  cube_casters_.assign(lights.cubes.size(), CasterView{});
  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    const ShadowCubeView& cube = lights.cubes[c];
    if (cube.render) {
      cube_casters_[c] =
          casters_.add_view(scene, cull_casters ? cube.position_far : everywhere, cube.caster_mask, copies);
    }
  }
  casters_.upload(slot);

  cube_faces_scratch_.assign(std::max<size_t>(1, lights.cubes.size()) * cube_faces_stride_, std::byte{0});
  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    const ShadowCubeView& cube = lights.cubes[c];
    if (!cube.render) continue;
    CubeFaces faces{shadows::face_views(cube).view_projection, {}};
    for (int f = 0; f < 6; ++f) faces.tile[f] = shadows::tile_clip_transform(cube.tiles[f], page_size);
    std::memcpy(cube_faces_scratch_.data() + c * cube_faces_stride_, &faces, sizeof(faces));
  }
  const vk::Buffer& faces = cube_faces_.write(slot, std::span<const std::byte>(cube_faces_scratch_));

  layout_.write(slot_sets_.sets[slot])
      .buffer(instances_binding, scene.instances(slot).handle())
      .buffer(cube_faces_binding, faces.handle(), 0, sizeof(CubeFaces))
      .buffer(view_instances_binding, casters_.ids(slot).handle())
      .image(material_textures_binding, textures_.array().view(), textures_.sampler())
      .update();
}

void ShadowPasses::draw_casters(VkCommandBuffer cmd, uint32_t slot, vk::UniquePipeline Pipelines::*kind,
                                const glm::mat4& view_projection, const glm::vec4& position_far,
                                uint32_t cube_faces_offset, const GpuScene& scene, CasterView view) const {
  if (view.command_count == 0 || !scene.bind_geometry(cmd)) return;
  layout_.bind(cmd, slot_sets_.sets[slot], {&cube_faces_offset, 1});
  layout_.push(cmd, PassConstants{view_projection, position_far});
  if (view.cut_out_commands < view.command_count) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, (opaque_.*kind).get());
    casters_.draw(cmd, slot, view, false);
  }
  if (view.cut_out_commands > 0) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, (cut_out_.*kind).get());
    casters_.draw(cmd, slot, view, true);
  }
}

rg::ImageHandle ShadowPasses::add_to(rg::RenderGraph& graph, rg::ImageHandle atlas, const FrameLights& lights,
                                     const GpuScene& scene, uint32_t slot, CubeShadowMode mode) const {
  // Each pass keeps its layer (other lights' tiles) and clears only its own tiles.
  const auto write_layer = [&](uint32_t page) {
    return [&atlas, page](rg::PassBuilder& b) {
      atlas = b.write(atlas, rg::Usage::depth_attachment, rg::SubresourceRange::layer(page));
    };
  };
  for (size_t m = 0; m < lights.maps.size(); ++m) {
    const ShadowMapView& map = lights.maps[m];
    if (!map.render) continue;
    graph.add_pass(map.name, write_layer(map.tile.page),
                   [this, &map, &scene, slot, view = map_casters_[m]](const vk::PassRecorder& rec) {
                     clear_tiles(rec.cmd(), {map.tile});
                     rec.set_viewport(tile_rect(map.tile));
                     draw_casters(rec.cmd(), slot, &Pipelines::map, map.view.view_projection(),
                                  glm::vec4(0.0f), 0, scene, view);
                   });
  }

  for (size_t c = 0; c < lights.cubes.size(); ++c) {
    const ShadowCubeView& cube = lights.cubes[c];
    if (!cube.render) continue;
    const CasterView view = cube_casters_[c];
    const auto faces_offset = static_cast<uint32_t>(c * cube_faces_stride_);
    if (mode == CubeShadowMode::layered) {
      graph.add_pass(cube.name, write_layer(cube.tiles[0].page),
                     [this, &cube, &scene, slot, faces_offset, view](const vk::PassRecorder& rec) {
                       const auto& t = cube.tiles;
                       clear_tiles(rec.cmd(), {t[0], t[1], t[2], t[3], t[4], t[5]});
                       rec.set_full_viewport();
                       draw_casters(rec.cmd(), slot, &Pipelines::layered, glm::mat4(1.0f), cube.position_far,
                                    faces_offset, scene, view);
                     });
      continue;
    }
    const shadows::CubeViews faces = shadows::face_views(cube);
    for (uint32_t face = 0; face < 6; ++face) {
      graph.add_pass(cube.name + " face " + std::to_string(face), write_layer(cube.tiles[face].page),
                     [this, &cube, &scene, slot, face, faces_offset, view,
                      view_projection = faces.view_projection[face]](const vk::PassRecorder& rec) {
                       clear_tiles(rec.cmd(), {cube.tiles[face]});
                       rec.set_viewport(tile_rect(cube.tiles[face]));
                       draw_casters(rec.cmd(), slot, &Pipelines::face, view_projection, cube.position_far,
                                    faces_offset, scene, view);
                     });
    }
  }
  return atlas;
}

}  // namespace sg
