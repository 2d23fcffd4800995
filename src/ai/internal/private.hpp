// The headers of src/ai/internal/ are the AI's own (the planner's steps, the levels' table), not
// its API: only the targets that link ai_internal (the ai library, its tests and its benchmarks;
// src/ai/CMakeLists.txt) may include them. Everything else uses src/ai/ai.hpp.
#pragma once

#ifndef COOLAABER_AI_INTERNAL
#error "ai/internal/ is private to the ai library: include its public header, ai/ai.hpp"
#endif
