// SPDX-License-Identifier: MIT
#pragma once
// Ctrl-C (SIGINT) or SIGTERM ends a sandbox run after the frame in hand, and the run then writes
// what its frames measured (the screenshot, --stats) as a shorter run would: an hour of frames
// is not lost to a key pressed to stop it. A second signal ends the program at once.
#include <atomic>

namespace sg::sandbox {

// From now on the two signals set interrupted() (once; the next one is the default's).
void catch_interrupts();

// Set once a signal came; frame loops read it between frames.
const std::atomic<bool>& interrupted();

}  // namespace sg::sandbox
