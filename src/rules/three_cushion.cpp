#include "rules/three_cushion.hpp"

#include <algorithm>

#include "rules/snooker_table.hpp"

namespace rules {

namespace {

namespace ball = physics::carom_ball;
using physics::EventType;

constexpr double kTipContactTime = 0.001;  ///< as in snooker (unit: s)

/// The stroke as the carom rules see it.
struct CaromStroke {
    std::optional<int> struck;   ///< the ball the cue struck
    std::vector<int> balls_hit;  ///< the other balls the struck ball met, first meetings, in order
    int cushions_before_second = 0;
    int cushions = 0;
    bool pushed = false;
    std::vector<int> off_table;  ///< balls that left the table (a pocket counts)
};

CaromStroke read_stroke(std::span<const physics::Event> events) {
    CaromStroke k;
    double strike_time = 0.0;
    for (const physics::Event& e : events) {
        if ((e.type == EventType::strike || e.type == EventType::miscue) && !k.struck) {
            k.struck = e.ball(0);
            strike_time = e.time;
        }
        if (!k.struck) continue;
        const int cue = *k.struck;
        if (e.type == EventType::cushion && e.ball(0) == cue) {
            ++k.cushions;
            if (k.balls_hit.size() < 2) ++k.cushions_before_second;
        } else if (e.type == EventType::ball_ball && e.involves(cue)) {
            const int other = e.ball(0) == cue ? e.ball(1) : e.ball(0);
            if (k.balls_hit.empty() && e.time > strike_time &&
                e.time - strike_time < kTipContactTime)
                k.pushed = true;
            if (std::find(k.balls_hit.begin(), k.balls_hit.end(), other) == k.balls_hit.end())
                k.balls_hit.push_back(other);
        } else if (e.type == EventType::off_table || e.type == EventType::pocket) {
            if (std::find(k.off_table.begin(), k.off_table.end(), e.ball(0)) == k.off_table.end())
                k.off_table.push_back(e.ball(0));
        }
    }
    return k;
}

std::vector<CaromFoul> find_fouls(const CaromState& s, const CaromStroke& k) {
    std::vector<CaromFoul> f;
    if (k.struck != s.cue_ball(s.shooter)) f.push_back(CaromFoul::wrong_cue_ball);
    if (!k.off_table.empty()) f.push_back(CaromFoul::ball_off_table);
    if (k.pushed) f.push_back(CaromFoul::push_stroke);
    if (s.opening && (k.balls_hit.empty() || k.balls_hit.front() != ball::red))
        f.push_back(CaromFoul::red_not_first);
    return f;
}

/// A ball that left the table goes back on its spot (red: top; white, yellow: bottom), or on
/// the first free one of top, bottom, the starting spot.
void respot(CaromVerdict& v, const std::vector<int>& balls, const physics::CaromSpots& spots,
            double R) {
    for (int b : balls) {
        v.state.positions.erase(b);
        std::vector<physics::Vec2> order{b == ball::red ? spots.top : spots.bottom, spots.top,
                                         spots.bottom, spots.start_right};
        for (physics::Vec2 p : order) {
            bool free = true;
            for (const auto& [id, q] : v.state.positions)
                if (physics::norm(q - p) < 2.0 * R) free = false;
            if (free) {
                v.state.positions[b] = p;
                break;
            }
        }
        v.respotted.push_back(b);
    }
}

/// The inning ends: the turn passes, or the game ends after an equalizing inning.
void end_inning(CaromVerdict& v, const CaromState& s) {
    CaromState& n = v.state;
    if (s.equalizing) {
        v.game_over = true;
        v.winner = s.starter;
        v.next_shooter.reset();
        return;
    }
    n.shooter = other(s.shooter);
    n.innings[index(n.shooter)] += 1;
    n.run = 0;
    v.next_shooter = n.shooter;
}

/// The shooter reached the target: he wins, or (equal innings) the other player may equalize.
void reach_target(CaromVerdict& v, const CaromOptions& o, const CaromState& s) {
    CaromState& n = v.state;
    v.game_over = true;
    v.next_shooter.reset();
    if (s.equalizing) {  // both reached it in as many innings: a draw
        v.winner.reset();
        return;
    }
    if (o.equal_innings && s.shooter == s.starter) {
        v.game_over = false;
        n.equalizing = true;
        n.shooter = other(s.shooter);
        n.innings[index(n.shooter)] += 1;
        n.run = 0;
        v.next_shooter = n.shooter;
        return;
    }
    v.winner = s.shooter;
}

}  // namespace

CaromVerdict judge_three_cushion(const CaromOptions& options, const physics::CaromSpots& spots,
                                 double ball_radius, const CaromState& s,
                                 std::span<const physics::Event> events) {
    const CaromStroke k = read_stroke(events);
    CaromVerdict v;
    v.fouls = find_fouls(s, k);
    v.foul = !v.fouls.empty();
    v.cushions = k.balls_hit.size() >= 2 ? k.cushions_before_second : k.cushions;
    v.point = !v.foul && k.balls_hit.size() >= 2 && k.cushions_before_second >= 3;
    v.state = s;
    v.state.opening = false;
    v.state.positions = last_positions(s.positions, events);
    respot(v, k.off_table, spots, ball_radius);
    v.next_shooter = s.shooter;
    if (!v.point) {
        end_inning(v, s);
        return v;
    }
    CaromState& n = v.state;
    n.scores[index(s.shooter)] += 1;
    n.run += 1;
    n.high_run[index(s.shooter)] = std::max(n.high_run[index(s.shooter)], n.run);
    if (n.scores[index(s.shooter)] >= options.target) reach_target(v, options, s);
    return v;
}

}  // namespace rules
