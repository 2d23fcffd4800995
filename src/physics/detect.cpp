// detect.hpp defines its functions inline (the event loop in simulate.cpp calls them about
// 10,000 times per break, and inlining them there saves about an eighth of a break's
// instructions); this file only checks that the header stands on its own.
#include "physics/internal/detect.hpp"
