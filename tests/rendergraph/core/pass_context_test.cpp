// SPDX-License-Identifier: MIT
#include "rendergraph/core/pass_context.h"

#include "rendergraph/core/render_graph.h"

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

TEST(PassContext, AnExecuteFunctionTakingTheRecorderGetsItUnwrapped) {
  RenderGraph graph;
  graph.add_pass(
      "draw", [](PassBuilder& b) { b.mark_side_effects(); },
      [](FakeRecorder& recorder) { recorder.draws += 3; });
  EXPECT_EQ(graph.passes()[0].queue, QueueType::graphics);  // the default queue

  FakeRecorder recorder;
  PassContext context(recorder);
  graph.passes()[0].execute(context);
  EXPECT_EQ(recorder.draws, 3);
}

TEST(PassContext, AnExecuteFunctionTakingAnotherRecorderIsRefusedWhenRun) {
  RenderGraph graph;
  graph.add_pass(
      "draw", QueueType::compute, [](PassBuilder& b) { b.mark_side_effects(); }, [](const FakeRecorder&) {});
  EXPECT_EQ(graph.passes()[0].queue, QueueType::compute);
  int other_recorder = 0;
  PassContext context(other_recorder);
  EXPECT_THROW(graph.passes()[0].execute(context), std::logic_error);
}

}  // namespace
}  // namespace sg::rg
