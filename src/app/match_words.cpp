#include "app/match_words.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <set>

namespace app {

namespace {

namespace sb = physics::snooker_ball;
using rules::Player;

std::string number_word(int n) {
    static constexpr std::array<const char*, 11> words{
        "no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"};
    return n >= 0 && n <= 10 ? words[static_cast<std::size_t>(n)] : std::to_string(n);
}

std::string points(int n) {
    return fmt::format("{} point{}", n, n == 1 ? "" : "s");
}

// The balls the shot pocketed (the cue ball left out), in the order they dropped.
std::vector<int> potted(const physics::Shot& shot) {
    std::vector<int> out;
    for (const physics::Event& e : shot.events())
        if (e.type == physics::EventType::pocket && e.ball(0) != 0) out.push_back(e.ball(0));
    return out;
}

// The first ball the cue ball `cue` met, if any.
std::optional<int> first_hit(std::span<const physics::Event> events, int cue) {
    for (const physics::Event& e : events)
        if (e.type == physics::EventType::ball_ball && e.involves(cue))
            return e.ball(0) == cue ? e.ball(1) : e.ball(0);
    return std::nullopt;
}

// "a red", "two reds", "the pink", "a red and the black".
std::string potted_words(const std::vector<int>& balls) {
    const auto reds = std::count_if(balls.begin(), balls.end(), physics::is_red);
    std::vector<std::string> parts;
    if (reds == 1) parts.push_back("a red");
    if (reds > 1) parts.push_back(number_word(static_cast<int>(reds)) + " reds");
    for (int id : balls)
        if (physics::is_colour(id)) parts.push_back("the " + game::snooker_ball_name(id));
    return fmt::format("{}", fmt::join(parts, " and "));
}

std::string ball_words(int id) {
    return physics::is_red(id) ? "a red" : "the " + game::snooker_ball_name(id);
}

std::string foul_reason(const game::SnookerSession& s, rules::SnookerFoul f,
                        const physics::Shot& shot) {
    const std::optional<int> first = first_hit(shot.events(), sb::cue);
    const std::string on = game::ball_on_name(rules::ball_on(s.before()));
    switch (f) {
        case rules::SnookerFoul::in_off:
            return first ? "the cue ball went in off " + ball_words(*first)
                         : "the cue ball went in";
        case rules::SnookerFoul::cue_ball_off_table:
            return "the cue ball left the table";
        case rules::SnookerFoul::no_contact:
            return "the cue ball hit no ball; " + on + " was on";
        case rules::SnookerFoul::wrong_ball_first:
            return fmt::format(
                "{} was hit first; {} was on", first ? ball_words(*first) : "a ball",
                s.before().nominated && s.before().colour_on
                    ? "the nominated " + game::snooker_ball_name(*s.before().nominated)
                    : on);
        case rules::SnookerFoul::ball_not_on_potted:
            return potted_words(potted(shot)) + " went in, and not all of it was on";
        case rules::SnookerFoul::ball_off_table:
            return "a ball left the table";
        case rules::SnookerFoul::push_stroke:
            return "a push stroke (the cue was still on the cue ball when it met a ball)";
        case rules::SnookerFoul::snookered_by_free_ball:
            return "the free ball left a snooker";
    }
    return "a foul";
}

std::string frame_end_words(const game::SnookerSession& s) {
    const rules::SnookerState& st = s.state();
    const Player w = *s.frame_winner();
    std::string out =
        fmt::format(" {} wins the frame {}–{}.", s.name(w), st.score(w), st.score(rules::other(w)));
    if (const std::optional<Player> m = s.match_winner())
        out +=
            fmt::format(" {} wins the match {}–{}.", s.name(*m), s.frames_won()[rules::index(*m)],
                        s.frames_won()[rules::index(rules::other(*m))]);
    return out;
}

}  // namespace

int snookers_required(const game::SnookerSession& s, Player p) {
    const int behind = s.state().score(rules::other(p)) - s.state().score(p);
    return std::max(0, behind - s.points_remaining());
}

std::string snooker_foul_words(const game::SnookerSession& s, const rules::SnookerVerdict& v,
                               const physics::Shot& shot) {
    const Player offender = s.before().shooter;
    return fmt::format("Foul: {} to {} — {}", points(v.foul_points), s.name(rules::other(offender)),
                       foul_reason(s, v.fouls.front(), shot));
}

std::string snooker_shot_words(const game::SnookerSession& s, const physics::Shot& shot) {
    if (!s.last_verdict()) return "";
    const rules::SnookerVerdict& v = *s.last_verdict();
    const Player striker = s.before().shooter;
    std::string out;
    if (v.foul) {
        out = snooker_foul_words(s, v, shot) + ".";
        if (v.miss) out += " A miss.";
        if (v.misses == 2)
            out += fmt::format(" {}: a third miss loses the frame.", s.name(striker));
    } else if (v.points_scored > 0) {
        out = fmt::format("{} pots {}: {}, break {}.", s.name(striker), potted_words(potted(shot)),
                          points(v.points_scored), v.state.break_points);
    } else {
        out = fmt::format("No score for {}.", s.name(striker));
    }
    for (const rules::Respot& r : v.respotted)
        out += fmt::format(" The {} is re-spotted{}.", game::snooker_ball_name(r.ball),
                           !r.spot ? " as near its spot as it can go"
                           : *r.spot != r.ball
                               ? " on the " + game::snooker_ball_name(*r.spot) + " spot"
                               : "");
    if (v.frame_over) return out + frame_end_words(s);
    if (v.respotted_black)
        out += " The scores are level: the black is re-spotted, the cue ball in hand.";
    if (v.free_ball && v.next_shooter)
        out += fmt::format(" Free ball: {} is snookered and may nominate any ball.",
                           s.name(*v.next_shooter));
    if (!s.choices().empty()) {
        const Player chooser = rules::other(striker);
        out += fmt::format(" {} may play, or ask {} to play again{}.", s.name(chooser),
                           s.name(striker),
                           s.choices().size() > 2 ? " with the balls replaced or as they lie" : "");
    } else if (v.next_shooter && *v.next_shooter != striker) {
        out += fmt::format(" {} to play.", s.name(*v.next_shooter));
    }
    return out;
}

std::string after_foul_words(const game::SnookerSession& s, rules::AfterFoul choice) {
    const Player offender = s.before().shooter, chooser = rules::other(offender);
    switch (choice) {
        case rules::AfterFoul::play:
            return fmt::format("{} plays from where the balls lie.", s.name(chooser));
        case rules::AfterFoul::play_again:
            return fmt::format("{} asks {} to play again.", s.name(chooser), s.name(offender));
        case rules::AfterFoul::replace:
            return fmt::format("The balls are replaced: {} plays again.", s.name(offender));
    }
    return "";
}

std::vector<std::string> snooker_info(const game::SnookerSession& s, std::optional<int> nom) {
    const rules::SnookerState& st = s.state();
    std::vector<std::string> lines;
    if (s.frame_winner()) {
        lines.push_back(fmt::format("{} won the frame {}–{}", s.name(*s.frame_winner()),
                                    st.score(*s.frame_winner()),
                                    st.score(rules::other(*s.frame_winner()))));
        lines.push_back(s.match_winner()
                            ? fmt::format("{} wins the match", s.name(*s.match_winner()))
                            : "Next frame sets the balls up again");
    } else if (s.phase() == game::MatchPhase::choose) {
        const Player offender = s.before().shooter;
        lines.push_back(fmt::format("Foul by {}: {} chooses", s.name(offender),
                                    s.name(rules::other(offender))));
        lines.push_back(fmt::format("Play from here, or ask {} to play again", s.name(offender)));
    } else {
        std::string on = "on: " + game::ball_on_name(s.ball_on());
        if (st.free_ball)
            on = nom ? "free ball: the " + game::snooker_ball_name(*nom)
                     : "free ball: nominate any ball, or play " + game::ball_on_name(s.ball_on());
        else if (nom)
            on += " (nominated: the " + game::snooker_ball_name(*nom) + ")";
        lines.push_back(fmt::format("{} to play — {}", s.name(st.shooter), on));
        if (st.cue_ball == rules::CueBall::in_hand)
            lines.push_back("Ball in hand: place the cue ball in the D");
    }
    lines.push_back(fmt::format("{} {} – {} {} · break {} · {} remaining", s.name(Player::A),
                                st.score(Player::A), st.score(Player::B), s.name(Player::B),
                                st.break_points, s.points_remaining()));
    for (Player p : {Player::A, Player::B})
        if (const int n = snookers_required(s, p); n > 0 && !s.frame_winner())
            lines.push_back(
                fmt::format("{} needs snookers ({} more than remain)", s.name(p), points(n)));
    if (s.config().best_of > 1)
        lines.push_back(fmt::format("Frames {}–{} (best of {})", s.frames_won()[0],
                                    s.frames_won()[1], s.config().best_of));
    return lines;
}

std::string snooker_aim_foul(const game::SnookerSession& s, std::optional<int> nom,
                             std::span<const physics::Event> events) {
    const std::optional<int> first = first_hit(events, sb::cue);
    if (!first) return "";
    rules::SnookerState st = s.state();
    if (nom) st.nominated = nom;
    const bool free = st.free_ball && st.nominated;
    std::set<int> on;
    const rules::BallOn b = s.ball_on();
    for (int id : st.on_table)
        if ((b == rules::BallOn::red && physics::is_red(id)) ||
            (b == rules::BallOn::colour && physics::is_colour(id) &&
             (!st.nominated || *st.nominated == id)) ||
            (b >= rules::BallOn::yellow &&
             id == sb::yellow + static_cast<int>(b) - static_cast<int>(rules::BallOn::yellow)))
            on.insert(id);
    if (free) on.insert(*st.nominated);
    if (on.count(*first)) return "";
    return fmt::format(
        "Foul as aimed: the cue ball would hit {} first; {} is on.", ball_words(*first),
        st.colour_on && st.nominated ? "the nominated " + game::snooker_ball_name(*st.nominated)
                                     : game::ball_on_name(b));
}

// ---- Three-cushion

std::string carom_shot_words(const game::CaromSession& s, const physics::Shot& shot) {
    if (!s.last_verdict()) return "";
    const rules::CaromVerdict& v = *s.last_verdict();
    std::string out;
    if (v.point) {
        out = fmt::format("Point: {} cushions before the second ball. Run {}.",
                          number_word(v.cushions), v.state.run);
    } else if (v.foul) {
        static constexpr std::array<const char*, 4> reasons{
            "the wrong cue ball was struck", "a ball left the table", "a push or a double hit",
            "the opening stroke must hit the red first"};
        out = fmt::format("Foul: {}.", reasons[static_cast<std::size_t>(v.fouls.front())]);
    } else {
        int cue = 0;
        for (const physics::Event& e : shot.events())
            if (e.type == physics::EventType::strike) cue = e.ball(0);
        std::set<int> met;
        for (const physics::Event& e : shot.events())
            if (e.type == physics::EventType::ball_ball && e.involves(cue))
                met.insert(e.ball(0) == cue ? e.ball(1) : e.ball(0));
        if (met.empty())
            out = "No point: no ball hit.";
        else if (met.size() == 1)
            out = "No point: only one ball hit.";
        else
            out = fmt::format("No point: only {} cushion{} before the second ball.",
                              number_word(v.cushions), v.cushions == 1 ? "" : "s");
    }
    const rules::CaromState& st = s.state();
    if (v.game_over) {
        if (v.winner)
            out += fmt::format(" {} wins the game {}–{}.", s.name(*v.winner),
                               st.scores[rules::index(*v.winner)],
                               st.scores[rules::index(rules::other(*v.winner))]);
        else
            out += fmt::format(" A draw, {}–{}, after the equalizing inning.", st.scores[0],
                               st.scores[1]);
    } else if (!v.point && v.next_shooter) {
        out += fmt::format(" {} to play.", s.name(*v.next_shooter));
    }
    return out;
}

std::vector<std::string> carom_info(const game::CaromSession& s) {
    const rules::CaromState& st = s.state();
    std::vector<std::string> lines;
    if (s.game_over()) {
        lines.push_back(s.winner() ? fmt::format("{} won the game", s.name(*s.winner()))
                                   : "The game is a draw");
        lines.push_back("Next game sets the balls up again");
    } else {
        lines.push_back(fmt::format("{} to play the {} — inning {}{}", s.name(st.shooter),
                                    game::carom_ball_name(s.cue_ball()),
                                    st.innings[rules::index(st.shooter)],
                                    st.equalizing ? " (the equalizing inning)" : ""));
        lines.push_back(fmt::format("Run {} · game to {}", st.run, s.config().options.target));
    }
    lines.push_back(fmt::format("{} {} – {} {}", s.name(Player::A), st.scores[0], st.scores[1],
                                s.name(Player::B)));
    return lines;
}

}  // namespace app
