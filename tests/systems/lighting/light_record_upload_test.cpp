// SPDX-License-Identifier: MIT
// LightRecordUpload writes each frame slot only the records that changed since that slot was last
// written: after any sequence of changes, every slot it hands out must hold what sorting the
// frame's records afresh gives, the cascades' records after them.
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "ecs/jobs/thread_pool.h"
#include "systems/lighting/light_record_upload.h"
#include "tests/support/gpu_test.h"

namespace sg::test {
namespace {

using shadows::GpuLight;

GpuLight record_of(uint32_t i) {
  GpuLight record;
  record.position_range = glm::vec4(float(i), 0.0f, 0.0f, 1.0f);
  record.info = {i % 2, 0u, i % 5, i % 7 == 0 ? shadows::no_shadow_map : 0u};
  return record;
}

class LightRecordUploadTest : public GpuTest {};

TEST_F(LightRecordUploadTest, EverySlotHoldsTheFramesSortedRecords) {
  constexpr uint32_t slots = 3;
  LightRecordUpload upload(context, slots);
  jobs::ThreadPool pool(3);
  std::mt19937 random(11);
  shadows::FrameLights lights;
  for (uint32_t i = 0; i < 4000; ++i) lights.records.push_back(record_of(i));
  for (uint32_t frame = 0; frame < 14; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    // Most frames change a few records; some change a record's group, or the count.
    for (int k = 0; k < 30; ++k) lights.records[random() % lights.records.size()].color_intensity.a += 1.0f;
    if (frame == 4) lights.records[17].info.z = 4u;
    if (frame == 6) lights.records.resize(3900);
    if (frame == 9) {
      for (uint32_t i = 0; i < 600; ++i) lights.records.push_back(record_of(5000 + i));
    }
    lights.cascades.assign((frame / 2) % 3, record_of(9000 + frame));  // slots grow for them alone

    const uint32_t slot = frame % slots;
    const vk::Buffer& buffer = upload.upload(lights, slot, frame % 2 == 0 ? &pool : nullptr);
    shadows::FrameLights fresh = lights;
    std::vector<GpuLight> expected(fresh.records.size());
    shadows::sort_by_group(fresh, expected);
    expected.insert(expected.end(), lights.cascades.begin(), lights.cascades.end());
    ASSERT_GE(buffer.size(), expected.size() * sizeof(GpuLight));
    EXPECT_EQ(std::memcmp(buffer.mapped(), expected.data(), expected.size() * sizeof(GpuLight)), 0)
        << "slot " << slot << " holds other records than sorting them afresh gives";
    EXPECT_EQ(&upload.buffer(slot), &buffer);
  }
}

}  // namespace
}  // namespace sg::test
