#include "render/renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "physics/markings.hpp"
#include "render/cue_stick.hpp"
#include "render/moving_scale.hpp"
#include "render/pockets.hpp"
#include "render/room.hpp"
#include "render/shaders.hpp"
#include "render/solid_mesh.hpp"
#include "render/table_mesh.hpp"
#include "render/textures.hpp"

namespace render {

namespace {

constexpr std::array<glm::vec3, 8> kColours = {{
    {0.95f, 0.94f, 0.89f},  // cue ball
    {0.98f, 0.76f, 0.04f},  // 1 yellow
    {0.04f, 0.18f, 0.68f},  // 2 blue
    {0.84f, 0.06f, 0.05f},  // 3 red
    {0.33f, 0.10f, 0.52f},  // 4 purple
    {1.00f, 0.40f, 0.04f},  // 5 orange
    {0.02f, 0.44f, 0.19f},  // 6 green
    {0.48f, 0.07f, 0.07f},  // 7 maroon
}};
constexpr glm::vec3 kBlack{0.03f, 0.03f, 0.03f};
constexpr glm::vec3 kClothColour{0.12f, 0.44f, 0.25f};     // sRGB: a tournament green
constexpr glm::vec3 kBackground{0.005f, 0.0045f, 0.005f};  // linear
constexpr glm::vec3 kRefused{0.95f, 0.12f, 0.08f};         // ball in hand where it may not go

/// What every pass of a frame needs.
struct Pass {
    glm::mat4 view_proj;
    glm::vec3 eye;
    int width, height;
    float focal;  ///< 1 / tan(fovy / 2)
};

struct Mesh {
    GLuint vao = 0, vbo = 0;
    GLsizei count = 0;
};

/// Static solid geometry (the room, the pockets, the lamps' glow) in its own buffer.
struct SolidMesh {
    GLuint vao = 0, vbo = 0;
    GLsizei count = 0;
};

SolidMesh upload_solid(const std::vector<SolidVertex>& v) {
    SolidMesh m;
    glGenVertexArrays(1, &m.vao);
    glGenBuffers(1, &m.vbo);
    glBindVertexArray(m.vao);
    glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(SolidVertex)), v.data(),
                 GL_STATIC_DRAW);
    for (GLuint i = 0; i < 3; ++i) {
        glEnableVertexAttribArray(i);
        glVertexAttribPointer(i, 3, GL_FLOAT, GL_FALSE, sizeof(SolidVertex),
                              reinterpret_cast<void*>(sizeof(glm::vec3) * i));
    }
    m.count = static_cast<GLsizei>(v.size());
    glBindVertexArray(0);
    return m;
}

Mesh upload(const std::vector<Vertex>& v) {
    Mesh m;
    glGenVertexArrays(1, &m.vao);
    glGenBuffers(1, &m.vbo);
    glBindVertexArray(m.vao);
    glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, pos)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, uv)));
    m.count = static_cast<GLsizei>(v.size());
    return m;
}

GLuint upload_texture(const TextureData& t, bool srgb = false) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (srgb && t.channels == 3) {
        // As sRGB with alpha: OpenGL ES 3 (WebGL 2) makes no mipmaps of GL_SRGB8.
        std::vector<std::uint8_t> rgba(t.pixels.size() / 3 * 4, 255);
        for (std::size_t i = 0, n = t.pixels.size() / 3; i < n; ++i)
            std::copy_n(&t.pixels[3 * i], 3, &rgba[4 * i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, t.width, t.height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, rgba.data());
    } else {
        const GLenum format = t.channels == 1 ? GL_RED : GL_RGB;
        const GLint internal = t.channels == 1 ? GL_R8 : GL_RGB8;
        glTexImage2D(GL_TEXTURE_2D, 0, internal, t.width, t.height, 0, format, GL_UNSIGNED_BYTE,
                     t.pixels.data());
    }
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    return tex;
}

/// The shaders' tone_map (ACES fit, then the display curve), for constants set as uniforms.
glm::vec3 tone_map(glm::vec3 c, float exposure) {
    c *= exposure;
    c = glm::clamp((c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f), 0.0f, 1.0f);
    const glm::vec3 s = glm::sqrt(c);
    return s * (1.2f - 0.2f * s);
}

}  // namespace

glm::vec3 ball_colour(int id) {
    if (id == 8) return kBlack;
    if (id >= 9 && id <= 15) return kColours[static_cast<std::size_t>(id - 8)];
    if (id >= 0 && id <= 7) return kColours[static_cast<std::size_t>(id)];
    return {0.5f, 0.5f, 0.5f};
}

bool is_stripe(int id) {
    return id >= 9 && id <= 15;
}

glm::vec3 ball_colour(int id, GameLook look) {
    constexpr std::array<glm::vec3, 7> snooker{{
        {0.70f, 0.04f, 0.04f},  // red
        {0.98f, 0.80f, 0.06f},  // yellow
        {0.02f, 0.38f, 0.16f},  // green
        {0.38f, 0.19f, 0.07f},  // brown
        {0.05f, 0.20f, 0.70f},  // blue
        {0.97f, 0.55f, 0.62f},  // pink
        kBlack,
    }};
    constexpr std::array<glm::vec3, 3> carom{
        {kColours[0], {0.98f, 0.82f, 0.16f}, {0.80f, 0.05f, 0.04f}}};  // white, yellow, red
    switch (look) {
        case GameLook::pool:
            return ball_colour(id);
        case GameLook::snooker:
            if (id == 0) return kColours[0];
            if (id >= 1 && id <= 15) return snooker[0];
            if (id >= 16 && id <= 21) return snooker[static_cast<std::size_t>(id - 15)];
            break;
        case GameLook::carom:
            if (id >= 0 && id <= 2) return carom[static_cast<std::size_t>(id)];
            break;
    }
    return {0.5f, 0.5f, 0.5f};
}

BallView ball_view(const physics::BallState& s, double ball_radius, const glm::dquat& q) {
    return {
        s.id,
        {static_cast<float>(s.pos.x), static_cast<float>(s.pos.y), static_cast<float>(ball_radius)},
        glm::quat(static_cast<float>(q.w), static_cast<float>(q.x), static_cast<float>(q.y),
                  static_cast<float>(q.z))};
}

struct Renderer::Impl {
    physics::Table table;
    float radius;
    RenderSettings settings;
    TableDims dims;
    std::vector<PocketHole> holes;
    /// The six holes (xy centre, z radius) in the shader's 3 x 2 grid: [ix + 3 iy], ix along x
    /// (0 foot end ... 2), iy 0 south, 1 north.
    std::array<glm::vec3, 6> hole_grid{};
    Mesh cloth, cushions, rails, rail_tops;
    GLuint quad_vao = 0, quad_vbo = 0;
    GLuint solid_vao = 0, solid_vbo = 0;
    SolidMesh room, fixtures, lamp_glow, pockets;
    // The table's programs, one per material (cloth, cushion, wood), and the cloth's bake.
    std::array<GLuint, 5> table_progs{};  // by TableMaterial; [3] bakes
    GLuint ball_prog = 0, shadow_prog = 0, cushion_shadow_prog = 0, cue_shadow_prog = 0,
           solid_prog = 0, room_prog = 0;
    GLuint cloth_tex = 0, wood_tex = 0, number_tex = 0;
    // The cloth's view-independent light, baked once over the cloth's footprint.
    GLuint cloth_light_tex = 0;
    glm::vec4 bake_rect{0.0f};
    float baked_exposure =
        0.0f;  // the cloth's baked colour is tone-mapped: re-baked when exposure changes
    std::array<glm::vec4, 3> lamps;
    // The static table's cache (colour and depth), valid for `cache_key`.
    GLuint cache_fbo = 0, cache_colour = 0, cache_depth = 0;
    std::vector<float> cache_key;
    // The moving camera's smaller target, and the last frame's camera and size.
    GLuint small_fbo = 0, small_colour = 0, small_depth = 0;
    glm::ivec2 small_size{0};
    std::vector<float> last_view;
    MovingScale moving_scale{1.0f, 1.0f, 0.0};  // set from the settings by the constructor
    /// While draw(frame, target) runs: the target's samples (a 24-bit depth renderbuffer, as
    /// every OffscreenTarget has), so that use_cache need not ask the GL; 0: unknown.
    int known_samples = 0;

    // Construction, in order.
    void build_hole_grid();
    void upload_table_meshes();
    void make_vertex_arrays();
    void build_programs();
    void upload_textures();
    void place_lamps();
    void draw_room(const glm::mat4& view_proj, const glm::vec3& eye);
    void draw_static_solid(const SolidMesh& mesh, bool lit, const glm::mat4& view_proj,
                           const glm::vec3& eye);

    void draw_table(const glm::mat4& view_proj, const glm::vec3& eye);
    /// Whether the camera moved since the last frame (remembers this one).
    bool camera_moved(const FrameView& frame, int width, int height);
    /// Binds the moving camera's target of `size` (made on first use).
    bool bind_small_target(glm::ivec2 size);
    void free_small_target();
    void draw_passes(const FrameView& frame, int width, int height, bool moving);
    // The frame's passes (Renderer::draw).
    void begin_frame(int width, int height);
    std::optional<CueAxis> cue_axis_of(const FrameView& frame) const;
    void draw_shadows(const FrameView& frame, const std::optional<CueAxis>& cue, const Pass& p);
    void draw_cushion_shadows(const FrameView& frame, const Pass& p);
    void draw_cue_shadow(const CueAxis& cue, const Pass& p);
    /// The screen rectangle (x, y, w, h) round a box, none when it is off screen.
    std::optional<glm::ivec4> screen_box(const Pass& p, glm::vec3 lo, glm::vec3 hi) const;
    void draw_overlays(const FrameView& frame, const Pass& p);
    void draw_ball_in_hand_marks(const BallInHandView& h, const Pass& p);
    std::vector<SolidVertex> tray_mesh() const;
    void draw_balls(const FrameView& frame, const Pass& p);
    void draw_ball(const BallView& b);
    float number_scale(const Pass& p) const;
    /// Flat (lit = false, blended with `alpha`, no depth writes) or lit solid geometry.
    void draw_solid(const std::vector<SolidVertex>& v, bool lit, float alpha,
                    const glm::mat4& view_proj, const glm::vec3& eye);
    void set_cloth_marks(GLuint prog) const;
    void set_table_uniforms(GLuint prog, const glm::mat4& view_proj, const glm::vec3& eye) const;
    void bake_cloth_light();
    bool use_cache(const FrameView& frame, int width, int height, const glm::mat4& view_proj);
    void free_cache() {
        if (cache_fbo) glDeleteFramebuffers(1, &cache_fbo);
        if (cache_colour) glDeleteRenderbuffers(1, &cache_colour);
        if (cache_depth) glDeleteRenderbuffers(1, &cache_depth);
        cache_fbo = cache_colour = cache_depth = 0;
        cache_key.clear();
    }

    void set_common(GLuint prog, const glm::mat4& view_proj, const glm::vec3& eye) const {
        glUseProgram(prog);
        glUniformMatrix4fv(glGetUniformLocation(prog, "u_view_proj"), 1, GL_FALSE,
                           glm::value_ptr(view_proj));
        glUniform3fv(glGetUniformLocation(prog, "u_eye"), 1, glm::value_ptr(eye));
        glUniform4fv(glGetUniformLocation(prog, "u_lamps"), 3, glm::value_ptr(lamps[0]));
        // Lamp power: 1.0 at 1 m gives a well-exposed cloth under each lamp.
        glUniform3f(glGetUniformLocation(prog, "u_lamp_colour"), 0.8f, 0.74f, 0.64f);
        glUniform1f(glGetUniformLocation(prog, "u_exposure"), settings.exposure);
        glUniform3fv(glGetUniformLocation(prog, "u_background"), 1, glm::value_ptr(kBackground));
        glUniform1f(glGetUniformLocation(prog, "u_fog_depth"),
                    settings.fog ? dims.apron_depth * 0.9f : 0.0f);
        glUniform3fv(glGetUniformLocation(prog, "u_cloth_colour"), 1, glm::value_ptr(kClothColour));
        const glm::vec3 cloth_linear = glm::pow(kClothColour, glm::vec3(2.2f));
        glUniform3fv(glGetUniformLocation(prog, "u_cloth_linear"), 1, glm::value_ptr(cloth_linear));
    }
};

// The spots and lines on the cloth of the game's table.
void Renderer::Impl::set_cloth_marks(GLuint prog) const {
    std::vector<physics::Vec2> spots;
    glm::vec3 baulk{0.0f};
    if (settings.look == GameLook::snooker) {
        const physics::SnookerMarkings m = physics::snooker_markings(table);
        for (int c = physics::snooker_ball::yellow; c <= physics::snooker_ball::black; ++c)
            spots.push_back(m.spot(c));
        baulk = {m.baulk_x, m.d_centre().y, m.d_radius};
    } else if (settings.look == GameLook::carom) {
        const physics::CaromSpots c = physics::carom_spots(table);
        spots = {c.top, c.bottom, c.start_left, c.start_right};
    } else {
        spots = {table.foot_spot(), table.head_spot()};
    }
    std::vector<glm::vec2> xy;
    for (const physics::Vec2& v : spots)
        xy.emplace_back(static_cast<float>(v.x), static_cast<float>(v.y));
    glUniform2fv(glGetUniformLocation(prog, "u_spots"), static_cast<GLsizei>(xy.size()),
                 glm::value_ptr(xy[0]));
    glUniform1i(glGetUniformLocation(prog, "u_spot_count"), static_cast<GLint>(xy.size()));
    glUniform3fv(glGetUniformLocation(prog, "u_baulk"), 1, glm::value_ptr(baulk));
}

void Renderer::Impl::set_table_uniforms(GLuint prog, const glm::mat4& view_proj,
                                        const glm::vec3& eye) const {
    set_common(prog, view_proj, eye);
    glUniform1i(glGetUniformLocation(prog, "u_cloth_tex"), 0);
    glUniform1i(glGetUniformLocation(prog, "u_wood_tex"), 1);
    glUniform1i(glGetUniformLocation(prog, "u_cloth_light"), 3);
    glUniform4fv(glGetUniformLocation(prog, "u_bake_rect"), 1, glm::value_ptr(bake_rect));
    glUniform3fv(glGetUniformLocation(prog, "u_holes"), 6, glm::value_ptr(hole_grid[0]));
    glUniform4f(glGetUniformLocation(prog, "u_table"), static_cast<float>(table.length()),
                static_cast<float>(table.width()), dims.cushion_width, dims.rail_width);
    set_cloth_marks(prog);
    glUniform1f(glGetUniformLocation(prog, "u_rail_height"), dims.rail_height);
    const glm::vec3 liner = tone_map(glm::vec3(0.012f, 0.010f, 0.009f), settings.exposure);
    glUniform3fv(glGetUniformLocation(prog, "u_liner_shown"), 1, glm::value_ptr(liner));
}

void Renderer::Impl::bake_cloth_light() {
    // The cloth quad covers the whole footprint; an orthographic view of exactly that
    // rectangle puts one texel per fragment.
    const float out = dims.cushion_width + dims.rail_width;
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    bake_rect = {-out, -out, L + 2 * out, W + 2 * out};
    const int bw = 2048, bh = 1024;  // about 1.5 mm a texel on a 9 ft table
    GLint previous_fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_fbo);
    GLint previous_viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, previous_viewport);
    if (cloth_light_tex) glDeleteTextures(1, &cloth_light_tex);
    baked_exposure = settings.exposure;
    glGenTextures(1, &cloth_light_tex);
    glBindTexture(GL_TEXTURE_2D, cloth_light_tex);
    // RGBA8, not a float format: llvmpipe filters 8-bit textures on a much faster path.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, bw, bh, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, cloth_light_tex, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &fbo);
        throw std::runtime_error("cannot bake the cloth's light: RGBA8 framebuffer incomplete");
    }
    glViewport(0, 0, bw, bh);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    const glm::mat4 ortho = glm::ortho(bake_rect.x, bake_rect.x + bake_rect.z, bake_rect.y,
                                       bake_rect.y + bake_rect.w, -1.0f, 1.0f);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, wood_tex);
    glActiveTexture(GL_TEXTURE0);
    set_table_uniforms(table_progs[3], ortho, {L / 2, W / 2, 3.0f});
    glBindVertexArray(cloth.vao);
    glDrawArrays(GL_TRIANGLES, 0, cloth.count);
    glBindVertexArray(0);
    glDeleteFramebuffers(1, &fbo);
    glBindTexture(GL_TEXTURE_2D, cloth_light_tex);
    // Bilinear without mipmaps: the light is smooth, and llvmpipe samples this way fastest.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_fbo));
    glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2],
               previous_viewport[3]);
}

void Renderer::Impl::draw_table(const glm::mat4& view_proj, const glm::vec3& eye) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, cloth_tex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, wood_tex);
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_2D, cloth_light_tex);
    glActiveTexture(GL_TEXTURE0);
    // Rails and cushions first, so the depth test spares the cloth hidden under them.
    const std::array<std::pair<const Mesh*, GLuint>, 4> parts = {{{&rail_tops, table_progs[4]},
                                                                  {&rails, table_progs[2]},
                                                                  {&cushions, table_progs[1]},
                                                                  {&cloth, table_progs[0]}}};
    for (const auto& [mesh, prog] : parts) {
        set_table_uniforms(prog, view_proj, eye);
        glBindVertexArray(mesh->vao);
        glDrawArrays(GL_TRIANGLES, 0, mesh->count);
    }
    // What shows through the holes, then the room behind the table.
    draw_static_solid(pockets, true, view_proj, eye);
    draw_room(view_proj, eye);
}

void Renderer::Impl::draw_room(const glm::mat4& view_proj, const glm::vec3& eye) {
    const RoomDims r = room_dims(table);
    const float out = dims.cushion_width + dims.rail_width;
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    set_common(room_prog, view_proj, eye);
    glUniform4f(glGetUniformLocation(room_prog, "u_footprint"), -out, -out, L + out, W + out);
    glUniform4f(glGetUniformLocation(room_prog, "u_room"), r.lo.x, r.lo.y, r.hi.x, r.hi.y);
    glUniform1f(glGetUniformLocation(room_prog, "u_floor_z"), r.floor_z);
    glEnable(GL_CULL_FACE);
    glBindVertexArray(room.vao);
    glDrawArrays(GL_TRIANGLES, 0, room.count);
    glDisable(GL_CULL_FACE);
    if (eye.z < lamps[0].z - 0.05f) {
        draw_static_solid(fixtures, true, view_proj, eye);
        draw_static_solid(lamp_glow, false, view_proj, eye);
    }
}

void Renderer::Impl::draw_static_solid(const SolidMesh& mesh, bool lit, const glm::mat4& view_proj,
                                       const glm::vec3& eye) {
    set_common(solid_prog, view_proj, eye);
    glUniform1i(glGetUniformLocation(solid_prog, "u_lit"), lit ? 1 : 0);
    glUniform1f(glGetUniformLocation(solid_prog, "u_alpha"), 1.0f);
    glBindVertexArray(mesh.vao);
    glDrawArrays(GL_TRIANGLES, 0, mesh.count);
}

void Renderer::Impl::draw_solid(const std::vector<SolidVertex>& v, bool lit, float alpha,
                                const glm::mat4& view_proj, const glm::vec3& eye) {
    if (v.empty()) return;
    set_common(solid_prog, view_proj, eye);
    glUniform1i(glGetUniformLocation(solid_prog, "u_lit"), lit ? 1 : 0);
    glUniform1f(glGetUniformLocation(solid_prog, "u_alpha"), alpha);
    const bool blend = alpha < 1.0f;
    if (blend) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    glBindVertexArray(solid_vao);
    glBindBuffer(GL_ARRAY_BUFFER, solid_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(SolidVertex)), v.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size()));
    if (blend) {
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
}

bool Renderer::Impl::use_cache(const FrameView& frame, int width, int height,
                               const glm::mat4& view_proj) {
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    if (target == 0) return false;
    GLint samples = known_samples > 1 ? known_samples : 0;  // GL_SAMPLES says 0 for one
    if (known_samples == 0) {
        GLint type = GL_NONE, depth_bits = 0;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type != GL_RENDERBUFFER) return false;
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                              GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depth_bits);
        glGetIntegerv(GL_SAMPLES, &samples);
        if (depth_bits != 24) return false;
    }
    // OpenGL ES 3 (WebGL 2) blits into no multisampled framebuffer: the table is drawn afresh.
    if (kPlatformGlsl == GlslTarget::es300 && samples > 1) return false;
    std::vector<float> key = {static_cast<float>(width), static_cast<float>(height),
                              static_cast<float>(samples), settings.fog ? 1.0f : 0.0f,
                              settings.exposure};
    const float* vp = glm::value_ptr(view_proj);
    key.insert(key.end(), vp, vp + 16);
    (void)frame;
    if (key != cache_key) {
        free_cache();
        glGenFramebuffers(1, &cache_fbo);
        glGenRenderbuffers(1, &cache_colour);
        glGenRenderbuffers(1, &cache_depth);
        glBindRenderbuffer(GL_RENDERBUFFER, cache_colour);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, cache_depth);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width,
                                         height);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, cache_fbo);
        glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  cache_colour);
        glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  cache_depth);
        if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            free_cache();
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
            return false;
        }
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        draw_table(view_proj, frame.camera.eye);
        cache_key = key;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, cache_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height,
                      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    return true;
}

void Renderer::Impl::build_hole_grid() {
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    std::array<bool, 6> used{};
    for (std::size_t i = 0; i < holes.size() && i < 6; ++i) {
        const glm::vec2 c = holes[i].centre;
        const int ix = std::clamp(static_cast<int>(std::floor(c.x / (0.5f * L) + 0.5f)), 0, 2);
        const std::size_t k = static_cast<std::size_t>(ix + (c.y > 0.5f * W ? 3 : 0));
        // A table whose pockets do not form the grid keeps them in order (hole_distance then
        // only approximates the nearest).
        const std::size_t slot = used[k] ? i : k;
        used[slot] = true;
        hole_grid[slot] = {c, holes[i].radius};
    }
}

void Renderer::Impl::upload_table_meshes() {
    const TableMesh mesh = build_table_mesh(table);
    cloth = upload(mesh.cloth);
    cushions = upload(mesh.cushions);
    // The rail tops (flat, at rail height) apart from the bevels and sides: their diffuse
    // light is baked.
    std::vector<Vertex> tops, rest;
    for (std::size_t i = 0; i + 2 < mesh.rails.size(); i += 3) {
        bool top = true;
        for (std::size_t k = i; k < i + 3; ++k)
            top = top && std::abs(mesh.rails[k].normal.z) > 0.999f &&
                  std::abs(mesh.rails[k].pos.z - dims.rail_height) < 1e-5f;
        (top ? tops : rest)
            .insert((top ? tops : rest).end(), mesh.rails.begin() + static_cast<std::ptrdiff_t>(i),
                    mesh.rails.begin() + static_cast<std::ptrdiff_t>(i + 3));
    }
    rails = upload(rest);
    rail_tops = upload(tops);
}

// The full-screen quad and the streamed solid geometry (position, normal, colour).
void Renderer::Impl::make_vertex_arrays() {
    const float corners[] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    glGenVertexArrays(1, &quad_vao);
    glGenBuffers(1, &quad_vbo);
    glBindVertexArray(quad_vao);
    glBindBuffer(GL_ARRAY_BUFFER, quad_vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);

    glGenVertexArrays(1, &solid_vao);
    glGenBuffers(1, &solid_vbo);
    glBindVertexArray(solid_vao);
    glBindBuffer(GL_ARRAY_BUFFER, solid_vbo);
    for (GLuint i = 0; i < 3; ++i) {
        glEnableVertexAttribArray(i);
        glVertexAttribPointer(i, 3, GL_FLOAT, GL_FALSE, sizeof(SolidVertex),
                              reinterpret_cast<void*>(sizeof(glm::vec3) * i));
    }
    glBindVertexArray(0);
}

void Renderer::Impl::build_programs() {
    for (int i = 0; i < 5; ++i)
        table_progs[static_cast<std::size_t>(i)] =
            build_program(glsl::kTableVert, table_fragment_source(static_cast<TableMaterial>(i)));
    ball_prog = build_program(glsl::kBallVert, glsl::kBallFrag);
    shadow_prog = build_program(glsl::kShadowVert, glsl::kShadowFrag);
    cue_shadow_prog = build_program(glsl::kCueShadowVert, glsl::kCueShadowFrag);
    cushion_shadow_prog = build_program(glsl::kTableVert, glsl::kCushionShadowFrag);
    solid_prog = build_program(glsl::kSolidVert, glsl::kSolidFrag);
    room_prog = build_program(glsl::kRoomVert, glsl::kRoomFrag);
}

void Renderer::Impl::upload_textures() {
    cloth_tex = upload_texture(make_cloth_texture());
    // One mip level per pixel, not two: the cloth is most of the frame, and the nap's levels
    // differ too little for the switch between them to show (looked at in the cue view).
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    wood_tex = upload_texture(make_wood_texture(), true);
    number_tex = upload_texture(make_number_atlas(settings.number_font));
    // Mipmaps down to 4 texels a cell, so far-away numbers blur instead of mixing cells.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

// Three shaded lamps along the table's long axis, about 1 m above the cloth.
void Renderer::Impl::place_lamps() {
    const std::vector<Lamp> l = table_lamps(table);
    for (std::size_t i = 0; i < 3; ++i) lamps[i] = {l[i].pos, l[i].radius};
    room = upload_solid(room_mesh(table));
    fixtures = upload_solid(fixtures_mesh(table));
    lamp_glow = upload_solid(lamp_glow_mesh(table));
    pockets = upload_solid(pocket_mesh(table));
}

Renderer::Renderer(const physics::Table& table, double ball_radius, RenderSettings settings)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.table = table;
    m.radius = static_cast<float>(ball_radius);
    m.settings = settings;
    m.moving_scale =
        MovingScale(settings.moving_scale, settings.moving_scale_lowest, settings.moving_budget_ms);
    m.dims = table_dims(table);
    m.holes = pocket_holes(table);
    m.build_hole_grid();
    m.upload_table_meshes();
    m.make_vertex_arrays();
    m.build_programs();
    m.upload_textures();
    m.place_lamps();
    m.bake_cloth_light();
}

Renderer::~Renderer() {
    Impl& m = *impl_;
    for (Mesh* mesh : {&m.cloth, &m.cushions, &m.rails, &m.rail_tops}) {
        glDeleteBuffers(1, &mesh->vbo);
        glDeleteVertexArrays(1, &mesh->vao);
    }
    glDeleteBuffers(1, &m.quad_vbo);
    glDeleteVertexArrays(1, &m.quad_vao);
    glDeleteBuffers(1, &m.solid_vbo);
    glDeleteVertexArrays(1, &m.solid_vao);
    for (SolidMesh* mesh : {&m.room, &m.fixtures, &m.lamp_glow, &m.pockets}) {
        glDeleteBuffers(1, &mesh->vbo);
        glDeleteVertexArrays(1, &mesh->vao);
    }
    for (GLuint p : m.table_progs) glDeleteProgram(p);
    for (GLuint p : {m.ball_prog, m.shadow_prog, m.cushion_shadow_prog, m.cue_shadow_prog,
                     m.solid_prog, m.room_prog})
        glDeleteProgram(p);
    glDeleteTextures(1, &m.cloth_light_tex);
    glDeleteTextures(1, &m.cloth_tex);
    glDeleteTextures(1, &m.wood_tex);
    glDeleteTextures(1, &m.number_tex);
    m.free_cache();
    m.free_small_target();
}

float Renderer::moving_scale() const {
    return impl_->moving_scale.scale();
}

RenderSettings& Renderer::settings() {
    return impl_->settings;
}

void Renderer::draw(const FrameView& frame, int width, int height) {
    Impl& m = *impl_;
    if (m.settings.exposure != m.baked_exposure) m.bake_cloth_light();
    const bool moving = m.camera_moved(frame, width, height) || frame.camera_moving;
    const float scale = m.moving_scale.scale();
    const glm::ivec2 small{static_cast<int>(static_cast<float>(width) * scale),
                           static_cast<int>(static_cast<float>(height) * scale)};
    if (!moving || scale >= 1.0f || small.x < 16 || small.y < 16) {
        m.draw_passes(frame, width, height, moving);
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    // Drawn smaller, then scaled up into the caller's framebuffer.
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    if (!m.bind_small_target(small)) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
        m.draw_passes(frame, width, height, moving);
        return;
    }
    m.draw_passes(frame, small.x, small.y, moving);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m.small_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
    glViewport(0, 0, width, height);
    glBlitFramebuffer(0, 0, small.x, small.y, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
    glFinish();  // a software renderer draws at the flush: this is the frame's real cost
    m.moving_scale.record(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
}

void Renderer::draw(const FrameView& frame, OffscreenTarget& target) {
    target.bind();
    impl_->known_samples = target.samples();
    draw(frame, target.width(), target.height());
    impl_->known_samples = 0;
}

// The passes of one frame into the bound framebuffer's (0, 0, width, height).
void Renderer::Impl::draw_passes(const FrameView& frame, int width, int height, bool moving) {
    const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
    const Pass p{frame.camera.projection(aspect) * frame.camera.view(), frame.camera.eye, width,
                 height, 1.0f / std::tan(glm::radians(frame.camera.fovy_deg) / 2)};
    begin_frame(width, height);
    // 1. The room and the table: from the cache when it can be (its copy overwrites colour and
    // depth, so no clear), else cleared and drawn. A moving camera would remake it every frame.
    if (!(settings.cache_table && !moving && use_cache(frame, width, height, p.view_proj))) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        draw_table(p.view_proj, p.eye);
    }
    const std::optional<CueAxis> cue = cue_axis_of(frame);
    // 2. Soft shadows and contact occlusion, multiplied onto the cloth and the cushions.
    if (settings.shadows) draw_shadows(frame, cue, p);
    // 3. On the cloth: the aim guide, the kitchen and the ball-in-hand ring; the tray.
    draw_overlays(frame, p);
    // 4. The balls (the tray's too), then the ball in hand, see-through.
    draw_balls(frame, p);
    // 5. The cue stick.
    if (cue) draw_solid(cue_mesh(*cue), true, 1.0f, p.view_proj, p.eye);
    glBindVertexArray(0);
}

bool Renderer::Impl::camera_moved(const FrameView& frame, int width, int height) {
    const Camera& c = frame.camera;
    std::vector<float> view = {static_cast<float>(width), static_cast<float>(height), c.fovy_deg,
                               c.near_m, c.far_m};
    for (const glm::vec3& v : {c.eye, c.target, c.up}) view.insert(view.end(), {v.x, v.y, v.z});
    const bool moved = !last_view.empty() && view != last_view;
    last_view = view;
    return moved;
}

bool Renderer::Impl::bind_small_target(glm::ivec2 size) {
    if (small_fbo && size == small_size) {
        glBindFramebuffer(GL_FRAMEBUFFER, small_fbo);
        return true;
    }
    free_small_target();
    glGenFramebuffers(1, &small_fbo);
    glGenRenderbuffers(1, &small_colour);
    glGenRenderbuffers(1, &small_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, small_colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.x, size.y);
    glBindRenderbuffer(GL_RENDERBUFFER, small_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.x, size.y);
    glBindFramebuffer(GL_FRAMEBUFFER, small_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, small_colour);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, small_depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        free_small_target();
        return false;
    }
    small_size = size;
    return true;
}

void Renderer::Impl::free_small_target() {
    if (small_fbo) glDeleteFramebuffers(1, &small_fbo);
    if (small_colour) glDeleteRenderbuffers(1, &small_colour);
    if (small_depth) glDeleteRenderbuffers(1, &small_depth);
    small_fbo = small_colour = small_depth = 0;
    small_size = {0, 0};
}

void Renderer::Impl::begin_frame(int width, int height) {
    glViewport(0, 0, width, height);
    const glm::vec3 bg = glm::pow(kBackground, glm::vec3(1.0f / 2.2f));
    glClearColor(bg.x, bg.y, bg.z, 1.0f);
    glClearDepth(1.0);
    glDisable(
        GL_SCISSOR_TEST);  // a UI drawn before may have left it on; clear and copy need it off
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);  // used for the room only
    glFrontFace(GL_CCW);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

std::optional<CueAxis> Renderer::Impl::cue_axis_of(const FrameView& frame) const {
    if (!frame.cue) return std::nullopt;
    const CueView& c = *frame.cue;
    // The butt rises over the rail when the rail forces it, as a real cue would.
    const float elevation =
        drawn_cue_elevation(table, radius, c.cue_ball, c.heading, c.elevation, c.tip_offset);
    return cue_axis(c.cue_ball, radius, c.heading, elevation, c.tip_offset, c.pull_back);
}

void Renderer::Impl::draw_shadows(const FrameView& frame, const std::optional<CueAxis>& cue,
                                  const Pass& p) {
    set_common(shadow_prog, p.view_proj, p.eye);
    glUniform1f(glGetUniformLocation(shadow_prog, "u_radius"), radius);
    const GLint centre = glGetUniformLocation(shadow_prog, "u_centre");
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);
    glDepthMask(GL_FALSE);
    glBindVertexArray(quad_vao);
    for (const BallView& b : frame.balls) {
        if (b.centre.z < 0.0f) continue;  // dropping into a pocket: no shadow on the cloth
        glUniform3fv(centre, 1, glm::value_ptr(b.centre));
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    draw_cushion_shadows(frame, p);
    if (cue) draw_cue_shadow(*cue, p);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

// On the cushions: only the balls close enough to one to shade it, one pass per ball,
// scissored to the screen box of the cushion round it, so only those few pixels run the shader.
void Renderer::Impl::draw_cushion_shadows(const FrameView& frame, const Pass& p) {
    std::array<glm::vec3, 16> near{};
    int near_count = 0;
    const float near_cushion = 4.0f * radius, Lt = static_cast<float>(table.length()),
                Wt = static_cast<float>(table.width());
    for (const BallView& b : frame.balls) {
        const bool close = b.centre.x < near_cushion || b.centre.x > Lt - near_cushion ||
                           b.centre.y < near_cushion || b.centre.y > Wt - near_cushion;
        if (close && b.centre.z > 0.0f && near_count < 16)
            near[static_cast<std::size_t>(near_count++)] = b.centre;
    }
    if (near_count == 0) return;
    set_common(cushion_shadow_prog, p.view_proj, p.eye);
    glUniform1i(glGetUniformLocation(cushion_shadow_prog, "u_ball_count"), 1);
    glUniform1f(glGetUniformLocation(cushion_shadow_prog, "u_radius"), radius);
    const GLint u_balls = glGetUniformLocation(cushion_shadow_prog, "u_balls");
    glBindVertexArray(cushions.vao);
    glEnable(GL_SCISSOR_TEST);
    for (int k = 0; k < near_count; ++k) {
        const glm::vec3 c = near[static_cast<std::size_t>(k)];
        const glm::vec3 lo{c.x - 4.0f * radius, c.y - 4.0f * radius, 0.0f};
        const glm::vec3 hi{c.x + 4.0f * radius, c.y + 4.0f * radius, dims.rail_height};
        const std::optional<glm::ivec4> box = screen_box(p, lo, hi);
        if (!box) continue;
        glScissor(box->x, box->y, box->z, box->w);
        glUniform3fv(u_balls, 1, glm::value_ptr(c));
        glDrawArrays(GL_TRIANGLES, 0, cushions.count);
    }
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(quad_vao);
}

std::optional<glm::ivec4> Renderer::Impl::screen_box(const Pass& p, glm::vec3 lo,
                                                     glm::vec3 hi) const {
    glm::vec2 a{1e9f}, b{-1e9f};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 q{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                          corner & 4 ? hi.z : lo.z};
        const glm::vec4 clip = p.view_proj * glm::vec4(q, 1.0f);
        if (clip.w <= 1e-4f) return glm::ivec4(0, 0, p.width, p.height);  // behind the eye
        a = glm::min(a, glm::vec2(clip) / clip.w);
        b = glm::max(b, glm::vec2(clip) / clip.w);
    }
    if (b.x < -1.0f || b.y < -1.0f || a.x > 1.0f || a.y > 1.0f) return std::nullopt;
    const auto px = [](float v, int size) {
        return std::clamp(
            static_cast<int>(std::floor((0.5f * v + 0.5f) * static_cast<float>(size))), 0, size);
    };
    const int x0 = px(a.x, p.width), y0 = px(a.y, p.height);
    const int x1 = std::min(px(b.x, p.width) + 1, p.width),
              y1 = std::min(px(b.y, p.height) + 1, p.height);
    return glm::ivec4(x0, y0, x1 - x0, y1 - y0);
}

// The cue's shadow, within cue_shadow_rect (never beyond the table).
void Renderer::Impl::draw_cue_shadow(const CueAxis& cue, const Pass& p) {
    const glm::vec3 a = cue.tip, b = cue.tip - kCueLength * cue.dir;
    const glm::vec4 rect = cue_shadow_rect(table, cue);
    if (rect.x >= rect.z || rect.y >= rect.w) return;
    set_common(cue_shadow_prog, p.view_proj, p.eye);
    glUniform4fv(glGetUniformLocation(cue_shadow_prog, "u_rect"), 1, glm::value_ptr(rect));
    glUniform3fv(glGetUniformLocation(cue_shadow_prog, "u_cue_a"), 1, glm::value_ptr(a));
    glUniform3fv(glGetUniformLocation(cue_shadow_prog, "u_cue_b"), 1, glm::value_ptr(b));
    glUniform2f(glGetUniformLocation(cue_shadow_prog, "u_cue_r"), cue_radius(0.0f),
                cue_radius(kCueLength));
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

void Renderer::Impl::draw_overlays(const FrameView& frame, const Pass& p) {
    std::vector<SolidVertex> guide;
    if (frame.aim) {
        const AimView& aim = *frame.aim;
        const glm::vec3 foul{1.0f, 0.2f, 0.15f};
        const auto colour = [&](glm::vec3 c) { return aim.illegal ? foul : c; };
        add_ribbon(guide, aim.cue_path, 0.0012f, 0.0006f, colour({0.95f, 0.95f, 0.95f}));
        add_ribbon(guide, aim.object_path, 0.0012f, 0.0006f, colour({1.0f, 0.85f, 0.3f}));
        add_ribbon(guide, aim.cue_after, 0.0009f, 0.0006f, colour({0.6f, 0.8f, 1.0f}));
        if (aim.ghost)
            add_ring(guide, *aim.ghost, radius, 0.0012f, 0.0007f, colour({0.95f, 0.95f, 0.95f}));
        for (const AimMark& k : aim.marks)
            add_ring(guide, k.centre, k.radius, k.half_width, 0.0007f, k.colour);
    }
    draw_solid(guide, false, 0.7f, p.view_proj, p.eye);
    if (frame.ball_in_hand) draw_ball_in_hand_marks(*frame.ball_in_hand, p);
    if (!frame.tray.empty()) draw_solid(tray_mesh(), true, 1.0f, p.view_proj, p.eye);
}

// The kitchen shaded when placement is restricted to it, a ring on the cloth round the cue
// ball's place (red where it may not go).
void Renderer::Impl::draw_ball_in_hand_marks(const BallInHandView& h, const Pass& p) {
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    if (h.kitchen_only) {
        std::vector<SolidVertex> kitchen;
        add_patch(kitchen, {0.0f, 0.0f}, {L / 4, W}, 0.0005f, {0.85f, 0.92f, 1.0f});
        draw_solid(kitchen, false, 0.07f, p.view_proj, p.eye);
        std::vector<SolidVertex> head_string;
        add_ribbon(head_string, {{L / 4, 0.0f}, {L / 4, W}}, 0.0015f, 0.0006f, {0.9f, 0.95f, 1.0f});
        draw_solid(head_string, false, 0.5f, p.view_proj, p.eye);
    }
    if (h.d_only) {
        std::vector<SolidVertex> d;
        add_half_disc(d, {h.d_only->x, h.d_only->y}, h.d_only->z, 1.5707963f, 4.7123890f, 0.0005f,
                      {0.85f, 0.92f, 1.0f});
        draw_solid(d, false, 0.07f, p.view_proj, p.eye);
    }
    std::vector<SolidVertex> ring;
    add_ring(ring, h.pos, radius * 1.3f, 0.003f, 0.0007f, h.legal ? glm::vec3(0.95f) : kRefused);
    draw_solid(ring, false, 0.85f, p.view_proj, p.eye);
}

// The ball-return tray along the south side: a dark wooden trough against the apron.
std::vector<SolidVertex> Renderer::Impl::tray_mesh() const {
    std::vector<SolidVertex> tray;
    const float L = static_cast<float>(table.length());
    const float out = dims.cushion_width + dims.rail_width;
    const float len = tray_length(radius), x0 = L / 2 - len / 2, x1 = L / 2 + len / 2;
    const float wall = dims.tray_wall, floor_z = dims.tray_floor, top = floor_z + 1.3f * radius;
    const float y_in = -out, y_out = -out - dims.tray_width - 2 * wall;
    const glm::vec3 wood{0.22f, 0.08f, 0.04f}, lining{0.05f, 0.05f, 0.05f};
    add_box(tray, {x0, y_out, floor_z - wall}, {x1, y_in, floor_z}, lining);    // floor
    add_box(tray, {x0, y_out, floor_z - wall}, {x1, y_out + wall, top}, wood);  // outer wall
    add_box(tray, {x0, y_in - wall, floor_z - wall}, {x1, y_in, top - 0.5f * radius}, wood);
    add_box(tray, {x0 - wall, y_out, floor_z - wall}, {x0, y_in, top}, wood);  // ends
    add_box(tray, {x1, y_out, floor_z - wall}, {x1 + wall, y_in, top}, wood);
    return tray;
}

void Renderer::Impl::draw_balls(const FrameView& frame, const Pass& p) {
    set_common(ball_prog, p.view_proj, p.eye);
    glUniform1f(glGetUniformLocation(ball_prog, "u_radius"), radius);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, number_tex);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(glGetUniformLocation(ball_prog, "u_numbers"), 2);
    glUniform1f(glGetUniformLocation(ball_prog, "u_number_scale"), number_scale(p));
    const GLint u_tint = glGetUniformLocation(ball_prog, "u_tint");
    const GLint u_alpha = glGetUniformLocation(ball_prog, "u_alpha");
    glUniform4f(u_tint, 0.0f, 0.0f, 0.0f, 0.0f);
    glUniform1f(u_alpha, 1.0f);
    glBindVertexArray(quad_vao);
    for (const BallView& b : frame.balls) draw_ball(b);
    // The tray's balls, numbers up and upright as seen from the overhead camera.
    const glm::quat numbers_up = glm::angleAxis(-1.5707963f, glm::vec3(0, 0, 1)) *
                                 glm::angleAxis(-1.5707963f, glm::vec3(0, 1, 0));
    for (std::size_t k = 0; k < frame.tray.size() && k < 15; ++k)
        draw_ball({frame.tray[k], tray_slot(table, radius, static_cast<int>(k)), numbers_up});
    if (frame.ball_in_hand) {
        // The ball in hand: see-through, red when it may not go there.
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        glUniform1f(u_alpha, 0.6f);
        if (!frame.ball_in_hand->legal)
            glUniform4f(u_tint, kRefused.x, kRefused.y, kRefused.z, 0.55f);
        draw_ball({0, {frame.ball_in_hand->pos, radius}, glm::quat(1, 0, 0, 0)});
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
}

void Renderer::Impl::draw_ball(const BallView& b) {
    const glm::mat3 rot = glm::mat3_cast(b.orientation);
    const glm::vec3 colour = ball_colour(b.id, settings.look);
    const bool pool = settings.look == GameLook::pool;
    const bool cue = b.id == 0 || (settings.look == GameLook::carom && b.id == 1);
    glUniform3fv(glGetUniformLocation(ball_prog, "u_centre"), 1, glm::value_ptr(b.centre));
    glUniformMatrix3fv(glGetUniformLocation(ball_prog, "u_rotation"), 1, GL_FALSE,
                       glm::value_ptr(rot));
    glUniform3fv(glGetUniformLocation(ball_prog, "u_colour"), 1, glm::value_ptr(colour));
    glUniform1i(glGetUniformLocation(ball_prog, "u_stripe"), pool && is_stripe(b.id) ? 1 : 0);
    glUniform1i(glGetUniformLocation(ball_prog, "u_cue"), cue ? 1 : 0);
    glUniform1i(glGetUniformLocation(ball_prog, "u_plain"), pool ? 0 : 1);
    glUniform1i(glGetUniformLocation(ball_prog, "u_number"),
                pool && b.id >= 1 && b.id <= 15 ? b.id : 0);
    glDrawArrays(GL_TRIANGLES, 0, 6);
}

// How much larger the numbers are drawn than on a real ball: 1 where a ball is large on screen,
// up to 1.6 where it is small (the overhead view of the whole table), so they stay readable.
float Renderer::Impl::number_scale(const Pass& p) const {
    const glm::vec3 centre{static_cast<float>(table.length()) / 2,
                           static_cast<float>(table.width()) / 2, radius};
    const glm::vec4 a = p.view_proj * glm::vec4(centre, 1.0f);
    const float pixels =
        radius / std::max(a.w, 1e-3f) * p.focal * 0.5f * static_cast<float>(p.height);
    return std::clamp(1.0f + (24.0f - pixels) / 20.0f, 1.0f, 1.6f);
}

OffscreenTarget::OffscreenTarget(int width, int height, int samples)
    : width_(width), height_(height), samples_(1) {
    GLint max_samples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples_ = std::max(1, std::min(samples, static_cast<int>(max_samples)));
    if (samples_ > 1) {  // one sample is read where it was drawn
        glGenFramebuffers(1, &resolve_fbo_);
        glGenRenderbuffers(1, &resolve_colour_);
        glBindRenderbuffer(GL_RENDERBUFFER, resolve_colour_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  resolve_colour_);
    }

    glGenFramebuffers(1, &draw_fbo_);
    glGenRenderbuffers(1, &draw_colour_);
    glGenRenderbuffers(1, &draw_depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, draw_colour_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_RGBA8, width,
                                     height);
    glBindRenderbuffer(GL_RENDERBUFFER, draw_depth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0,
                                     GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_colour_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, draw_depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("offscreen framebuffer incomplete: try fewer samples");
}

OffscreenTarget::~OffscreenTarget() {
    glDeleteFramebuffers(1, &draw_fbo_);
    glDeleteFramebuffers(1, &resolve_fbo_);
    glDeleteRenderbuffers(1, &draw_colour_);
    glDeleteRenderbuffers(1, &draw_depth_);
    glDeleteRenderbuffers(1, &resolve_colour_);
}

void OffscreenTarget::bind() {
    glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
    glViewport(0, 0, width_, height_);
}

void OffscreenTarget::resolve() {
    // A single-sampled image needs no copy (a whole-view blit a frame, dear on a CPU renderer).
    if (samples_ <= 1) {
        glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
        return;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
}

}  // namespace render
