#include "rules/fouls.hpp"

namespace rules {

bool is_scratch(const ShotFacts& f) {
    return f.cue_pocketed;
}

bool is_cue_ball_off_table(const ShotFacts& f) {
    return f.cue_off_table;
}

bool is_no_contact(const ShotFacts& f) {
    return !f.first_contact.has_value();
}

bool is_wrong_ball_first(const ShotFacts& f, const std::set<int>& legal_first) {
    return f.first_contact && legal_first.count(*f.first_contact) == 0;
}

bool is_no_rail_after_contact(const ShotFacts& f) {
    return f.first_contact && f.pocketed.empty() && !f.cushion_after_contact;
}

bool is_ball_off_table(const ShotFacts& f) {
    return !f.off_table.empty();
}

bool is_bad_play_from_kitchen(const ShotFacts& f, const GameState& s, double head_string_x) {
    if (s.cue_ball != CueBall::in_hand_kitchen || !f.first_contact || f.cue_left_kitchen)
        return false;
    auto lay = s.positions.find(*f.first_contact);
    return lay != s.positions.end() && lay->second.x < head_string_x;
}

bool meets_break_requirement(const ShotFacts& f) {
    return !f.pocketed.empty() || f.object_balls_to_cushion.size() >= 4;
}

std::vector<Foul> FoulList::canonical() const {
    std::vector<Foul> out;
    const bool alone = has(Foul::no_contact);
    for (Foul foul : fouls_) {
        const bool implied = foul == Foul::wrong_ball_first ||
                             foul == Foul::no_rail_after_contact ||
                             foul == Foul::bad_play_from_kitchen || foul == Foul::illegal_break;
        if (alone && implied) continue;
        out.push_back(foul);
    }
    return out;
}

}  // namespace rules
