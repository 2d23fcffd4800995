// The three-cushion save format (docs/game.md, "Snooker and three-cushion saves"):
// CaromSession::to_json and from_json. Reading checks every field and the whole.
#include <fmt/format.h>

#include "game/atomic_file.hpp"
#include "game/carom_session.hpp"
#include "game/match_json.hpp"
#include "game/state_json.hpp"
#include "game/text_file.hpp"
#include "rules/names.hpp"

namespace game {

using nlohmann::ordered_json;

namespace {

constexpr std::string_view format_name = "coolaaber-three-cushion";
constexpr int max_count = 100000;

ordered_json state_json(const rules::CaromState& s) {
    ordered_json j;
    j["shooter"] = rules::name(s.shooter);
    j["starter"] = rules::name(s.starter);
    j["opening"] = s.opening;
    j["equalizing"] = s.equalizing;
    j["scores"] = match_json::pair(s.scores);
    j["innings"] = match_json::pair(s.innings);
    j["run"] = s.run;
    j["high_run"] = match_json::pair(s.high_run);
    j["positions"] = match_json::positions(s.positions);
    return j;
}

rules::CaromState read_state(const Field& f, const CaromSession& s) {
    f.require_fields({"shooter", "starter", "opening", "equalizing", "scores", "innings", "run",
                      "high_run", "positions"});
    rules::CaromState st;
    st.shooter = f.at("shooter").name_of<rules::Player>();
    st.starter = f.at("starter").name_of<rules::Player>();
    if (st.starter != s.starter_of_game(s.game_number()))
        f.at("starter").fail(fmt::format("game {} is opened by {}", s.game_number() + 1,
                                         rules::name(s.starter_of_game(s.game_number()))));
    st.opening = f.at("opening").boolean();
    st.equalizing = f.at("equalizing").boolean();
    st.scores = match_json::read_pair(f.at("scores"), 0, max_count);
    st.innings = match_json::read_pair(f.at("innings"), 0, max_count);
    st.run = static_cast<int>(f.at("run").integer_in(0, max_count));
    st.high_run = match_json::read_pair(f.at("high_run"), 0, max_count);
    for (rules::Player p : {rules::Player::A, rules::Player::B}) {
        const std::size_t i = rules::index(p);
        if (st.high_run[i] > st.scores[i])
            f.at("high_run").at(rules::name(p)).fail("a run higher than the player's score");
    }
    if (st.run > st.scores[rules::index(st.shooter)])
        f.at("run").fail("a run higher than the striker's score");
    if (st.opening && (st.scores != std::array<int, 2>{0, 0}))
        f.at("opening").fail("the opening stroke comes before any point");
    st.positions = match_json::read_positions(f.at("positions"), s.table(), s.config().params,
                                              [](int id) { return id >= 0 && id <= 2; });
    if (st.positions.size() != 3)
        f.at("positions").fail("the white, the yellow and the red (\"0\", \"1\", \"2\")");
    return st;
}

ordered_json config_json(const CaromConfig& c) {
    ordered_json j;
    j["target"] = c.options.target;
    j["equal_innings"] = c.options.equal_innings;
    j["table"] = to_json(c.table);
    j["params"] = to_json(c.params);
    j["players"] = match_json::names(c.names);
    j["first_starter"] = rules::name(c.first_starter);
    return j;
}

CaromConfig read_config(const Field& f) {
    f.require_fields({"target", "equal_innings", "table", "params", "players", "first_starter"});
    CaromConfig c;
    c.options.target = static_cast<int>(f.at("target").integer_in(1, 1000));
    c.options.equal_innings = f.at("equal_innings").boolean();
    c.params = read_params(f.at("params"), Fields::all);
    c.table = read_table(f.at("table"), c.params.ball_radius, Fields::all);
    c.names = match_json::read_names(f.at("players"));
    c.first_starter = f.at("first_starter").name_of<rules::Player>();
    return c;
}

}  // namespace

struct CaromJson {
    static void read_result(const Field& root, CaromSession& s) {
        s.over_ = root.at("game_over").boolean();
        if (Field w = root.at("winner"); !w.is_null()) {
            if (!s.over_) w.fail("must be null: the game is not over");
            s.winner_ = w.name_of<rules::Player>();
        }
        const std::array<int, 2>& sc = s.state_.scores;
        const int target = s.config_.options.target;
        const bool reached = sc[0] >= target || sc[1] >= target;
        if (s.over_ && !reached) root.at("game_over").fail("nobody has reached the target");
        if (s.winner_ && sc[rules::index(*s.winner_)] < target)
            root.at("winner").fail("the winner has not reached the target");
    }
};

std::string CaromSession::to_json() const {
    ordered_json j;
    match_json::write_header(j, format_name);
    j["config"] = config_json(config_);
    j["game"] = game_;
    j["games_won"] = match_json::pair(games_);
    j["state"] = state_json(state_);
    j["game_over"] = over_;
    j["winner"] = winner_ ? ordered_json(rules::name(*winner_)) : ordered_json(nullptr);
    return j.dump() + "\n";
}

CaromSession CaromSession::from_json(const std::string& text) {
    const nlohmann::json doc = parse_document(text, "carom");
    const Field root(doc, "carom");
    match_json::check_header(root, format_name);
    root.require_fields(
        {"format", "version", "config", "game", "games_won", "state", "game_over", "winner"});
    CaromSession s(read_config(root.at("config")), Restored{});
    s.game_ = static_cast<int>(root.at("game").integer_in(0, max_count));
    s.games_ = match_json::read_pair(root.at("games_won"), 0, max_count);
    if (s.games_[0] + s.games_[1] > s.game_ + 1)
        root.at("games_won").fail("more games won than games played");
    s.state_ = read_state(root.at("state"), s);
    CaromJson::read_result(root, s);
    return s;
}

void CaromSession::save_file(const std::filesystem::path& path) const {
    const std::string text = to_json();
    try {
        (void)from_json(text);  // never write a file that would not load
    } catch (const LoadError& e) {
        throw std::logic_error(fmt::format(
            "save: the three-cushion game does not read back ({}); please report this", e.what()));
    }
    write_file_atomically(path, text);
}

CaromSession CaromSession::load_file(const std::filesystem::path& path) {
    return from_json(read_regular_file(path));
}

}  // namespace game
