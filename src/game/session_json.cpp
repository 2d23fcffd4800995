// The session's save format (docs/game.md, "Save format"): Session::to_json and
// Session::from_json. Reading checks every field and the consistency of the whole.
#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "game/json_field.hpp"
#include "game/session.hpp"
#include "game/state_json.hpp"
#include "rules/names.hpp"

namespace game {

using nlohmann::ordered_json;
using rules::name;

namespace {

constexpr std::string_view format_name = "coolaaber-session";
constexpr std::int64_t format_version = 1;
constexpr std::size_t max_name_length = 100;
constexpr std::int64_t max_count = 1'000'000'000;

// ---- Writing

ordered_json config_json(const Config& c) {
    ordered_json j;
    j["game"] = name(c.game);
    j["options"] = to_json(c.options);
    j["table"] = to_json(c.table);
    j["params"] = to_json(c.params);
    j["players"] = {{"A", c.names[0]}, {"B", c.names[1]}};
    j["seed"] = c.seed;
    j["first_breaker"] = name(c.first_breaker);
    j["keep_events"] = c.keep_events;
    return j;
}

ordered_json pocket_or_null(int pocket) {
    if (pocket < 0) return nullptr;
    return physics::pocket_name(pocket);
}

ordered_json summary_json(const ShotSummary& s) {
    ordered_json j;
    j["first_contact"] = s.first_contact ? ordered_json(*s.first_contact) : ordered_json(nullptr);
    ordered_json down = ordered_json::array();
    for (const BallDown& d : s.down)
        down.push_back({{"ball", d.ball}, {"pocket", pocket_or_null(d.pocket)}});
    j["down"] = std::move(down);
    j["cushions"] = s.cushions;
    j["ball_contacts"] = s.ball_contacts;
    j["events"] = s.events;
    j["duration"] = s.duration;
    j["truncated"] = s.truncated;
    return j;
}

ordered_json record_json(const ShotRecord& r, bool keep_events) {
    ordered_json j;
    j["rack"] = r.rack;
    j["before"] = to_json(r.before);
    j["stroke"] = to_json(r.stroke);
    j["summary"] = summary_json(r.summary);
    if (keep_events) {
        ordered_json events = ordered_json::array();
        for (const physics::Event& e : r.events) events.push_back(to_json(e));
        j["events"] = std::move(events);
    }
    j["verdict"] = to_json(r.verdict);
    j["choice"] = r.choice ? ordered_json(name(*r.choice)) : ordered_json(nullptr);
    return j;
}

// ---- Reading

Config read_config(const Field& f) {
    f.require_fields(
        {"game", "options", "table", "params", "players", "seed", "first_breaker", "keep_events"});
    Config c;
    c.game = f.at("game").name_of<rules::Game>();
    c.options = read_options(f.at("options"), Fields::all);
    c.params = read_params(f.at("params"), Fields::all);
    c.table = read_table(f.at("table"), c.params.ball_radius, Fields::all);
    Field players = f.at("players");
    players.require_fields({"A", "B"});
    for (rules::Player p : {rules::Player::A, rules::Player::B}) {
        Field n = players.at(name(p));
        std::string s = n.string();
        if (s.empty() || s.size() > max_name_length)
            n.fail(fmt::format("a player's name has 1 to {} bytes", max_name_length));
        c.names[rules::index(p)] = std::move(s);
    }
    c.seed = f.at("seed").unsigned_integer();
    c.first_breaker = f.at("first_breaker").name_of<rules::Player>();
    c.keep_events = f.at("keep_events").boolean();
    return c;
}

int read_optional_pocket(const Field& f) {
    return f.is_null() ? -1 : read_pocket(f);
}

ShotSummary read_summary(const Field& f, rules::Game game) {
    f.require_fields(
        {"first_contact", "down", "cushions", "ball_contacts", "events", "duration", "truncated"});
    ShotSummary s;
    const int highest = rules::highest_ball(game);
    if (Field fc = f.at("first_contact"); !fc.is_null())
        s.first_contact = static_cast<int>(fc.integer_in(1, highest));
    Field down = f.at("down");
    for (std::size_t i = 0; i < down.array_size(); ++i) {
        Field d = down.at(i);
        d.require_fields({"ball", "pocket"});
        const int ball = static_cast<int>(d.at("ball").integer_in(0, highest));
        for (const BallDown& earlier : s.down)
            if (earlier.ball == ball)
                d.at("ball").fail(fmt::format("ball {} is listed twice", ball));
        s.down.push_back({ball, read_optional_pocket(d.at("pocket"))});
    }
    s.cushions = static_cast<int>(f.at("cushions").integer_in(0, max_count));
    s.ball_contacts = static_cast<int>(f.at("ball_contacts").integer_in(0, max_count));
    s.events = static_cast<int>(f.at("events").integer_in(0, max_count));
    s.duration = f.at("duration").number_in(0.0, 1e9);
    s.truncated = f.at("truncated").boolean();
    return s;
}

ShotRecord read_record(const Field& f, const TableContext& t, bool keep_events, int rack_number) {
    if (keep_events)
        f.require_fields({"rack", "before", "stroke", "summary", "events", "verdict", "choice"});
    else
        f.require_fields({"rack", "before", "stroke", "summary", "verdict", "choice"});
    ShotRecord r;
    r.rack = static_cast<int>(f.at("rack").integer_in(0, rack_number));
    r.before = read_state(f.at("before"), t, Fields::all);
    if (!r.before.positions.count(0))
        f.at("before")
            .at("positions")
            .fail("the cue ball has no position: a shot was played from here");
    r.stroke = read_stroke(f.at("stroke"));
    r.summary = read_summary(f.at("summary"), t.game);
    if (keep_events) {
        Field events = f.at("events");
        for (std::size_t i = 0; i < events.array_size(); ++i)
            r.events.push_back(read_event(events.at(i), t.game, Fields::all));
    }
    r.verdict = read_verdict(f.at("verdict"), t);
    if (Field c = f.at("choice"); !c.is_null()) {
        const rules::ChoiceOption o = c.name_of<rules::ChoiceOption>();
        const auto& offered = r.verdict.choice;
        if (!offered || std::find(offered->options.begin(), offered->options.end(), o) ==
                            offered->options.end())
            c.fail(fmt::format("\"{}\" was not offered by the verdict's choice", name(o)));
        r.choice = o;
    }
    return r;
}

}  // namespace

std::string Session::to_json() const {
    ordered_json j;
    j["format"] = format_name;
    j["version"] = format_version;
    j["config"] = config_json(config_);
    j["game_number"] = game_number_;
    j["rack_number"] = rack_number_;
    j["score"] = {{"A", score_[0]}, {"B", score_[1]}};
    j["state"] = game::to_json(state_);
    j["pending"] = pending_ ? game::to_json(*pending_) : ordered_json(nullptr);
    j["winner"] = winner_ ? ordered_json(rules::name(*winner_)) : ordered_json(nullptr);
    ordered_json pocketed = ordered_json::array();
    for (const Pocketed& p : pocketed_)
        pocketed.push_back(
            {{"ball", p.ball}, {"pocket", pocket_or_null(p.pocket)}, {"by", rules::name(p.by)}});
    j["pocketed"] = std::move(pocketed);
    ordered_json history = ordered_json::array();
    for (const ShotRecord& r : history_) history.push_back(record_json(r, config_.keep_events));
    j["history"] = std::move(history);
    return j.dump() + "\n";
}

namespace {

// `format` and `version`: a Coolaaber session of the version this build reads.
void check_format(const Field& root) {
    if (!root.raw().is_object()) root.fail("not a Coolaaber session: expected a JSON object");
    std::optional<Field> format = root.find("format");
    if (!format || !format->raw().is_string() || format->string() != format_name)
        throw LoadError(
            "session.format",
            fmt::format("not a Coolaaber session file (expected \"format\": \"{}\")", format_name));
    Field version = root.at("version");
    if (version.integer_in(1, 1000000) != format_version)
        version.fail(fmt::format("version {} is not supported (this build reads version {})",
                                 version.raw().dump(), format_version));
}

std::array<int, 2> read_score(const Field& f) {
    f.require_fields({"A", "B"});
    std::array<int, 2> score{};
    for (rules::Player p : {rules::Player::A, rules::Player::B})
        score[rules::index(p)] = static_cast<int>(f.at(rules::name(p)).integer_in(0, max_count));
    return score;
}

// `pending`: null, or a verdict offering a choice, with the table as `state` shows it.
std::optional<rules::Verdict> read_pending(const Field& f, const TableContext& t,
                                           const rules::GameState& state, bool over) {
    if (f.is_null()) return std::nullopt;
    if (over) f.fail("must be null: the game is over");
    rules::Verdict v = read_verdict(f, t);
    if (!v.choice) f.at("choice").fail("a pending verdict offers a choice");
    if (game::to_json(v.state) != game::to_json(state))
        f.at("state").fail(
            "differs from session.state (a pending choice shows the table as it lies)");
    return v;
}

// `pocketed`: every object ball of the game not on the table, once each.
std::vector<Pocketed> read_pocketed(const Field& f, const TableContext& t,
                                    const rules::GameState& state) {
    std::vector<Pocketed> pocketed;
    const int highest = rules::highest_ball(t.game);
    for (std::size_t i = 0; i < f.array_size(); ++i) {
        Field item = f.at(i);
        item.require_fields({"ball", "pocket", "by"});
        Field ball = item.at("ball");
        const int id = static_cast<int>(ball.integer_in(-1000, 1000));
        if (id < 1 || id > highest)
            ball.fail(fmt::format("ball {} does not exist (the object balls of {} are 1 to {})", id,
                                  rules::name(t.game), highest));
        if (state.has(id))
            ball.fail(fmt::format("ball {} is also on the table (session.state.on_table)", id));
        for (const Pocketed& earlier : pocketed)
            if (earlier.ball == id) ball.fail(fmt::format("ball {} is listed twice", id));
        pocketed.push_back(
            {id, read_optional_pocket(item.at("pocket")), item.at("by").name_of<rules::Player>()});
    }
    for (int id = 1; id <= highest; ++id) {
        const bool down = std::any_of(pocketed.begin(), pocketed.end(),
                                      [id](const Pocketed& p) { return p.ball == id; });
        if (!down && !state.has(id))
            f.fail(fmt::format("ball {} is neither on the table nor pocketed", id));
    }
    return pocketed;
}

// `history`: the shots, none after one that ended the game.
std::vector<ShotRecord> read_history(const Field& f, const TableContext& t, bool keep_events,
                                     int rack_number) {
    std::vector<ShotRecord> history;
    for (std::size_t i = 0; i < f.array_size(); ++i)
        history.push_back(read_record(f.at(i), t, keep_events, rack_number));
    for (std::size_t i = 0; i + 1 < history.size(); ++i)
        if (history[i].verdict.game_over)
            f.at(i).at("verdict").fail("the game ended here, yet more shots follow");
    return history;
}

}  // namespace

Session Session::from_json(const std::string& text) {
    const nlohmann::json doc = parse_document(text, "session");
    const Field root(doc, "session");
    check_format(root);
    root.require_fields({"format", "version", "config", "game_number", "rack_number", "score",
                         "state", "pending", "winner", "pocketed", "history"});

    Session s(read_config(root.at("config")), Restored{});
    const TableContext t{s.config_.game, s.table_, s.config_.params};
    s.game_number_ = static_cast<int>(root.at("game_number").integer_in(0, max_count));
    s.rack_number_ = static_cast<int>(root.at("rack_number").integer_in(0, max_count));
    s.score_ = read_score(root.at("score"));
    if (Field w = root.at("winner"); !w.is_null()) s.winner_ = w.name_of<rules::Player>();
    s.state_ = read_state(root.at("state"), t, Fields::all, s.winner_.has_value());
    s.pending_ = read_pending(root.at("pending"), t, s.state_, s.winner_.has_value());
    s.pocketed_ = read_pocketed(root.at("pocketed"), t, s.state_);
    s.history_ = read_history(root.at("history"), t, s.config_.keep_events, s.rack_number_);
    if (s.winner_ && (s.history_.empty() || !s.history_.back().verdict.game_over))
        root.at("winner").fail("the game is over, but the last shot of the history did not end it");
    if (!s.history_.empty() && s.history_.back().verdict.game_over &&
        s.history_.back().verdict.winner != s.winner_)
        root.at("winner").fail(
            "the last shot of the history ended the game with another winner: give that one");
    if (s.pending_ &&
        (s.history_.empty() || !s.history_.back().verdict.choice || s.history_.back().choice))
        root.at("pending").fail("the last shot of the history offers no open choice");
    return s;
}

}  // namespace game
