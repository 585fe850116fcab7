// SPDX-License-Identifier: MIT
#pragma once

// Small vocabulary shared by the render graph tests: common states and plan lookups.

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "rendergraph/core/compile.h"

namespace sg::rg::testing {

inline constexpr ImageDesc shadow_atlas_desc{2048, 2048, Format::d32_sfloat, 16, 1, false};
inline constexpr ImageDesc cube_array_desc{512, 512, Format::d16_unorm, 24, 1, true};  // 4 cubes
inline constexpr ImageDesc screen_color_desc{1280, 720, Format::rgba16_sfloat, 1, 1, false};

inline constexpr PipelineStage depth_tests =
    PipelineStage::early_fragment_tests | PipelineStage::late_fragment_tests;
inline constexpr Access depth_read_write =
    Access::depth_stencil_attachment_read | Access::depth_stencil_attachment_write;
inline constexpr Access color_read_write = Access::color_attachment_read | Access::color_attachment_write;

// How a shadow map is left for the lighting pass of the next frame.
inline constexpr ResourceState sampled_in_fragment{
    PipelineStage::fragment_shader, Access::shader_sampled_read, ImageLayout::read_only_optimal};
inline constexpr ResourceState presentable{PipelineStage::none, Access::none, ImageLayout::present_src};
// A swapchain image right after acquire: its semaphore wait is at color attachment output.
inline constexpr ResourceState acquired{PipelineStage::color_attachment_output, Access::none,
                                        ImageLayout::undefined};

// A substring check that prints the whole message when it fails.
inline ::testing::AssertionResult mentions(const std::string& message, std::string_view text) {
  if (message.find(text) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << message << "' does not mention '" << text << "'";
}

// The plan of a graph that must compile; fails the test with every error message otherwise.
inline std::shared_ptr<const CompiledPlan> compile_ok(const RenderGraph& graph) {
  CompileResult result = compile(graph);
  for (const GraphError& error : result.errors) ADD_FAILURE() << error.message;
  if (!result.ok()) throw std::runtime_error("graph did not compile");
  return result.plan;
}

inline const CompiledPass& pass_named(const CompiledPlan& plan, std::string_view name) {
  for (const CompiledPass& pass : plan.passes) {
    if (pass.name == name) return pass;
  }
  throw std::runtime_error("no executed pass named " + std::string(name));
}

}  // namespace sg::rg::testing
