// The snooker save format (docs/game.md, "Snooker and three-cushion saves"):
// SnookerSession::to_json and from_json. Reading checks every field and the whole.
#include <fmt/format.h>

#include <algorithm>

#include "game/atomic_file.hpp"
#include "game/match_json.hpp"
#include "game/snooker_session.hpp"
#include "game/state_json.hpp"
#include "game/text_file.hpp"
#include "rules/names.hpp"

namespace game {

using nlohmann::ordered_json;
namespace sb = physics::snooker_ball;

namespace {

constexpr std::string_view format_name = "coolaaber-snooker";
constexpr int max_score = 10000;
constexpr std::array<std::string_view, 3> choice_names{"play", "play_again", "replace"};

ordered_json state_json(const rules::SnookerState& s) {
    ordered_json j;
    j["shooter"] = rules::name(s.shooter);
    j["on_table"] = s.on_table;
    j["cue_ball"] = s.cue_ball == rules::CueBall::on_table ? "on_table" : "in_hand";
    j["colour_on"] = s.colour_on;
    j["nominated"] = s.nominated ? ordered_json(*s.nominated) : ordered_json(nullptr);
    j["free_ball"] = s.free_ball;
    j["respotted_black"] = s.respotted_black;
    j["scores"] = match_json::pair(s.scores);
    j["break"] = s.break_points;
    j["misses"] = s.misses;
    j["positions"] = match_json::positions(s.positions);
    return j;
}

std::set<int> read_on_table(const Field& f) {
    std::set<int> on;
    for (std::size_t i = 0; i < f.array_size(); ++i) {
        const int id = static_cast<int>(f.at(i).integer_in(1, sb::black));
        if (!on.insert(id).second) f.at(i).fail(fmt::format("ball {} is listed twice", id));
    }
    return on;
}

void check_state(const Field& f, const rules::SnookerState& s, const rules::SnookerTable& t) {
    if (s.reds() > 0)
        for (int c = sb::yellow; c <= sb::black; ++c)
            if (!s.has(c))
                f.at("on_table")
                    .fail(fmt::format(
                        "the {} is missing: colours stay on the table while reds remain",
                        snooker_ball_name(c)));
    if (s.nominated) {
        if (!s.has(*s.nominated))
            f.at("nominated").fail(fmt::format("ball {} is not on the table", *s.nominated));
        if (!s.colour_on && !s.free_ball)
            f.at("nominated").fail("a ball is nominated only with a colour on or a free ball");
    }
    for (int id : s.on_table)
        if (!s.positions.count(id))
            f.at("positions").fail(fmt::format("ball {} is on the table but has no position", id));
    const auto cue = s.positions.find(sb::cue);
    if (s.cue_ball == rules::CueBall::on_table && cue == s.positions.end())
        f.at("positions").fail("the cue ball is on the table but has no position (\"0\")");
    if (s.cue_ball == rules::CueBall::in_hand && cue != s.positions.end() &&
        !t.marks.in_d(cue->second))
        f.at("positions").at("0").fail("a cue ball in hand is placed in the D");
}

rules::SnookerState read_state(const Field& f, const SnookerSession& s) {
    f.require_fields({"shooter", "on_table", "cue_ball", "colour_on", "nominated", "free_ball",
                      "respotted_black", "scores", "break", "misses", "positions"});
    rules::SnookerState st;
    st.shooter = f.at("shooter").name_of<rules::Player>();
    st.on_table = read_on_table(f.at("on_table"));
    st.cue_ball = f.at("cue_ball").one_of({"on_table", "in_hand"}) == "on_table"
                      ? rules::CueBall::on_table
                      : rules::CueBall::in_hand;
    st.colour_on = f.at("colour_on").boolean();
    if (Field n = f.at("nominated"); !n.is_null())
        st.nominated = static_cast<int>(n.integer_in(1, sb::black));
    st.free_ball = f.at("free_ball").boolean();
    st.respotted_black = f.at("respotted_black").boolean();
    st.scores = match_json::read_pair(f.at("scores"), 0, max_score);
    st.break_points = static_cast<int>(f.at("break").integer_in(0, max_score));
    st.misses = static_cast<int>(f.at("misses").integer_in(0, 2));
    st.positions = match_json::read_positions(f.at("positions"), s.table(), s.config().params,
                                              [&](int id) { return id == sb::cue || st.has(id); });
    check_state(f, st, s.marks());
    return st;
}

ordered_json config_json(const SnookerConfig& c) {
    ordered_json j;
    j["miss_rule"] = c.options.miss_rule;
    j["best_of"] = c.best_of;
    j["table"] = to_json(c.table);
    j["params"] = to_json(c.params);
    j["players"] = match_json::names(c.names);
    j["first_breaker"] = rules::name(c.first_breaker);
    return j;
}

SnookerConfig read_config(const Field& f) {
    f.require_fields({"miss_rule", "best_of", "table", "params", "players", "first_breaker"});
    SnookerConfig c;
    c.options.miss_rule = f.at("miss_rule").boolean();
    Field best_of = f.at("best_of");
    c.best_of = static_cast<int>(best_of.integer_in(1, 35));
    if (c.best_of % 2 == 0) best_of.fail("a match is the best of an odd number of frames");
    c.params = read_params(f.at("params"), Fields::all);
    c.table = read_table(f.at("table"), c.params.ball_radius, Fields::all);
    if (!c.table.pockets) f.at("table").fail("snooker needs a table with pockets");
    c.names = match_json::read_names(f.at("players"));
    c.first_breaker = f.at("first_breaker").name_of<rules::Player>();
    return c;
}

}  // namespace

struct SnookerJson {
    static void read_pending(const Field& f, SnookerSession& s) {
        if (f.is_null()) return;
        f.require_fields({"options", "misses", "before"});
        if (s.frame_winner_) f.fail("must be null: the frame is over");
        const std::string opts = f.at("options").raw().dump();
        if (opts == R"(["play","play_again"])")
            s.choices_ = {rules::AfterFoul::play, rules::AfterFoul::play_again};
        else if (opts == R"(["play","play_again","replace"])")
            s.choices_ = {rules::AfterFoul::play, rules::AfterFoul::play_again,
                          rules::AfterFoul::replace};
        else
            f.at("options").fail(
                R"(expected ["play", "play_again"] or ["play", "play_again", "replace"])");
        s.pending_misses_ = static_cast<int>(f.at("misses").integer_in(0, 3));
        s.before_ = read_state(f.at("before"), s);
        if (s.before_.shooter == s.state_.shooter)
            f.at("before").at("shooter").fail(
                "the offender's: the other player is to choose (session.state.shooter)");
    }
};

std::string SnookerSession::to_json() const {
    ordered_json j;
    match_json::write_header(j, format_name);
    j["config"] = config_json(config_);
    j["frame"] = frame_;
    j["frames_won"] = match_json::pair(frames_);
    j["frame_winner"] =
        frame_winner_ ? ordered_json(rules::name(*frame_winner_)) : ordered_json(nullptr);
    j["state"] = state_json(state_);
    if (choices_.empty()) {
        j["pending"] = nullptr;
    } else {
        ordered_json opts = ordered_json::array();
        for (rules::AfterFoul c : choices_) opts.push_back(choice_names[static_cast<int>(c)]);
        j["pending"] = {
            {"options", opts}, {"misses", pending_misses_}, {"before", state_json(before_)}};
    }
    return j.dump() + "\n";
}

SnookerSession SnookerSession::from_json(const std::string& text) {
    const nlohmann::json doc = parse_document(text, "snooker");
    const Field root(doc, "snooker");
    match_json::check_header(root, format_name);
    root.require_fields(
        {"format", "version", "config", "frame", "frames_won", "frame_winner", "state", "pending"});
    SnookerSession s(read_config(root.at("config")), Restored{});
    s.frame_ = static_cast<int>(root.at("frame").integer_in(0, 1000));
    s.frames_ = match_json::read_pair(root.at("frames_won"), 0, s.frames_needed());
    if (s.frames_[0] + s.frames_[1] > s.frame_ + 1)
        root.at("frames_won").fail("more frames won than frames played");
    if (s.frames_[0] == s.frames_needed() && s.frames_[1] == s.frames_needed())
        root.at("frames_won").fail("both players cannot have won the match");
    if (Field w = root.at("frame_winner"); !w.is_null())
        s.frame_winner_ = w.name_of<rules::Player>();
    if (s.match_winner() && !s.frame_winner_)
        root.at("frame_winner").fail("the match is won: the last frame has a winner");
    s.state_ = read_state(root.at("state"), s);
    s.before_ = s.state_;
    SnookerJson::read_pending(root.at("pending"), s);
    return s;
}

void SnookerSession::save_file(const std::filesystem::path& path) const {
    const std::string text = to_json();
    try {
        (void)from_json(text);  // never write a file that would not load
    } catch (const LoadError& e) {
        throw std::logic_error(fmt::format(
            "save: the snooker match does not read back ({}); please report this", e.what()));
    }
    write_file_atomically(path, text);
}

SnookerSession SnookerSession::load_file(const std::filesystem::path& path) {
    return from_json(read_regular_file(path));
}

}  // namespace game
