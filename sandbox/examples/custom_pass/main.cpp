// SPDX-License-Identifier: MIT
// custom_pass: the engine's frame with a pass of this program's own (fog_pass.h), rendered
// headless into a PNG. Built outside the engine's tree against the installed engine
// (find_package(Shadowgraph), CMakeLists.txt).
//
//   custom_pass OUT.png [--plain] [--scene NAME|PATH] [--width W] [--height H]
//
// --plain leaves the pass out, for comparing: the two pictures differ in the left half alone.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "fog_pass.h"
#include "rendergraph/device/context.h"
#include "rendergraph/device/frame_ring.h"
#include "systems/frame/frame.h"
#include "systems/frame/frame_settings.h"
#include "systems/frame/gpu_time_log.h"
#include "systems/frame/headless_frames.h"
#include "systems/frame/png.h"
#include "systems/frame/scene_view.h"

int main(int argc, char** argv) {
  try {
    sg::FrameSettings settings;
    settings.width = 640;
    settings.height = 360;
    std::string out;
    bool plain = false;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--plain") {
        plain = true;
      } else if ((arg == "--scene" || arg == "--width" || arg == "--height") && i + 1 < argc) {
        const std::string value = argv[++i];
        if (arg == "--scene") settings.scene = value;
        if (arg == "--width") settings.width = static_cast<uint32_t>(std::stoul(value));
        if (arg == "--height") settings.height = static_cast<uint32_t>(std::stoul(value));
      } else if (!arg.starts_with("--") && out.empty()) {
        out = arg;
      } else {
        out.clear();
        break;
      }
    }
    if (out.empty()) {
      std::fprintf(stderr,
                   "usage: custom_pass OUT.png [--plain] [--scene NAME|PATH] [--width W] [--height H]\n");
      return 2;
    }

    sg::SceneView view = sg::load_scene_view(settings, float(settings.width) / float(settings.height));
    sg::vk::VulkanContext context(sg::context_options(settings));
    sg::vk::FrameRing ring(context);
    const custom_pass::FogPass fog(context, sg::frame_format);
    std::vector<sg::FrameExtension> extensions;
    if (!plain) {
      extensions.push_back({.add_passes = [&](sg::rg::RenderGraph& graph, const sg::RenderedFrame& rendered,
                                              sg::rg::ImageHandle color, uint32_t) {
        return fog.add_to(graph, rendered.depth, color, view.lens);
      }});
    }
    sg::Frame frame(context, view, settings, ring.frames_in_flight(), std::move(extensions));
    frame.resize({settings.width, settings.height});
    sg::GpuTimeLog times;
    sg::render_headless_frames(frame, ring, 3, times, false);
    sg::write_png(out, sg::vk::read_rgba8(context, frame.image()));
    std::printf("custom_pass: wrote %s (%s)\n", out.c_str(), plain ? "plain" : "with fog");
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "custom_pass: %s\n", error.what());
    return 1;
  }
}
