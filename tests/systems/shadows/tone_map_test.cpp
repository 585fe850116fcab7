// SPDX-License-Identifier: MIT
// The tone curve of shaders/tone_map.glsl, compiled here as C++ from that file.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace sg::test::glsl {
using namespace glm;
#include "shaders/tone_map.glsl"
}  // namespace sg::test::glsl

namespace sg::test {
namespace {

using glsl::TONE_KNEE;
using glsl::tone_map;

TEST(ToneMap, LeavesColorsBelowTheKneeAsTheyAre) {
  // The single-light tests compare pixels with the lighting formula: tone mapping must not move
  // them while the scene is lit within range.
  for (const glm::vec3 c :
       {glm::vec3(0.0f), glm::vec3(0.02f, 0.02f, 0.03f), glm::vec3(0.5f, 0.3f, 0.1f), glm::vec3(TONE_KNEE)}) {
    EXPECT_EQ(tone_map(c, 1.0f), c);
  }
  EXPECT_EQ(tone_map(glm::vec3(0.2f), 2.0f), glm::vec3(0.4f));  // exposure multiplies first
}

TEST(ToneMap, CompressesHighlightsBelowOneKeepingHue) {
  float previous = TONE_KNEE;
  for (float x = TONE_KNEE + 0.01f; x < 100.0f; x *= 1.5f) {
    const glm::vec3 mapped = tone_map(glm::vec3(x, 0.5f * x, 0.25f * x), 1.0f);
    EXPECT_LE(mapped.x, 1.0f);
    EXPECT_GE(mapped.x, previous) << "monotonic";
    if (x < 3.0f) {  // beyond, the float curve has reached 1
      EXPECT_LT(mapped.x, 1.0f);
      EXPECT_GT(mapped.x, previous);
    }
    EXPECT_NEAR(mapped.y / mapped.x, 0.5f, 1e-5f) << "the color is scaled, not clipped per channel";
    EXPECT_NEAR(mapped.z / mapped.x, 0.25f, 1e-5f);
    previous = mapped.x;
  }
  // Continuous at the knee, in value and slope.
  const float h = 1e-3f;
  EXPECT_NEAR(tone_map(glm::vec3(TONE_KNEE + h), 1.0f).x, TONE_KNEE + h, 1e-5f);
  EXPECT_EQ(tone_map(glm::vec3(-1.0f), 1.0f), glm::vec3(0.0f));
}

}  // namespace
}  // namespace sg::test
