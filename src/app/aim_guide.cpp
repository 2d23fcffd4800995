#include "app/aim_guide.hpp"

namespace app {

namespace {

const glm::vec3 call_gold{1.0f, 0.8f, 0.2f};
const glm::vec3 drops_green{0.3f, 0.95f, 0.4f};
const glm::vec3 jaw_orange{1.0f, 0.45f, 0.1f};
const glm::vec3 foul_red{1.0f, 0.2f, 0.15f};

// Where the practice level's object path ends: a green disc in the pocket, an orange ring at a
// jaw (a path that rattles must not look like one that drops).
void add_end_mark(render::AimView& v, const AimPreview& p, float R) {
    if (v.object_path.empty()) return;
    const glm::vec2 end = v.object_path.back();
    if (p.object_end == PathEnd::pocket) v.marks.push_back({end, 0.5f * R, 0.5f * R, drops_green});
    if (p.object_end == PathEnd::jaw) v.marks.push_back({end, 0.8f * R, 0.25f * R, jaw_orange});
}

}  // namespace

render::AimView guide_view(const AimPreview& p, AimGuide level, bool illegal, float R) {
    render::AimView v;
    v.illegal = illegal;
    switch (level) {
        case AimGuide::off:
            return v;
        case AimGuide::practice:
            v = p.view;
            v.illegal = illegal;
            add_end_mark(v, p, R);
            return v;
        case AimGuide::ghost:
        case AimGuide::lines:
            break;
    }
    v.cue_path = p.view.cue_path;
    v.ghost = p.view.ghost;
    if (level == AimGuide::lines && p.first_ball) {
        // From the object ball's edge and from the ghost ball, so the lines start where the
        // balls do.
        const glm::vec2 o = p.object_at + R * p.object_dir;
        v.object_path = {o, o + object_line_length * p.object_dir};
        // The tangent line: the incoming direction less its part along the object ball's
        // line (none for a full hit).
        const glm::vec2 t = p.cue_dir - glm::dot(p.cue_dir, p.object_dir) * p.object_dir;
        if (p.view.ghost && glm::length(t) > 0.02f) {
            const glm::vec2 g = *p.view.ghost;
            v.cue_after = {g, g + tangent_line_length * glm::normalize(t)};
        }
    }
    return v;
}

void add_call_marks(render::AimView& v, const physics::Table& table, physics::Vec2 ball_at,
                    int pocket, float R) {
    v.marks.push_back({{static_cast<float>(ball_at.x), static_cast<float>(ball_at.y)},
                       1.45f * R,
                       0.12f * R,
                       call_gold});
    for (const physics::Pocket& p : table.pockets) {
        if (p.id != pocket) continue;
        const physics::Vec2 mouth = 0.5 * (p.mouth_a + p.mouth_b);
        v.marks.push_back({{static_cast<float>(mouth.x), static_cast<float>(mouth.y)},
                           1.6f * R,
                           0.15f * R,
                           call_gold});
    }
}

void add_foul_mark(render::AimView& v, physics::Vec2 ball_at, float R) {
    v.marks.push_back({{static_cast<float>(ball_at.x), static_cast<float>(ball_at.y)},
                       1.5f * R,
                       0.2f * R,
                       foul_red});
}

}  // namespace app
