// SPDX-License-Identifier: MIT
// The C++ light record against the shader's: member offsets and size from glslang's reflection
// of lighting_probe.comp (built with the tests), constants from light_record.glsl's text.
#include <cstddef>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "systems/scene/lights.h"
#include "systems/scene/shadow_settings.h"
#include "systems/shadows/gpu_light.h"

namespace sg::shadows {
namespace {

std::string read_text(const char* path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

struct Reflection {
  std::map<std::string, long> member_offsets;  // Light member name -> offset
  long block_size = -1;                        // the Lights block
  long array_stride = -1;
};

// glslang prints `lights[0].<member>: offset N, ..., topLevelArrayStride S` per member (and,
// for members the probe uses, the same as `lights.<member>`), then `Lights: ..., size N, ...`.
Reflection parse_reflection(const std::string& text) {
  Reflection reflection;
  const std::regex member(R"(^lights(?:\[0\])?\.(\w+): offset (\d+),.*topLevelArrayStride (\d+))");
  const std::regex block(R"(^Lights: .*size (\d+),)");
  std::istringstream lines(text);
  std::string line;
  std::smatch match;
  while (std::getline(lines, line)) {
    if (std::regex_search(line, match, member)) {
      const long offset = std::stol(match[2]);
      const auto [it, inserted] = reflection.member_offsets.emplace(match[1], offset);
      EXPECT_EQ(it->second, offset) << "glslang reports two offsets for " << match[1];
      reflection.array_stride = std::stol(match[3]);
    } else if (std::regex_search(line, match, block)) {
      reflection.block_size = std::stol(match[1]);
    }
  }
  return reflection;
}

TEST(LightRecordLayout, EveryMemberSitsWhereTheShaderReadsIt) {
  const Reflection reflection = parse_reflection(read_text(SHADOWGRAPH_LIGHT_REFLECTION));
  const std::map<std::string, long> cpp = {
      {"position_range", offsetof(GpuLight, position_range)},
      {"direction_type", offsetof(GpuLight, direction_type)},
      {"color_intensity", offsetof(GpuLight, color_intensity)},
      {"shape", offsetof(GpuLight, shape)},
      {"shadow_color_density", offsetof(GpuLight, shadow_color_density)},
      {"shadow_bias", offsetof(GpuLight, shadow_bias)},
      {"info", offsetof(GpuLight, info)},
      {"shadow_rect", offsetof(GpuLight, shadow_rect)},
      {"shadow_depth", offsetof(GpuLight, shadow_depth)},
      {"shadow_matrix", offsetof(GpuLight, shadow_matrix)},
  };
  // Same member names, none missing on either side, and the same offsets.
  EXPECT_EQ(reflection.member_offsets, cpp);
  EXPECT_EQ(reflection.block_size, long(sizeof(GpuLight)));
  EXPECT_EQ(reflection.array_stride, long(sizeof(GpuLight)));
}

// light_at's `light.<member>[column] = ...(texelFetch(light_records, first + N))` lines of
// lights_interface.glsl, as member -> byte offset 16 * N (a member's first texel).
std::map<std::string, long> parse_texel_reads(const std::string& text) {
  std::map<std::string, long> offsets;
  const std::regex read(R"(light\.(\w+)(?:\[\d\])? = .*texelFetch\(light_records, first(?: \+ (\d+))?\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), read); it != std::sregex_iterator(); ++it) {
    const long offset = 16 * ((*it)[2].matched ? std::stol((*it)[2]) : 0);
    offsets.emplace((*it)[1], offset);  // a matrix at its first column
  }
  return offsets;
}

TEST(LightRecordLayout, TheTexelReaderReadsEveryMemberWhereTheLayoutPutsIt) {
  const Reflection reflection = parse_reflection(read_text(SHADOWGRAPH_LIGHT_REFLECTION));
  const std::string text = read_text(SHADOWGRAPH_LIGHTS_INTERFACE_GLSL);
  EXPECT_EQ(parse_texel_reads(text), reflection.member_offsets);
  // Every texel of the record read once: 13 texels, the last the matrix's fourth column.
  EXPECT_NE(text.find("const int LIGHT_RECORD_TEXELS = " + std::to_string(sizeof(GpuLight) / 16) + ";"),
            std::string::npos);
  EXPECT_NE(text.find("light.shadow_matrix[3] = uintBitsToFloat(texelFetch(light_records, first + " +
                      std::to_string(sizeof(GpuLight) / 16 - 1) + "))"),
            std::string::npos);
}

// `const uint NAME = VALUEu;` lines of light_record.glsl.
std::map<std::string, unsigned long> parse_constants(const std::string& text) {
  std::map<std::string, unsigned long> constants;
  const std::regex constant(R"(const uint (\w+) = (0x[0-9A-Fa-f]+|\d+)u;)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), constant); it != std::sregex_iterator();
       ++it) {
    constants[(*it)[1]] = std::stoul((*it)[2], nullptr, 0);
  }
  return constants;
}

TEST(LightRecordLayout, ShaderConstantsMatchTheCppValues) {
  using scene::FalloffMode;
  using scene::ShadowAlgorithm;
  const auto value = [](auto e) { return static_cast<unsigned long>(e); };
  const std::map<std::string, unsigned long> cpp = {
      {"LIGHT_POINT", value(GpuLightType::point)},
      {"LIGHT_SPOT", value(GpuLightType::spot)},
      {"LIGHT_DIRECTIONAL", value(GpuLightType::directional)},
      {"LIGHT_CYLINDER", value(GpuLightType::cylinder)},
      {"FALLOFF_LINEAR_WINDOW", value(FalloffMode::linear_window)},
      {"FALLOFF_GLTF_PUNCTUAL", value(FalloffMode::gltf_punctual)},
      {"SHADOW_HARD", value(ShadowAlgorithm::hard)},
      {"SHADOW_PCF", value(ShadowAlgorithm::pcf)},
      {"SHADOW_NOISE", value(ShadowAlgorithm::noise)},
      {"SHADOW_PCSS", value(ShadowAlgorithm::pcss)},
      {"SHADOW_PCSS_NOISE", value(ShadowAlgorithm::pcss_noise)},
      {"NO_SHADOW_MAP", value(no_shadow_map)},
      {"CASCADED_SHADOW_MAPS", value(cascaded_shadow_maps)},
      {"CASCADED_TYPE_BIT", value(cascaded_type_bit)},
      {"LIGHT_MASK_SHIFT", value(light_mask_shift)},
      {"KERNEL_PCF_SHIFT", value(kernel_pcf_shift)},
      {"KERNEL_BLOCKER_SHIFT", value(kernel_blocker_shift)},
      {"KERNEL_FILTER_SHIFT", value(kernel_filter_shift)},
      {"KERNEL_NOISE_SHIFT", value(kernel_noise_shift)},
  };
  EXPECT_EQ(parse_constants(read_text(SHADOWGRAPH_LIGHT_RECORD_GLSL)), cpp);
}

}  // namespace
}  // namespace sg::shadows
