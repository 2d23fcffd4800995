#include "render/shaders.hpp"

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

namespace render {

std::string shader_source(std::string_view body, GlslTarget target) {
    std::string s = target == GlslTarget::gl33
                        ? "#version 330 core\n"
                        : "#version 300 es\nprecision highp float;\nprecision highp int;\n";
    s += body;
    return s;
}

namespace {

unsigned compile(GLenum type, const std::string& source) {
    GLuint s = glCreateShader(type);
    const char* src = source.c_str();
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw std::runtime_error(std::string("shader compile failed: ") + log);
    }
    return s;
}

}  // namespace

unsigned build_program(std::string_view vertex_body, std::string_view fragment_body,
                       GlslTarget target) {
    GLuint vs = compile(GL_VERTEX_SHADER, shader_source(vertex_body, target));
    GLuint fs =
        compile(GL_FRAGMENT_SHADER,
                shader_source(std::string(glsl::kCommon) + std::string(fragment_body), target));
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetProgramInfoLog(p, sizeof log, nullptr, log);
        glDeleteProgram(p);
        throw std::runtime_error(std::string("shader link failed: ") + log);
    }
    return p;
}

namespace glsl {

const char* const kCommon = R"(
// Lamps over the table: position (unit: m) and radius of the shade's opening in w.
uniform vec4 u_lamps[3];
uniform vec3 u_lamp_colour;

// A ball's soft shadow at point p (normal n): the light that still reaches p, as a factor.
// Per lamp, the fraction of the lamp's disc that the ball's disc covers as seen from p,
// weighted by that lamp's share of the light there; and the ambient occlusion of a sphere,
// (R/d)^2 cos(theta). Used on the cloth (n = z) and on the cushions.
float ball_shadow_keep(vec3 p, vec3 n, vec3 centre, float radius) {
    vec3 to_ball = centre - p;
    float db = length(to_ball);
    vec3 bdir = to_ball / db;
    float ab = asin(min(radius / db, 1.0));
    float lit = 0.0, shadowed = 0.0;
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - p;
        float dl = length(d);
        vec3 ldir = d / dl;
        float w = smoothstep(0.25, 0.6, ldir.z) * max(dot(n, ldir), 0.0) / (dl * dl);
        float al = asin(min(u_lamps[i].w / dl, 1.0));
        float sep = acos(clamp(dot(ldir, bdir), -1.0, 1.0));
        float cover = 1.0 - smoothstep(abs(ab - al), ab + al, sep);
        cover *= min(1.0, (ab * ab) / (al * al));
        lit += w;
        shadowed += w * cover;
    }
    float ambient = 0.035;
    float ao = (radius * radius) / (db * db) * max(dot(n, bdir), 0.0);
    return (lit - shadowed + ambient * (1.0 - ao)) / (lit + ambient);
}
uniform vec3 u_eye;
uniform float u_exposure;
uniform vec3 u_background;   // linear
uniform float u_fog_depth;   // below the cloth, the depth at which the fog is complete (unit: m); 0: off

vec3 to_linear(vec3 c) { return pow(c, vec3(2.2)); }
uniform vec3 u_cloth_linear;  // the cloth's colour, linear (to_linear(u_cloth_colour), set once)

// Direct light from the lamps on a surface at p with normal n: diffuse irradiance and
// Blinn-Phong specular toward the eye (exponent `shine`, weight `spec`).
vec3 lamps_light(vec3 p, vec3 n, vec3 albedo, float shine, float spec) {
    vec3 v = normalize(u_eye - p);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - p;
        float dist2 = dot(d, d);
        vec3 l = d * inversesqrt(dist2);
        // The shade limits the light to a cone: full below it, gone beyond ~70 degrees.
        float cone = smoothstep(0.25, 0.6, l.z);
        float ndl = max(dot(n, l), 0.0);
        vec3 h = normalize(l + v);
        float s = spec * pow(max(dot(n, h), 0.0), shine) * (shine + 8.0) / 25.0;
        sum += u_lamp_colour * cone * (albedo * ndl + s * step(0.0, dot(n, l))) / dist2;
    }
    return sum;
}

// Diffuse light only (the cloth): cheaper, for the largest area on screen.
vec3 lamps_diffuse(vec3 p, vec3 n, vec3 albedo) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - p;
        float inv = inversesqrt(dot(d, d));
        vec3 l = d * inv;
        sum += smoothstep(0.25, 0.6, l.z) * max(dot(n, l), 0.0) * inv * inv;
    }
    return u_lamp_colour * albedo * sum;
}

// ACES filmic fit (Narkowicz 2015), then display gamma.
vec3 tone_map(vec3 c) {
    c *= u_exposure;
    c = clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
    // Display gamma 2.2 without pow (which llvmpipe evaluates slowly, per channel): with
    // s = sqrt(c), s (1.2 - 0.2 s) is within 0.02 of c^(1/2.2) over [0.001, 1].
    vec3 s = sqrt(c);
    return s * (1.2 - 0.2 * s);
}

// Height fog: the table below the cloth fades into the room's darkness.
vec3 apply_fog(vec3 c, vec3 p) {
    if (u_fog_depth <= 0.0) return c;
    float f = clamp(-p.z / u_fog_depth, 0.0, 1.0);
    return mix(c, u_background, f * f * (3.0 - 2.0 * f));
}
)";

const char* const kTableVert = R"(
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_view_proj;
out vec3 v_pos;
out vec3 v_normal;
out vec2 v_uv;
void main() {
    v_pos = a_pos;
    v_normal = a_normal;
    v_uv = a_uv;
    gl_Position = u_view_proj * vec4(a_pos, 1.0);
}
)";

// The table's materials. The program is built once per material with `kMaterial` set
// (table_fragment_source; 4 is the rail tops): llvmpipe runs both sides of every branch, so one
// shader for all materials would pay for all of them on every pixel. The cloth's light is
// view-independent (diffuse lamps, painted pockets, liner, foot spot), so material 3 bakes it once
// into a texture over the table's footprint and the cloth (material 0) only samples it; so does the
// rail tops' diffuse light, wood grain, sights and leather lips (material 4 adds highlights).
const char* const kTableFrag = R"(
in vec3 v_pos;
in vec3 v_normal;
in vec2 v_uv;
layout(location = 0) out vec4 o_colour;
uniform sampler2D u_cloth_tex;
uniform sampler2D u_wood_tex;
uniform sampler2D u_cloth_light; // baked by material 3 (see there)
uniform vec3 u_liner_shown;      // the pockets' leather liner, tone-mapped
uniform vec4 u_bake_rect;        // the baked texture's footprint: xy min corner, zw size (unit: m)
uniform vec3 u_holes[6];       // xy centre, z radius (unit: m), as a 3 x 2 grid (hole_distance)
uniform vec4 u_table;          // length, width, cushion width, rail width (unit: m)
uniform vec3 u_cloth_colour;   // sRGB
uniform vec2 u_spots[8];       // the spots on the cloth (pool: foot and head; snooker: colours)
uniform int u_spot_count;
uniform vec3 u_baulk;          // snooker: baulk line x, the D's centre y and radius (z 0: none)
uniform float u_rail_height;   // (unit: m)

// Distance to the nearest pocket hole's edge (negative inside). The holes come in a 3 x 2
// grid (u_holes[ix + 3 iy]: ix 0..2 along x, iy 0 south, 1 north), so the nearest is found
// from the position instead of a loop over all six.
float hole_distance(vec2 p, out float radius) {
    int ix = int(clamp(floor(p.x / (0.5 * u_table.x) + 0.5), 0.0, 2.0));
    int iy = p.y > 0.5 * u_table.y ? 1 : 0;
    vec3 h = u_holes[ix + 3 * iy];
    radius = h.z;
    return length(p - h.xy) - h.z;
}

// Mother-of-pearl sights: three per short rail, six per long rail, on the rail's centre line.
float diamond(vec2 p) {
    float L = u_table.x, W = u_table.y;
    float mid = u_table.z + 0.5 * u_table.w;
    float best = 1e9;
    vec2 q;
    if (p.y < 0.0 || p.y > W) {
        float k = clamp(floor(p.x / (L / 8.0) + 0.5), 1.0, 7.0);
        if (k == 4.0) k = 3.0;
        q = vec2(p.x - k * L / 8.0, p.y < 0.0 ? p.y + mid : p.y - W - mid);
        best = abs(q.x) + abs(q.y) * 0.55;
    }
    if (p.x < 0.0 || p.x > L) {
        float k = clamp(floor(p.y / (W / 4.0) + 0.5), 1.0, 3.0);
        q = vec2(p.y - k * W / 4.0, p.x < 0.0 ? p.x + mid : p.x - L - mid);
        best = min(best, abs(q.x) + abs(q.y) * 0.55);
    }
    return best;
}

// x^(2^k) by k squarings: a highlight's power without llvmpipe's slow pow.
float pow2k(float x, int k) {
    for (int i = 0; i < k; ++i) x *= x;
    return x;
}

// The lamps' highlights alone (the rail tops, whose diffuse light is baked); Blinn-Phong with
// the exponent 2^k.
vec3 lamps_specular(vec3 p, vec3 n, int k, float spec) {
    vec3 v = normalize(u_eye - p);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - p;
        float inv = inversesqrt(dot(d, d));
        vec3 l = d * inv;
        float x = max(dot(n, normalize(l + v)), 0.0);
        sum += vec3(smoothstep(0.25, 0.6, l.z) * pow2k(x, k) * (inv * inv));
    }
    float shine = float(1 << k);
    return u_lamp_colour * sum * (spec * (shine + 8.0) / 25.0);
}

// lamps_light with the exponent 2^k, by squarings.
vec3 lamps_light_cheap(vec3 p, vec3 n, vec3 albedo, int k, float spec) {
    vec3 v = normalize(u_eye - p);
    float shine = float(1 << k);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - p;
        float inv = inversesqrt(dot(d, d));
        vec3 l = d * inv;
        float cone = smoothstep(0.25, 0.6, l.z);
        float ndl = dot(n, l);
        float s = spec * pow2k(max(dot(n, normalize(l + v)), 0.0), k) * (shine + 8.0) / 25.0;
        sum += cone * (albedo * max(ndl, 0.0) + s * step(0.0, ndl)) * (inv * inv);
    }
    return u_lamp_colour * sum;
}

void main() {
    vec3 c;
    if (kMaterial == 0) {
        // The cloth: baked light times this pixel's nap.
        // The cloth: the baked, already tone-mapped colour, modulated by this pixel's nap by
        // the baked amount (the cloth is at z = 0: no fog).
        float nap = texture(u_cloth_tex, v_uv * 12.0).r;
        vec4 baked = texture(u_cloth_light, (v_pos.xy - u_bake_rect.xy) / u_bake_rect.zw);
        vec3 shown = baked.rgb * (1.0 + baked.a * (2.0 * nap - 1.0));
        // Worsted sheen: the cloth brightens toward grazing angles, more looking with the nap
        // (from the head toward the foot, +x).
        vec3 v = normalize(u_eye - v_pos);
        float g = 1.0 - v.z;
        g *= g;
        shown *= 1.0 + 0.5 * g * g * (0.8 - 0.2 * v.x);
        // Under the rail tops the texture holds the rail's light; what shows of the cloth
        // there (through the holes, past their edge) is the pocket's black leather liner.
        float ox = max(-v_pos.x, v_pos.x - u_table.x), oy = max(-v_pos.y, v_pos.y - u_table.y);
        float under_rail = step(u_table.z - 0.0005, max(ox, oy)) * step(0.1, baked.a);
        o_colour = vec4(mix(shown, u_liner_shown, under_rail), 1.0);
        return;
    }
    vec3 n = normalize(v_normal);
    if (dot(n, u_eye - v_pos) < 0.0) n = -n;
    if (kMaterial == 2) {
        // The bevels and the table's sides (the rail tops are material 4): no pocket reaches
        // them, so no hole test (and no discard, which would cost llvmpipe its early depth test).
        // Seen from inside the table (through a pocket's hole in the rail top), the sides'
        // inner faces are the dark of the pocket's leather, not lit wood.
        if (dot(n.xy, 0.5 * u_table.xy - v_pos.xy) > 0.0) {
            o_colour = vec4(u_liner_shown, 1.0);
            return;
        }
        vec3 albedo = texture(u_wood_tex, vec2(v_uv.x / 1.3, v_uv.y / 0.16)).rgb;  // an sRGB texture: linear when sampled
        // The bevels shine; the vertical sides, lit at grazing angles, barely.
        c = lamps_light_cheap(v_pos, n, albedo, 6, 0.25 * smoothstep(0.3, 0.9, n.z)) + albedo * 0.06;
        o_colour = vec4(tone_map(apply_fog(c, v_pos)), 1.0);
        return;
    }
    float hole_r = 0.0;
    float hd = hole_distance(v_pos.xy, hole_r);
    if (kMaterial == 3) {
        // Baking the cloth (seen from above, n = +z): the light at the mean nap (the nap
        // factor 0.72 + 0.56 nap is 1 at nap = 0.5) and in a, how much of it the nap modulates.
        vec3 albedo = u_cloth_linear;
        // The spots: thin white discs.
        float spot = 1e3;
        for (int i = 0; i < u_spot_count; ++i) spot = min(spot, length(v_pos.xy - u_spots[i]));
        albedo = mix(albedo, vec3(0.75), 1.0 - smoothstep(0.006, 0.0075, spot));
        if (u_baulk.z > 0.0) {
            // The baulk line across the table and the D behind it: thin chalk-white lines.
            float line = abs(v_pos.x - u_baulk.x);
            vec2 dc = v_pos.xy - vec2(u_baulk.x, u_baulk.y);
            if (v_pos.x < u_baulk.x) line = min(line, abs(length(dc) - u_baulk.z));
            albedo = mix(albedo, vec3(0.75), 1.0 - smoothstep(0.0011, 0.0019, line));
        }
        vec3 cloth = lamps_diffuse(v_pos, vec3(0.0, 0.0, 1.0), albedo) + albedo * 0.035;
        // The cushions hide part of the lamps and the room from the cloth along them.
        float to_nose = min(min(v_pos.x, u_table.x - v_pos.x), min(v_pos.y, u_table.y - v_pos.y));
        cloth *= mix(0.72, 1.0, smoothstep(0.0, 0.12, max(to_nose, 0.0)));
        // Beyond the cushion noses and outside the hole: the pocket's black leather liner.
        float outside = max(max(-v_pos.x, v_pos.x - u_table.x), max(-v_pos.y, v_pos.y - u_table.y));
        float liner = smoothstep(0.0, 0.006, outside);
        vec3 liner_c = vec3(0.012, 0.010, 0.009);
        float edge = mix(0.35, 1.0, smoothstep(0.0, 0.012, hd));  // the cloth turning down over the slate edge
        vec3 napped = cloth * (1.0 - liner) * edge, plain = liner_c * liner * edge;
        if (hd < 0.0) {
            // The pocket: dark inside, a little light on the far wall of the hole.
            float depth = clamp(-hd / hole_r, 0.0, 1.0);
            napped = vec3(0.0);
            plain = mix(vec3(0.018, 0.016, 0.014), vec3(0.002), sqrt(depth));
        }
        vec3 sum = napped + plain;
        float weight = dot(napped, vec3(1.0)) / max(dot(sum, vec3(1.0)), 1e-6);
        // Beyond the cushions' backs: the rail top, at rail height; its diffuse light, and in
        // a its specular weight (1 on the wood; 0 in the holes, where the rail top is cut away
        // and the cloth pass shows the pocket's colour, which has no nap either).
        float ox = max(-v_pos.x, v_pos.x - u_table.x), oy = max(-v_pos.y, v_pos.y - u_table.y);
        if (max(ox, oy) > u_table.z - 0.0005 && hd >= 0.0) {
            // The rails' texture coordinates as the mesh has them: along the rail, and across
            // from the cushion back; the four trapezoids meet on the corners' diagonals.
            vec2 ruv = ox > oy ? vec2(v_pos.y, ox - u_table.z) : vec2(v_pos.x, oy - u_table.z);
            vec3 wood = texture(u_wood_tex, vec2(ruv.x / 1.3, ruv.y / 0.16)).rgb;  // sRGB texture: linear
            float pearl = 1.0 - smoothstep(0.007, 0.0085, diamond(v_pos.xy));
            wood = mix(wood, vec3(0.85, 0.83, 0.78), pearl);
            float lip = 1.0 - smoothstep(0.010, 0.013, hd);
            wood = mix(wood, vec3(0.012, 0.010, 0.009), lip);
            vec3 top = vec3(v_pos.xy, u_rail_height);
            vec3 lit = lamps_diffuse(top, vec3(0.0, 0.0, 1.0), wood) + wood * 0.06;
            o_colour = vec4(sqrt(lit), mix(1.0, 0.2, lip));
            return;
        }
        // The cloth's texels hold what is shown (tone-mapped) at the mean nap, and in a how
        // much the nap's factor, 0.72 to 1.28, changes that (relative, either way).
        vec3 shown = tone_map(sum);
        float swing = (tone_map(sum * 1.28).g - tone_map(sum * 0.72).g) / (2.0 * max(shown.g, 1e-4));
        o_colour = vec4(shown, clamp(weight * swing, 0.0, 1.0));
        return;
    }
    if (kMaterial == 4) {
        // The rail tops: the baked diffuse light and the lamps' highlights, view-dependent.
        vec4 baked = texture(u_cloth_light, (v_pos.xy - u_bake_rect.xy) / u_bake_rect.zw);
        if (baked.a < 0.1) discard;  // a pocket hole
        c = baked.rgb * baked.rgb + lamps_specular(v_pos, vec3(0.0, 0.0, 1.0), 7, 0.06 * baked.a);
        o_colour = vec4(tone_map(c), 1.0);  // above the cloth: no fog
        return;
    }
    // The cushions: cloth-covered rubber, cut away at the pockets. Their sheen (a highlight of
    // weight 0.015) is too faint to pay for: diffuse only.
    if (hd < 0.0) discard;
    vec3 albedo = u_cloth_linear * 0.92;
    float nap = texture(u_cloth_tex, v_uv * 12.0).r;
    albedo *= 0.8 + 0.4 * nap;
    c = lamps_diffuse(v_pos, n, albedo) + albedo * 0.035;
    o_colour = vec4(tone_map(apply_fog(c, v_pos)), 1.0);
}
)";

const char* const kBallVert = R"(
layout(location = 0) in vec2 a_corner;   // (-1,-1) .. (1,1)
uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform vec3 u_centre;
uniform float u_radius;
out vec3 v_world;
void main() {
    // A billboard through the centre, facing the eye, large enough for the silhouette.
    vec3 to_eye = u_eye - u_centre;
    float d = length(to_eye);
    vec3 f = to_eye / d;
    vec3 up = abs(f.z) < 0.99 ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
    vec3 r = normalize(cross(up, f));
    vec3 u = cross(f, r);
    float s = u_radius * d / sqrt(max(d * d - u_radius * u_radius, 1e-6)) * 1.08;
    v_world = u_centre + s * (a_corner.x * r + a_corner.y * u);
    gl_Position = u_view_proj * vec4(v_world, 1.0);
}
)";

const char* const kBallFrag = R"(
in vec3 v_world;
layout(location = 0) out vec4 o_colour;
uniform mat4 u_view_proj;
uniform vec3 u_centre;
uniform float u_radius;
uniform mat3 u_rotation;      // ball frame -> table frame
uniform vec3 u_colour;        // sRGB
uniform int u_stripe;         // 1: a stripe ball (colour band on white)
uniform int u_cue;            // 1: the cue ball
uniform int u_number;         // 1-15: the number in the white circles
uniform int u_plain;          // 1: no number circles (snooker, carom)
uniform float u_number_scale; // the circles' size relative to a real ball's (>= 1: far away)
uniform vec4 u_tint;          // rgb: mixed into the colour by a (ball in hand, illegal: red)
uniform float u_alpha;        // < 1: drawn see-through (ball in hand)
uniform sampler2D u_numbers;  // the numbers' atlas, 4 x 4 cells (render::make_number_atlas)
uniform vec3 u_cloth_colour;  // sRGB, for the reflection of the table

// What the ball's varnish reflects: the lit cloth below, the dark room above, the lamps' discs.
vec3 environment(vec3 r, vec3 p) {
    vec3 env;
    if (r.z < 0.0) {
        env = u_cloth_linear * 0.8 * smoothstep(-0.02, -0.3, r.z);
    } else {
        // The room: the lit walls round the horizon (the wainscot darker, just above it), the
        // dim ceiling overhead.
        env = mix(vec3(0.05, 0.038, 0.026), vec3(0.008, 0.0075, 0.007), smoothstep(0.0, 0.45, r.z));
        env *= mix(0.5, 1.0, smoothstep(0.04, 0.1, r.z));
    }
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - p;
        float dist = length(d);
        float cos_a = dot(r, d / dist);
        float ang = u_lamps[i].w / dist;        // angular radius of the lamp's opening
        float disc = smoothstep(cos(ang), cos(ang * 0.8), cos_a);
        env += u_lamp_colour * 0.45 * disc;
    }
    return env;
}

void main() {
    vec3 dir = normalize(v_world - u_eye);
    vec3 oc = u_eye - u_centre;
    float b = dot(oc, dir);
    float c = dot(oc, oc) - u_radius * u_radius;
    float h = b * b - c;
    if (h < 0.0) discard;
    // Clamped so that the quad's helper pixels past the silhouette still give finite texture
    // derivatives for the numbers.
    float t = -b - sqrt(max(h, 0.0));
    vec3 p = u_eye + t * dir;
    vec3 n = (p - u_centre) / u_radius;
    vec3 local = transpose(u_rotation) * n;

    vec3 white = vec3(0.93, 0.92, 0.86);
    vec3 albedo = u_colour;
    if (u_stripe == 1 && abs(local.z) > 0.48) albedo = white;
    // The number's white circle, on both sides, and the number in it: the atlas cell of
    // u_number spans the circle; on the -x side the digits are mirrored to read from outside.
    // The circle's radius: 0.456 R on a real ball, larger when the ball is small on screen.
    float rho = 0.456 * u_number_scale;
    vec2 q = vec2(local.x >= 0.0 ? local.y : -local.y, local.z) / rho;
    vec2 cell = vec2(float(u_number % 4), float(3 - u_number / 4));
    float ink = texture(u_numbers, (cell + 0.5 + 0.5 * clamp(q, -0.97, 0.97)) * 0.25).r;
    if (u_cue == 0 && u_plain == 0 && abs(local.x) > sqrt(1.0 - rho * rho)) albedo = mix(white, vec3(0.025, 0.022, 0.02), ink);
    // The cue ball's red dots show its spin.
    if (u_cue == 1 && abs(local.x) > 0.985) albedo = vec3(0.75, 0.05, 0.04);
    albedo = to_linear(albedo);

    float ndv = max(dot(n, -dir), 0.0);
    float m = 1.0 - ndv, m2 = m * m;
    float fresnel = 0.04 + 0.96 * m2 * m2 * m;
    vec3 diffuse = lamps_light(p, n, albedo, 400.0, 0.6);
    // Ambient: light bounced off the cloth from below, the dim room above.
    vec3 ambient = albedo * mix(u_cloth_linear * 0.9, vec3(0.06), 0.5 + 0.5 * n.z);
    // The ball's contact with the cloth darkens its very bottom.
    ambient *= smoothstep(-1.0, -0.6, n.z);
    vec3 r = reflect(dir, n);
    vec3 col = diffuse + ambient + fresnel * environment(r, p) * 1.0 + 0.06 * environment(r, p) * (1.0 - fresnel);

    vec4 clip = u_view_proj * vec4(p, 1.0);
    gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;
    o_colour = vec4(mix(tone_map(col), u_tint.rgb, u_tint.a), u_alpha);
}
)";

const char* const kShadowVert = R"(
layout(location = 0) in vec2 a_corner;
uniform mat4 u_view_proj;
uniform vec3 u_centre;
uniform float u_radius;
out vec3 v_world;
void main() {
    v_world = vec3(u_centre.xy + a_corner * u_radius * 4.0, 0.0004);
    gl_Position = u_view_proj * vec4(v_world, 1.0);
}
)";

// Soft shadow of one ball on the cloth, computed analytically (kCommon's ball_shadow_keep
// with the cloth's normal). The output multiplies the framebuffer.
const char* const kShadowFrag = R"(
in vec3 v_world;
layout(location = 0) out vec4 o_colour;
uniform vec3 u_centre;
uniform float u_radius;
void main() {
    o_colour = vec4(vec3(ball_shadow_keep(vec3(v_world.xy, 0.0), vec3(0.0, 0.0, 1.0), u_centre, u_radius)), 1.0);
}
)";

// The balls' soft shadows on the cushions: ball_shadow_keep at the cushion's own surface
// point and normal, for the balls near a cushion
// (drawn over the cushions' mesh with kTableVert, multiplied onto the framebuffer).
const char* const kCushionShadowFrag = R"(
in vec3 v_pos;
in vec3 v_normal;
in vec2 v_uv;
layout(location = 0) out vec4 o_colour;
uniform vec3 u_balls[16];   // centres of the balls near a cushion (unit: m)
uniform int u_ball_count;
uniform float u_radius;
void main() {
    vec3 n = normalize(v_normal);
    if (dot(n, u_eye - v_pos) < 0.0) n = -n;
    float keep = 1.0;
    for (int b = 0; b < 16; ++b) {
        if (b >= u_ball_count) break;
        keep *= ball_shadow_keep(v_pos, n, u_balls[b], u_radius);
    }
    o_colour = vec4(vec3(keep), 1.0);
}
)";

// The cue stick's soft shadow on the cloth: for each lamp, the closest approach of the ray
// from the cloth point to the lamp and the cue's axis gives the cue's angular offset and
// half-width as seen from that point; the part of the lamp's disc the cue's strip covers
// (taken across the strip) is that lamp's shadow, weighted by its share of the light.
const char* const kCueShadowVert = R"(
layout(location = 0) in vec2 a_corner;
uniform mat4 u_view_proj;
uniform vec4 u_rect;   // the shadow's footprint on the cloth: xy min, xy max (unit: m)
out vec3 v_world;
void main() {
    v_world = vec3(mix(u_rect.xy, u_rect.zw, a_corner * 0.5 + 0.5), 0.0004);
    gl_Position = u_view_proj * vec4(v_world, 1.0);
}
)";

const char* const kCueShadowFrag = R"(
in vec3 v_world;
layout(location = 0) out vec4 o_colour;
uniform vec3 u_cue_a;   // the cue's axis from the tip ...
uniform vec3 u_cue_b;   // ... to the butt (unit: m)
uniform vec2 u_cue_r;   // its radius at the tip and at the butt (unit: m)
void main() {
    vec3 p = vec3(v_world.xy, 0.0);
    vec3 u = u_cue_b - u_cue_a;
    vec3 r = p - u_cue_a;
    float uu = dot(u, u), ur = dot(u, r);
    float lit = 0.0, shadowed = 0.0;
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - p;
        float dl = length(d);
        vec3 l = d / dl;
        float w = smoothstep(0.25, 0.6, l.z) * l.z / (dl * dl);
        float ul = dot(u, l), lr = dot(l, r);
        float s = clamp((ur - lr * ul) / max(uu - ul * ul, 1e-9), 0.0, 1.0);
        float t = max(s * ul - lr, 1e-4);
        float dist = length(r + t * l - s * u);
        float half_w = mix(u_cue_r.x, u_cue_r.y, s) / t, theta = dist / t;
        float al = u_lamps[i].w / dl;
        float cover = clamp((min(theta + half_w, al) - max(theta - half_w, -al)) / (2.0 * al), 0.0, 1.0);
        lit += w;
        shadowed += w * cover;
    }
    float ambient = 0.035;
    o_colour = vec4(vec3((lit - shadowed + ambient) / (lit + ambient)), 1.0);
}
)";

const char* const kSolidVert = R"(
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_colour;
uniform mat4 u_view_proj;
out vec3 v_pos;
out vec3 v_normal;
out vec3 v_colour;
void main() {
    v_pos = a_pos;
    v_normal = a_normal;
    v_colour = a_colour;
    gl_Position = u_view_proj * vec4(a_pos, 1.0);
}
)";

const char* const kSolidFrag = R"(
in vec3 v_pos;
in vec3 v_normal;
in vec3 v_colour;
layout(location = 0) out vec4 o_colour;
uniform int u_lit;     // 1: lit by the lamps; 0: flat colour (the aim guide)
uniform float u_alpha;
void main() {
    if (u_lit == 0) {
        o_colour = vec4(v_colour, u_alpha);
        return;
    }
    vec3 n = normalize(v_normal);
    if (dot(n, u_eye - v_pos) < 0.0) n = -n;
    vec3 albedo = to_linear(v_colour);
    vec3 c = lamps_light(v_pos, n, albedo, 90.0, 0.35) + albedo * 0.06;
    o_colour = vec4(tone_map(apply_fog(c, v_pos)), u_alpha);
}
)";

// The room is large and dim, and llvmpipe pays for every pixel of it: its light (the lamps,
// their shades' cut-off, the table blocking them from the floor below it, a little bounced
// light), its fog and the tone mapping are computed per vertex; the pixels only add the pattern.
const char* const kRoomVert = R"(
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_colour;
uniform mat4 u_view_proj;
uniform vec3 u_eye;
uniform vec4 u_lamps[3];
uniform vec3 u_lamp_colour;
uniform float u_exposure;
uniform vec3 u_background;  // linear
uniform vec4 u_footprint;   // the table's outline: xy min, xy max (unit: m)
out vec3 v_pos;
out vec3 v_shown;
void main() {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        vec3 d = u_lamps[i].xyz - a_pos;
        float inv = inversesqrt(dot(d, d));
        vec3 l = d * inv;
        // Below the cloth the table stands between the lamp and the point.
        float t = clamp(-a_pos.z / max(d.z, 1e-4), 0.0, 1.0);
        vec2 q = a_pos.xy + t * d.xy;
        vec2 inside = smoothstep(u_footprint.xy - 0.15, u_footprint.xy + 0.15, q) *
                      (1.0 - smoothstep(u_footprint.zw - 0.15, u_footprint.zw + 0.15, q));
        float blocked = a_pos.z < -0.01 ? inside.x * inside.y : 0.0;
        sum += smoothstep(0.25, 0.6, l.z) * max(dot(a_normal, l), 0.0) * inv * inv * (1.0 - blocked);
    }
    // Light bounced off the bright table and the room's own dim fill.
    vec3 to_table = vec3(0.5 * (u_footprint.xy + u_footprint.zw), 0.0) - a_pos;
    float bounce = max(dot(a_normal, normalize(to_table)), 0.0) / (1.0 + dot(to_table, to_table));
    vec3 light = u_lamp_colour * sum + vec3(0.6, 0.55, 0.45) * bounce + vec3(0.16, 0.15, 0.13);
    float fog = clamp((length(a_pos - u_eye) - 1.5) / 9.0, 0.0, 0.75);
    vec3 c = mix(pow(a_colour, vec3(2.2)) * light, u_background, fog) * u_exposure;
    c = clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
    vec3 s = sqrt(c);
    v_shown = s * (1.2 - 0.2 * s);
    v_pos = a_pos;
    gl_Position = u_view_proj * vec4(a_pos, 1.0);
}
)";

const char* const kRoomFrag = R"(
in vec3 v_pos;
in vec3 v_shown;
layout(location = 0) out vec4 o_colour;
uniform vec4 u_room;        // the walls: xy min, xy max (unit: m)
uniform float u_floor_z;

// A hash without sin (slow on llvmpipe).
float hash(float x) {
    x = fract(x * 0.1031);
    x *= x + 33.33;
    x *= x + x;
    return fract(x);
}

void main() {
    float shade = 1.0;
    // Which surface from where the pixel lies (fewer varyings: each costs llvmpipe per pixel).
    if (v_pos.z < u_floor_z + 0.001) {
        // Oak planks 11 cm wide in staggered 1.2 m lengths, dark seams, a faint grain.
        float row = floor(v_pos.y / 0.11);
        float along = v_pos.x + 1.2 * hash(row);
        float board = floor(along / 1.2);
        shade = 0.8 + 0.35 * hash(row * 7.13 + board * 3.71);
        float seam = min(fract(v_pos.y / 0.11), fract(along / 1.2) * 10.9);
        shade *= mix(0.5, 1.0, smoothstep(0.0, 0.03, seam));
        shade *= 0.94 + 0.12 * abs(fract(along * 9.0 + 0.4 * fract(v_pos.y * 13.0)) - 0.5);
    } else if (v_pos.z < u_floor_z + 1.0) {
        // The wainscot's panels: raised frames every 0.7 m along the wall and a rail on top.
        vec2 off = min(v_pos.xy - u_room.xy, u_room.zw - v_pos.xy);
        float along = off.x < off.y ? v_pos.y : v_pos.x;
        float u = fract(along / 0.7), h = v_pos.z - u_floor_z;
        float frame = min(min(u, 1.0 - u) * 7.0, min(abs(h - 0.12), abs(h - 0.88)) * 10.0);
        shade = min(off.x, off.y) < 0.01 ? mix(0.6, 1.0, smoothstep(0.04, 0.12, frame)) : 1.0;
    }
    o_colour = vec4(v_shown * shade, 1.0);
}
)";

}  // namespace glsl

std::string table_fragment_source(TableMaterial material) {
    return "const int kMaterial = " + std::to_string(static_cast<int>(material)) + ";\n" +
           glsl::kTableFrag;
}

}  // namespace render
