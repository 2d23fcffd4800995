// The headers of src/physics/internal/ are the physics library's own, not its API: only the
// targets that link physics_internal (the library, its tests and its tools; see
// src/physics/CMakeLists.txt) may include them. Everything else uses src/physics/*.hpp.
#pragma once

#ifndef COOLAABER_PHYSICS_INTERNAL
#error \
    "physics/internal/ is private to the physics library: include the public headers of src/physics/"
#endif
