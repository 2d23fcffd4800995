// A pause point between two of the AI's independent steps (the items of its parallel loops):
// where a caller that thinks in time slices (the web page without threads, docs/web.md) hands
// the CPU back to the browser's frames. The hook comes with the player's settings
// (PlanSettings::pause) and changes nothing the AI computes: its decisions are the same bit for
// bit with or without one (decisions_test.cpp, games_test.cpp).
#pragma once

namespace ai {

/// Called after each step; it returns when the caller lets the thinking go on.
using PauseHook = void (*)();

}  // namespace ai
