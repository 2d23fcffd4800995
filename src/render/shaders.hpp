// GLSL sources. Bodies are GLSL ES 3.00-compatible; only the #version line differs between
// desktop OpenGL 3.3 core and WebGL 2 / GLES 3.
#pragma once

#include <string>
#include <string_view>

namespace render {

enum class GlslTarget { gl33, es300 };

// The one place that picks the GLSL by platform: the web build (cmake/web.cmake) defines
// COOLAABER_GLSL_ES, its WebGL 2 takes GLSL ES 3.00.
#ifndef COOLAABER_GLSL_ES
#define COOLAABER_GLSL_ES 0
#endif
/// The GLSL of this build's OpenGL: 3.30 core on the desktop, ES 3.00 in the browser.
inline constexpr GlslTarget kPlatformGlsl =
    COOLAABER_GLSL_ES ? GlslTarget::es300 : GlslTarget::gl33;

/// The #version line (and, for ES, default precision) followed by the body.
std::string shader_source(std::string_view body, GlslTarget target = kPlatformGlsl);

/// Compiles and links a program; throws std::runtime_error with the info log on failure.
unsigned build_program(std::string_view vertex_body, std::string_view fragment_body,
                       GlslTarget target = kPlatformGlsl);

/// The table shader's materials, each its own program.
enum class TableMaterial { cloth = 0, cushion = 1, wood = 2, cloth_bake = 3, rail_top = 4 };
/// glsl::kTableFrag specialised for one material.
std::string table_fragment_source(TableMaterial material);

namespace glsl {
extern const char* const kCommon;  ///< lamps, tone mapping, fog (included by the fragment shaders)
extern const char* const kTableVert;
extern const char* const kTableFrag;  ///< needs `const int kMaterial` first: table_fragment_source
extern const char* const kBallVert;
extern const char* const kBallFrag;
extern const char* const kShadowVert;
extern const char* const kShadowFrag;
extern const char* const kCushionShadowFrag;  ///< with kTableVert: ball shadows on the cushions
extern const char* const kCueShadowVert;      ///< the cue's soft shadow on the cloth
extern const char* const kCueShadowFrag;
extern const char* const kSolidVert;  ///< cue stick, aim guide: lit or flat-coloured geometry
extern const char* const kSolidFrag;
extern const char* const kRoomVert;  ///< the room: lit per vertex (its faces are cut in cells)
extern const char* const kRoomFrag;  ///< floor planks, panelled walls, fog toward the background
}  // namespace glsl

}  // namespace render
