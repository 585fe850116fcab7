// SPDX-License-Identifier: MIT
#pragma once
// Ctrl-C (SIGINT) or SIGTERM ends a run after the step in hand (a frame, a light measured), and
// the program then writes what the run measured (the sandbox's screenshot and --stats, the
// reference's tables) as a shorter run would: an hour of work is not lost to a key pressed to
// stop it. A second signal ends the program at once. For the applications; the engine installs
// no handler.
#include <atomic>

namespace sg {

// From now on the two signals set interrupted() (once; the next one is the default's).
void catch_interrupts();

// Set once a signal came; frame loops read it between frames.
const std::atomic<bool>& interrupted();

}  // namespace sg
