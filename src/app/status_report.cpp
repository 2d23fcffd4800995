#include "app/status_report.hpp"

#include <nlohmann/json.hpp>

#include "game/atomic_file.hpp"
#include "rules/names.hpp"

namespace app {

namespace {

const char* phase_name(game::Phase p) {
    switch (p) {
        case game::Phase::place_cue_ball:
            return "place_cue_ball";
        case game::Phase::shoot:
            return "shoot";
        case game::Phase::choose:
            return "choose";
        case game::Phase::game_over:
            return "game_over";
    }
    return "?";
}

const char* view_name(CameraMode m) {
    switch (m) {
        case CameraMode::overhead:
            return "overhead";
        case CameraMode::cue_ball:
            return "cueball";
        case CameraMode::free:
            return "free";
    }
    return "?";
}

const char* path_end_name(PathEnd e) {
    switch (e) {
        case PathEnd::none:
            return "none";
        case PathEnd::pocket:
            return "pocket";
        case PathEnd::jaw:
            return "jaw";
        case PathEnd::rail:
            return "rail";
        case PathEnd::ball:
            return "ball";
    }
    return "?";
}

// The snooker or three-cushion scoreboard as the panel shows it; null in pool.
nlohmann::ordered_json match_json(const Controller& c) {
    using rules::Player;
    if (const game::SnookerSession* s = c.snooker()) {
        const rules::SnookerState& st = s->state();
        const std::optional<int> nom = c.nomination();
        return {
            {"game", "snooker"},
            {"scores", {st.score(Player::A), st.score(Player::B)}},
            {"break", st.break_points},
            {"remaining", s->points_remaining()},
            {"frames", {s->frames_won()[0], s->frames_won()[1]}},
            {"reds", st.reds()},
            {"choices", s->choices().size()},
            {"in_hand", st.cue_ball == rules::CueBall::in_hand},
            {"nomination", nom ? nlohmann::ordered_json(*nom) : nlohmann::ordered_json(nullptr)},
            {"frame_over", s->frame_winner().has_value()}};
    }
    if (const game::CaromSession* s = c.carom()) {
        const rules::CaromState& st = s->state();
        return {{"game", "three_cushion"},
                {"scores", {st.scores[0], st.scores[1]}},
                {"innings", {st.innings[0], st.innings[1]}},
                {"run", st.run},
                {"cue_ball", s->cue_ball()},
                {"game_over", s->game_over()}};
    }
    return nullptr;
}

}  // namespace

std::string status_json(const Controller& c, const Settings& s, CameraMode view,
                        const FrameFacts& frame) {
    const game::Session& session = c.session();
    nlohmann::ordered_json j;
    j["phase"] = phase_name(session.phase());
    const std::optional<rules::Player> p = session.to_act();
    j["to_act"] = p ? nlohmann::ordered_json(session.name(*p)) : nlohmann::ordered_json(nullptr);
    j["moving"] = c.moving();
    j["replaying"] = c.replaying();
    j["tray"] = c.tray();
    j["busy"] = c.busy();
    j["thinking"] = c.computer_thinking();
    j["view"] = view_name(view);
    j["sound"] = s.sound;
    j["power"] = c.aim().power;
    j["shots"] = session.history().size();
    j["game_number"] = session.game_number();
    j["info"] = c.info();
    j["last_shot"] = c.last_shot_words();
    j["refusal"] = c.refusal();
    j["winner"] = session.winner() ? nlohmann::ordered_json(session.name(*session.winner()))
                                   : nlohmann::ordered_json(nullptr);
    j["heading_deg"] = c.aim().heading_deg;
    const auto cue = session.state().positions.find(c.cue_ball_id());
    j["cue_ball"] = cue != session.state().positions.end()
                        ? nlohmann::ordered_json::array({cue->second.x, cue->second.y})
                        : nlohmann::ordered_json(nullptr);
    j["balls_on_table"] = session.state().on_table.size();
    nlohmann::ordered_json positions = nlohmann::ordered_json::object();
    for (const auto& [id, pos] : session.state().positions)
        positions[std::to_string(id)] = {pos.x, pos.y};
    j["positions"] = std::move(positions);
    j["aim_guide_level"] = aim_guide_name(s.aim_guide);
    j["aim_foul"] = c.aim_foul();
    const rules::Call call = c.call();
    j["call"] = call.is_ball()
                    ? nlohmann::ordered_json{{"ball", call.ball}, {"pocket", call.pocket}}
                    : nlohmann::ordered_json(nullptr);
    j["guide_end"] = c.preview() ? path_end_name(c.preview()->object_end) : "";
    j["widgets"] = frame.widgets;
    j["frames"] = frame.frames;
    j["window"] = frame.window;
    j["panel_width"] = frame.panel_width;
    j["panel_height"] = frame.panel_height;
    j["table_view"] = frame.table_view;
    j["link_note"] = frame.link_note;
    nlohmann::ordered_json px = nlohmann::ordered_json::object();
    for (const auto& [id, at] : frame.ball_px) px[std::to_string(id)] = at;
    j["ball_px"] = std::move(px);
    j["practice"] = c.practicing();
    j["look"] = c.look() == render::GameLook::snooker ? "snooker"
                : c.look() == render::GameLook::carom ? "carom"
                                                      : "pool";
    j["match"] = match_json(c);
    j["drawn"] = {{"cue", frame.cue},
                  {"aim_guide", frame.aim_guide},
                  {"ball_in_hand", frame.ball_in_hand},
                  {"marks", frame.marks},
                  {"aim_illegal", frame.aim_illegal}};
    return j.dump() + "\n";
}

void StatusFile::write(const std::string& text) {
    if (text == last_) return;
    try {
        game::write_file_atomically(path_, text);
        last_ = text;
    } catch (const std::exception&) {
        // a test hook: a failed write is retried at the next change
    }
}

}  // namespace app
