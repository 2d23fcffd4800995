// The shaders' bodies are GLSL ES 3.00-compatible (only the #version line differs): every
// program the renderer builds compiles and links in an OpenGL ES 3.0 context too (EGL on
// Mesa llvmpipe, headless).
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "render/headless_context.hpp"
#include "render/shaders.hpp"

namespace {

TEST(GlslEs, EveryProgramCompilesAsGlslEs300) {
    render::HeadlessContext context(render::HeadlessApi::gles30);
    namespace g = render::glsl;
    std::vector<std::pair<std::string, std::pair<std::string, std::string>>> programs = {
        {"ball", {g::kBallVert, g::kBallFrag}},
        {"shadow", {g::kShadowVert, g::kShadowFrag}},
        {"cushion shadow", {g::kTableVert, g::kCushionShadowFrag}},
        {"cue shadow", {g::kCueShadowVert, g::kCueShadowFrag}},
        {"solid", {g::kSolidVert, g::kSolidFrag}},
    };
    for (int k = 0; k <= 4; ++k)
        programs.push_back({"table material " + std::to_string(k),
                            {g::kTableVert, render::table_fragment_source(
                                                static_cast<render::TableMaterial>(k))}});
    for (const auto& [name, sources] : programs) {
        unsigned program = 0;
        EXPECT_NO_THROW(program = render::build_program(sources.first, sources.second,
                                                        render::GlslTarget::es300))
            << name;
        EXPECT_NE(program, 0u) << name;
        if (program) glDeleteProgram(program);
    }
}

}  // namespace
