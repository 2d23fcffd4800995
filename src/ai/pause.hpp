// A pause point between two of the AI's independent steps (the items of its parallel loops,
// internal/parallel.hpp): where a caller that thinks in time slices (the web page without
// threads, docs/web.md) hands the CPU back to the browser's frames. A hook changes nothing the AI
// computes: its decisions are the same bit for bit with or without one (decisions_test.cpp).
#pragma once

namespace ai {

using PauseHook = void (*)();

/// Sets the hook the AI calls, on this thread, after each step (nullptr: none, the default);
/// returns the one it replaces.
PauseHook set_pause_hook(PauseHook hook);

}  // namespace ai
