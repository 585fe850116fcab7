// SPDX-License-Identifier: MIT
// shadowgraph-plain-forward: a one-light scene (point-room, spot-columns) drawn the way the shadow
// samples of Vulkan sample collections draw theirs, as the baseline of the one-light frame
// ratios in docs/PERFORMANCE.md. Every frame draws the light's shadow map again (a spot light's
// depth map; a point light's six cube faces, each a pass writing the distance to a color target),
// then one forward pass over every triangle lights each fragment with the engine's lighting model
// (ambient, Blinn with specular, the tone curve) and its shadow (3 x 3 PCF of nine fetches, or one
// cube fetch) into an sRGB image: the engine's picture. No depth prepass, light lists, culling or
// caching: the frame a plain renderer pays.
//
//   shadowgraph-plain-forward [--scene point-room|spot-columns] [--width W] [--height H]
//                             [--frames N] [--screenshot PNG] [--device NAME] [--validation]
//
// Prints the median wall and GPU milliseconds of the frames after the first. Each frame is
// submitted and waited for: on lavapipe, where the recording is a sliver of the frame, its wall
// time is the GPU's; on a GPU it adds the round trip (the H200, point-room at 1920x1080:
// 3.15 ms wall against 2.46 GPU, 2026-12-04).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "plain_forward_shaders/plain_depth.vert.spv.h"
#include "plain_forward_shaders/plain_distance.frag.spv.h"
#include "plain_forward_shaders/plain_distance.vert.spv.h"
#include "plain_forward_shaders/plain_point.frag.spv.h"
#include "plain_forward_shaders/plain_scene.vert.spv.h"
#include "plain_forward_shaders/plain_spot.frag.spv.h"
#include "plain_scene.h"
#include "rendergraph/device/barriers.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/descriptors.h"
#include "rendergraph/device/image_views.h"
#include "rendergraph/device/pipeline.h"
#include "rendergraph/device/readback.h"
#include "rendergraph/device/resources.h"
#include "rendergraph/device/upload.h"
#include "rendergraph/vulkan/pass_timer.h"
#include "systems/frame/command_line.h"
#include "systems/frame/png.h"
#include "systems/frame/time_summary.h"
#include "systems/scene/builtin_scenes.h"
#include "systems/shadows/light_views.h"

namespace {

using namespace sg;
using plain_forward::LightKind;
using plain_forward::PlainScene;
using plain_forward::PlainVertex;

constexpr VkFormat frame_format = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat depth_format = VK_FORMAT_D32_SFLOAT;        // the camera's
constexpr VkFormat shadow_depth_format = VK_FORMAT_D16_UNORM;  // the light's, as the samples keep it
constexpr VkFormat distance_format = VK_FORMAT_R32_SFLOAT;

// shaders/plain_interface.glsl's Frame.
struct FrameUniforms {
  glm::mat4 camera;
  glm::vec4 camera_position;
  glm::mat4 light;
  glm::vec4 light_position_range;
  glm::vec4 light_direction;
  glm::vec4 light_color;
};

// The shadow passes' push constants (shaders/plain_depth.vert, plain_distance.vert).
struct ViewConstants {
  glm::mat4 view_projection;
  glm::vec4 light_position_range;  // xyz, range: a cube face's distances are to it
};

struct Geometry {
  vk::Buffer vertices;
  vk::Buffer indices;
  uint32_t index_count = 0;
};

Geometry upload_geometry(vk::VulkanContext& context, const PlainScene& scene) {
  Geometry geometry{vk::Buffer(context, {scene.vertices.size() * sizeof(PlainVertex),
                                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         vk::MemoryUsage::gpu_only, "plain vertices"}),
                    vk::Buffer(context, {scene.indices.size() * sizeof(uint32_t),
                                         VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         vk::MemoryUsage::gpu_only, "plain indices"}),
                    static_cast<uint32_t>(scene.indices.size())};
  vk::UploadBatch upload(context);
  upload.copy(geometry.vertices, std::span<const PlainVertex>(scene.vertices));
  upload.copy(geometry.indices, std::span<const uint32_t>(scene.indices));
  upload.submit();
  return geometry;
}

void draw(VkCommandBuffer cmd, const Geometry& geometry) {
  const VkBuffer vertices = geometry.vertices.handle();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
  vkCmdBindIndexBuffer(cmd, geometry.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, geometry.index_count, 1, 0, 0, 0);
}

// Positions only (the shadow passes), or positions, normals and colors.
void vertex_input(vk::GraphicsPipelineDesc& desc, bool positions_only) {
  desc.vertex_bindings = {{0, sizeof(PlainVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(PlainVertex, position)}};
  if (positions_only) return;
  desc.vertex_attributes.push_back({1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(PlainVertex, normal)});
  desc.vertex_attributes.push_back({2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(PlainVertex, color)});
  desc.vertex_attributes.push_back(
      {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(PlainVertex, specular_shininess)});
}

struct Target {
  VkImageView color = VK_NULL_HANDLE;  // none for a depth-only pass
  VkImageView depth = VK_NULL_HANDLE;
  VkExtent2D extent{};
  float clear_depth = 1.0f;
  VkClearColorValue clear_color{{1.0f, 1.0f, 1.0f, 1.0f}};  // the distance cube's "nothing there"
};

void begin_pass(VkCommandBuffer cmd, const Target& target) {
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = target.color;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.clearValue.color = target.clear_color;
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = target.depth;
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {target.clear_depth, 0};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, target.extent};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = target.color != VK_NULL_HANDLE ? 1 : 0;
  rendering.pColorAttachments = &color;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);
  const VkViewport viewport{0.0f, 0.0f, float(target.extent.width), float(target.extent.height), 0.0f, 1.0f};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
}

// A barrier after everything recorded before, which may have written `image`: its layout from
// `from` (undefined: its contents dropped, as each frame's writes start) to `to`.
void transition(VkCommandBuffer cmd, const vk::Image& image, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags2 dst_stages, VkAccessFlags2 dst_access) {
  vk::ImageTransition t;
  t.image = image.handle();
  t.aspect = image.aspect();
  t.old_layout = from;
  t.new_layout = to;
  t.src_stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  t.src_access = VK_ACCESS_2_MEMORY_WRITE_BIT;
  t.dst_stages = dst_stages;
  t.dst_access = dst_access;
  vk::transition(cmd, t);
}

void start_writes(VkCommandBuffer cmd, const vk::Image& image, VkImageLayout layout) {
  transition(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, layout, VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT,
             VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
}

// One pass into the shadow map: what it draws into, and from where.
struct ShadowView {
  VkImageView color = VK_NULL_HANDLE;  // a cube face of distances; none for a depth map
  VkImageView depth = VK_NULL_HANDLE;
  ViewConstants constants;
};

// The light's shadow map, drawn again every frame, and what the scene pass samples of it: a spot
// light's depth map in one view, or a point light's cube of distances in six, each face with a
// depth layer of its own.
class ShadowPass {
 public:
  ShadowPass(vk::VulkanContext& context, const plain_forward::PlainLight& light)
      : size_(light.resolution),
        layout_(
            context.device(), {},
            vk::push_constants<ViewConstants>(VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT)) {
    const glm::vec4 position_range(light.position, light.range);
    vk::GraphicsPipelineDesc desc;
    vertex_input(desc, true);
    desc.depth_format = shadow_depth_format;
    desc.layout = layout_.get();
    if (light.kind == LightKind::spot) {
      map_ = vk::Image(context, {{size_, size_},
                                 shadow_depth_format,
                                 VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                 1,
                                 1,
                                 VK_IMAGE_VIEW_TYPE_2D,
                                 "plain shadow map"});
      map_written_ = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
      light_matrix_ =
          shadows::spot_light_view(light.position, light.direction, std::acos(light.cos_outer), light.range)
              .view_projection();
      views_ = {{VK_NULL_HANDLE, map_.view(), {light_matrix_, position_range}}};
      desc.vertex_spirv = plain_depth_vert;
      desc.name = "plain shadow map";
    } else {
      map_ = vk::Image(context, {{size_, size_},
                                 distance_format,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                 1,
                                 6,
                                 VK_IMAGE_VIEW_TYPE_CUBE,
                                 "plain shadow cube"});
      map_written_ = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
      face_depths_ = vk::Image(context, {{size_, size_},
                                         shadow_depth_format,
                                         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                         1,
                                         6,
                                         VK_IMAGE_VIEW_TYPE_2D_ARRAY,
                                         "plain cube face depths"});
      const shadows::CubeViews faces = shadows::point_light_cube(light.position, light.range);
      for (uint32_t face = 0; face < 6; ++face) {
        views_.push_back({map_.views().get({.base_layer = face}),
                          face_depths_.views().get({.base_layer = face}),
                          {faces.view_projection[face], position_range}});
      }
      desc.vertex_spirv = plain_distance_vert;
      desc.fragment_spirv = plain_distance_frag;
      desc.color_formats = {distance_format};
      desc.front_face = VK_FRONT_FACE_CLOCKWISE;  // the cube's faces are mirrored (shadows::CubeViews)
      desc.name = "plain shadow cube face";
    }
    pipeline_ = vk::create_graphics_pipeline(context, desc);
  }

  const glm::mat4& light_matrix() const { return light_matrix_; }  // spot lights'
  VkImageView view() const { return map_.view(); }

  // Leaves the map in READ_ONLY_OPTIMAL for the scene pass's fragment shader.
  void record(VkCommandBuffer cmd, const Geometry& geometry) const {
    start_writes(cmd, map_, map_written_);
    if (face_depths_.handle() != VK_NULL_HANDLE) {
      start_writes(cmd, face_depths_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    for (const ShadowView& view : views_) {
      begin_pass(cmd, {view.color, view.depth, {size_, size_}});
      layout_.push(cmd, view.constants);
      draw(cmd, geometry);
      vkCmdEndRendering(cmd);
    }
    transition(cmd, map_, map_written_, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
               VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  }

 private:
  uint32_t size_;
  vk::Image map_;
  VkImageLayout map_written_ = VK_IMAGE_LAYOUT_UNDEFINED;  // its layout while the views draw
  vk::Image face_depths_;                                  // point lights': a layer a face
  std::vector<ShadowView> views_;
  glm::mat4 light_matrix_{1.0f};
  vk::PipelineLayout layout_;
  vk::UniquePipeline pipeline_;
};

// The forward pass: every triangle, each fragment lit with the shadow, into the frame.
class ScenePass {
 public:
  ScenePass(vk::VulkanContext& context, const PlainScene& scene, const ShadowPass& shadow, VkExtent2D extent)
      : extent_(extent),
        frame_(context,
               {extent, frame_format, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                1, 1, VK_IMAGE_VIEW_TYPE_2D, "plain frame"}),
        depth_(context, {extent, depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, 1, 1,
                         VK_IMAGE_VIEW_TYPE_2D, "plain depth"}),
        uniforms_(context, {sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                            vk::MemoryUsage::upload, "plain frame uniforms"}),
        sampler_(vk::create_sampler(context.device(), VK_FILTER_NEAREST)),
        layout_(context.device(),
                {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
                 {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                  VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}}),
        sets_(layout_.allocate_sets(1)) {
    const plain_forward::PlainLight& light = scene.light;
    const FrameUniforms uniforms{scene.camera,
                                 glm::vec4(scene.eye, 1.0f),
                                 shadow.light_matrix(),
                                 glm::vec4(light.position, light.range),
                                 glm::vec4(light.direction, light.cos_outer),
                                 glm::vec4(light.color, light.cos_inner)};
    std::memcpy(uniforms_.mapped(), &uniforms, sizeof(uniforms));
    layout_.write(sets_.sets[0])
        .image(0, shadow.view(), sampler_.get())
        .buffer(1, uniforms_.handle())
        .update();
    vk::GraphicsPipelineDesc desc{.vertex_spirv = plain_scene_vert,
                                  .fragment_spirv = light.kind == LightKind::spot
                                                        ? std::span<const uint32_t>(plain_spot_frag)
                                                        : std::span<const uint32_t>(plain_point_frag)};
    vertex_input(desc, false);
    desc.color_formats = {frame_format};
    desc.depth_format = depth_format;
    desc.depth_compare = VK_COMPARE_OP_GREATER;  // the camera's depth is reversed (systems/gpu/camera.h)
    desc.layout = layout_.get();
    desc.name = "plain forward";
    pipeline_ = vk::create_graphics_pipeline(context, desc);
  }

  const vk::Image& frame() const { return frame_; }

  // Leaves the frame in TRANSFER_SRC_OPTIMAL, for a screenshot.
  void record(VkCommandBuffer cmd, const Geometry& geometry) const {
    start_writes(cmd, frame_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    start_writes(cmd, depth_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    begin_pass(cmd, {frame_.view(), depth_.view(), extent_, 0.0f, {{0.02f, 0.02f, 0.03f, 1.0f}}});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    layout_.bind(cmd, sets_.sets[0]);
    draw(cmd, geometry);
    vkCmdEndRendering(cmd);
    transition(cmd, frame_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  }

 private:
  VkExtent2D extent_;
  vk::Image frame_;
  vk::Image depth_;
  vk::Buffer uniforms_;
  vk::UniqueSampler sampler_;
  vk::PipelineLayout layout_;
  vk::DescriptorSets sets_;
  vk::UniquePipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
  vk::ContextOptions context_options;
  std::string scene_name = "spot-columns";
  uint32_t width = 1280;
  uint32_t height = 720;
  uint32_t frames = 30;
  std::string screenshot;
  CLI::App app{
      "Draws a one-light scene as a plain forward renderer does: its shadow map again every frame, then one "
      "forward pass. The baseline of the one-light frame ratios."};
  app.add_option("--scene", scene_name, "point-room (a point light, a cube) or spot-columns (a spot light)")
      ->check(CLI::IsMember({"point-room", "spot-columns"}));
  app.add_option("--width", width, "Frame width in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--height", height, "Frame height in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--frames", frames, "Frames to draw; the first is left out of the medians")
      ->check(CLI::Range(2u, 100000u));
  sg::check_writable_output(
      *app.add_option("--screenshot", screenshot, "Write the last frame as PNG")->option_text("PNG"));
  app.add_option("--device", context_options.device_name,
                 "Use the Vulkan device whose name contains NAME (case-insensitive)")
      ->option_text("NAME");
  app.add_flag("--validation", context_options.validation,
               "Khronos validation layer on (also SHADOWGRAPH_VALIDATION=1)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) != static_cast<int>(CLI::ExitCodes::Success) ? 2 : 0;
  }
  context_options.validation = context_options.validation || vk::validation_requested_by_environment();

  try {
    vk::VulkanContext context(context_options);
    const PlainScene scene =
        plain_forward::flatten(scene::build_scene(scene_name), float(width) / float(height));
    const Geometry geometry = upload_geometry(context, scene);
    const ShadowPass shadow(context, scene.light);
    const ScenePass forward(context, scene, shadow, {width, height});
    vk::PassTimer timer(context, 1);
    std::vector<double> wall_ms;
    std::vector<double> gpu_ms;
    std::vector<double> pass_ms;
    std::vector<double> shadow_ms;
    std::vector<double> forward_ms;
    for (uint32_t frame = 0; frame < frames; ++frame) {
      const auto start = std::chrono::steady_clock::now();
      context.submit_and_wait([&](VkCommandBuffer cmd) {
        timer.begin_frame(cmd, 0, 2);
        timer.begin_pass(cmd, 0, 0);
        shadow.record(cmd, geometry);
        timer.end_pass(cmd, 0, 0);
        timer.begin_pass(cmd, 0, 1);
        forward.record(cmd, geometry);
        timer.end_pass(cmd, 0, 1);
      });
      const std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - start;
      if (frame == 0) continue;  // pays for first use
      wall_ms.push_back(wall.count());
      if (!timer.collect(0, pass_ms)) {
        throw std::runtime_error("the device's queue has no timestamps, so nothing can be measured");
      }
      shadow_ms.push_back(pass_ms[0]);
      forward_ms.push_back(pass_ms[1]);
      gpu_ms.push_back(pass_ms[0] + pass_ms[1]);
    }
    if (!screenshot.empty()) write_png(screenshot, vk::read_rgba8(context, forward.frame()));
    const auto median = [](const std::vector<double>& ms) { return summarize(ms)->median; };  // never empty
    std::printf(
        "plain forward, %s (%zu triangles), %ux%u, %s: wall %.2f ms, GPU %.2f ms a frame (shadow map %.2f, "
        "forward pass %.2f; medians of %u)\n",
        scene_name.c_str(), scene.indices.size() / 3, width, height, context.device_name().c_str(),
        median(wall_ms), median(gpu_ms), median(shadow_ms), median(forward_ms), frames - 1);
    if (context.validation_enabled() && context.validation_errors() > 0) {
      std::fprintf(stderr, "shadowgraph-plain-forward: the validation layer reported %u errors\n",
                   context.validation_errors());
      return 3;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowgraph-plain-forward: error: %s\n", e.what());
    return 1;
  }
}
