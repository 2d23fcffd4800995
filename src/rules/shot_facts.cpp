#include "rules/shot_facts.hpp"

#include <algorithm>

namespace rules {

namespace {

constexpr int cue = 0;

bool gone_already(const ShotFacts& f, int ball) {
    if (ball == cue) return f.cue_pocketed || f.cue_off_table;
    return f.was_pocketed(ball) || f.went_off_table(ball);
}

// Whether an event shows the cue ball's centre outside the kitchen.
bool shows_cue_outside_kitchen(const physics::Event& e, double head_string_x) {
    for (int k = 0; k < e.ball_count && k < 2; ++k) {
        const physics::EventBall& b = e.balls[static_cast<std::size_t>(k)];
        if (b.id == cue && b.pos.x >= head_string_x) return true;  // false for NaN
    }
    return false;
}

}  // namespace

bool ShotFacts::was_pocketed(int ball) const {
    return pocket_of(ball).has_value();
}

bool ShotFacts::went_off_table(int ball) const {
    return std::find(off_table.begin(), off_table.end(), ball) != off_table.end();
}

std::optional<int> ShotFacts::pocket_of(int ball) const {
    for (const PocketedBall& p : pocketed)
        if (p.ball == ball) return p.pocket;
    return std::nullopt;
}

ShotFacts distill(std::span<const physics::Event> events, double head_string_x) {
    using physics::EventType;
    ShotFacts f;
    for (const physics::Event& e : events) {
        const bool before_contact = !f.first_contact.has_value();
        if (before_contact && shows_cue_outside_kitchen(e, head_string_x))
            f.cue_left_kitchen = true;

        switch (e.type) {
            case EventType::ball_ball:
                if (before_contact && e.ball_count == 2 && e.involves(cue)) {
                    int other = e.ball(0) == cue ? e.ball(1) : e.ball(0);
                    if (other != cue) f.first_contact = other;
                }
                break;
            case EventType::cushion:
                if (!before_contact) f.cushion_after_contact = true;
                if (e.ball(0) != cue) f.object_balls_to_cushion.insert(e.ball(0));
                break;
            case EventType::pocket:
                if (gone_already(f, e.ball(0))) break;
                if (e.ball(0) == cue)
                    f.cue_pocketed = true;
                else
                    f.pocketed.push_back({e.ball(0), e.pocket});
                break;
            case EventType::off_table:
                if (gone_already(f, e.ball(0))) break;
                if (e.ball(0) == cue)
                    f.cue_off_table = true;
                else
                    f.off_table.push_back(e.ball(0));
                break;
            case EventType::strike:
            case EventType::miscue:
            case EventType::transition:
                break;
        }
    }
    return f;
}

}  // namespace rules
