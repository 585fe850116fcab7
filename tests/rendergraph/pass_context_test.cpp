#include "rendergraph/core/pass_context.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace sg::rg {
namespace {

struct FakeRecorder {
  int draws = 0;
};

TEST(PassContext, HandsBackTheRecorderTheExecutorWrapped) {
  FakeRecorder recorder;
  PassContext context(recorder);
  context.get<FakeRecorder>().draws += 2;
  EXPECT_EQ(recorder.draws, 2);
}

TEST(PassContext, RefusesToReinterpretAsAnotherType) {
  FakeRecorder recorder;
  PassContext context(recorder);
  EXPECT_THROW(context.get<int>(), std::logic_error);
}

}  // namespace
}  // namespace sg::rg
