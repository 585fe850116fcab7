// SPDX-License-Identifier: MIT
#include <cstdio>

#include "rendergraph/device/context.h"
#include "sandbox/run.h"
#include "sandbox/window_session.h"
#include "systems/frame/interrupt.h"

namespace sg::sandbox {

int run_windowed(const Options& options) {
  WindowSession session(options);
  std::printf("shadowgraph: window on %s (Esc closes)\n", session.context().device_name().c_str());
  const size_t frame_limit = options.frames.value_or(UINT32_MAX);
  while (session.frame_ms().size() < frame_limit && !interrupted() &&
         session.frame() != FrameResult::closed) {
  }
  session.finish();
  return finish_run(options, session.context(), session.scene(), session.sandbox_frame(),
                    {session.frame_ms(), session.wall_frame_ms(), &session.gpu_times()});
}

}  // namespace sg::sandbox
