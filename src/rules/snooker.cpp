#include "rules/snooker.hpp"

#include <algorithm>
#include <stdexcept>

#include "rules/shot_facts.hpp"
#include "rules/snooker_table.hpp"

namespace rules {

namespace {

using physics::is_colour;
using physics::is_red;
using physics::snooker_value;
namespace ball = physics::snooker_ball;

/// The cue tip stays on the ball about a millisecond (unit: s): a ball met sooner was pushed.
constexpr double kTipContactTime = 0.001;

int lowest_colour(const SnookerState& s) {
    for (int c = ball::yellow; c <= ball::black; ++c)
        if (s.has(c)) return c;
    return ball::black;
}

/// The balls that are on for this stroke (the nominated free ball included).
std::set<int> balls_on(const SnookerState& s) {
    std::set<int> on;
    if (s.colour_on) {
        for (int c = ball::yellow; c <= ball::black; ++c)
            if (s.has(c) && (!s.nominated || *s.nominated == c)) on.insert(c);
        return on;
    }
    if (s.reds() > 0) {
        for (int r = ball::first_red; r <= ball::last_red; ++r)
            if (s.has(r)) on.insert(r);
    } else {
        on.insert(lowest_colour(s));
    }
    if (s.free_ball && s.nominated) on.insert(*s.nominated);
    return on;
}

/// The value of the ball on, for a foul's penalty.
int value_on(const SnookerState& s) {
    if (s.colour_on) return s.nominated ? snooker_value(*s.nominated) : 0;
    return s.reds() > 0 ? 1 : snooker_value(lowest_colour(s));
}

/// Whether the cue ball met a ball within the tip's contact time after the strike (events
/// without times say nothing: a frozen ball is the touching-ball rule's).
bool pushed(std::span<const physics::Event> events) {
    double strike = -1.0;
    for (const physics::Event& e : events) {
        if (e.type == physics::EventType::strike) strike = e.time;
        if (e.type == physics::EventType::ball_ball && e.involves(ball::cue))
            return strike >= 0.0 && e.time > strike && e.time - strike < kTipContactTime;
    }
    return false;
}

/// What the stroke did, as the snooker rules see it.
struct Stroke {
    ShotFacts facts;
    std::set<int> on;          ///< may be potted
    std::set<int> first_on;    ///< may be hit first: the balls on, or only the nominated free ball
    std::optional<int> first;  ///< the first ball hit (a touching ball on is deemed hit)
    std::optional<int> nominated;  ///< with a colour on: nominated, else the first colour hit
    std::vector<int> potted;       ///< object balls potted, in order
    std::optional<int> touching;   ///< the ball on the cue ball touched at the start
};

Stroke read_stroke(const SnookerState& s, std::span<const physics::Event> events, double R) {
    Stroke k;
    k.facts = distill(events, 0.0);
    k.nominated = s.nominated;
    k.first = k.facts.first_contact;
    if (s.colour_on && !s.nominated && k.first && is_colour(*k.first)) k.nominated = k.first;
    SnookerState nominated_state = s;
    nominated_state.nominated = k.nominated;
    k.on = balls_on(nominated_state);
    k.first_on = s.free_ball && s.nominated ? std::set<int>{*s.nominated} : k.on;
    // A cue ball in hand counts where the striker placed it (its position, when given).
    if (auto t = touching_ball(s.positions, R); t && k.on.count(*t) != 0) k.touching = t;
    if (!k.first && k.touching) k.first = k.touching;
    for (const PocketedBall& p : k.facts.pocketed) k.potted.push_back(p.ball);
    return k;
}

std::vector<SnookerFoul> find_fouls(const SnookerState& s, const Stroke& k,
                                    std::span<const physics::Event> events) {
    std::vector<SnookerFoul> f;
    if (k.facts.cue_pocketed) f.push_back(SnookerFoul::in_off);
    if (k.facts.cue_off_table) f.push_back(SnookerFoul::cue_ball_off_table);
    if (!k.first) {
        f.push_back(SnookerFoul::no_contact);
    } else if (k.first_on.count(*k.first) == 0) {
        f.push_back(SnookerFoul::wrong_ball_first);
    }
    for (int b : k.potted) {
        if (k.on.count(b) == 0 || (s.colour_on && k.potted.size() > 1)) {
            f.push_back(SnookerFoul::ball_not_on_potted);
            break;
        }
    }
    if (!k.facts.off_table.empty()) f.push_back(SnookerFoul::ball_off_table);
    if (pushed(events) || (k.touching && k.facts.first_contact == k.touching))
        f.push_back(SnookerFoul::push_stroke);
    return f;
}

/// Four points, or the value of the ball on, the ball first hit, or a ball potted or driven
/// off the table, whichever is highest (S3 R10, Penalties); seven for reds in successive strokes.
int foul_value(const SnookerState& s, const Stroke& k) {
    int v = std::max(4, value_on(s));
    if (k.first && k.first_on.count(*k.first) == 0) v = std::max(v, snooker_value(*k.first));
    if (s.colour_on && k.first && is_red(*k.first)) v = 7;
    for (int b : k.potted) v = std::max(v, snooker_value(b));
    for (int b : k.facts.off_table) v = std::max(v, snooker_value(b));
    if (s.colour_on && k.nominated) v = std::max(v, snooker_value(*k.nominated));
    return v;
}

bool needs_snookers(const SnookerState& s, Player p) {
    return s.score(other(p)) - s.score(p) > points_remaining(s);
}

/// The table after the stroke: balls gone removed, the cue ball where it lies or in hand.
SnookerState table_after(const SnookerState& s, const Stroke& k,
                         std::span<const physics::Event> events) {
    SnookerState n = s;
    for (int b : k.potted) n.on_table.erase(b);
    for (int b : k.facts.off_table) n.on_table.erase(b);
    n.positions = last_positions(s.positions, events);
    std::erase_if(n.positions, [&](const auto& e) { return e.first != 0 && !n.has(e.first); });
    n.cue_ball = k.facts.cue_ball_lost() ? CueBall::in_hand : CueBall::on_table;
    if (n.cue_ball == CueBall::in_hand) n.positions.erase(0);
    n.nominated.reset();
    n.free_ball = false;
    n.colour_on = false;
    n.misses = 0;
    return n;
}

void respot(SnookerVerdict& v, std::vector<int> colours, const SnookerTable& table) {
    for (int c : colours) v.state.on_table.insert(c);
    std::vector<Respot> r = respot_colours(std::move(colours), v.state.positions, table);
    v.respotted.insert(v.respotted.end(), r.begin(), r.end());
}

void end_frame(SnookerVerdict& v, Player last_striker) {
    const SnookerState& n = v.state;
    if (n.score(Player::A) == n.score(Player::B) && !n.respotted_black) {
        v.respotted_black = true;
        return;
    }
    v.frame_over = true;
    v.next_shooter.reset();
    v.winner = n.score(Player::A) > n.score(Player::B) ? Player::A : Player::B;
    if (n.score(Player::A) == n.score(Player::B)) v.winner = other(last_striker);
}

/// The re-spotted black after a tie: the black on its spot, the opponent of the last striker
/// plays first with the cue ball in hand (docs/rules.md: the project's stand-in for lots).
void start_respotted_black(SnookerVerdict& v, Player last_striker, const SnookerTable& t) {
    SnookerState& n = v.state;
    n.on_table = {ball::black};
    n.positions.clear();
    n.respotted_black = true;
    n.cue_ball = CueBall::in_hand;
    respot(v, {ball::black}, t);
    n.shooter = other(last_striker);
    n.break_points = 0;
    v.next_shooter = n.shooter;
}

}  // namespace

int SnookerState::reds() const {
    return static_cast<int>(std::count_if(on_table.begin(), on_table.end(), is_red));
}

bool SnookerVerdict::has(SnookerFoul f) const {
    return std::find(fouls.begin(), fouls.end(), f) != fouls.end();
}

BallOn ball_on(const SnookerState& s) {
    if (s.colour_on) return BallOn::colour;
    if (s.reds() > 0) return BallOn::red;
    return static_cast<BallOn>(static_cast<int>(BallOn::yellow) + lowest_colour(s) - ball::yellow);
}

int points_remaining(const SnookerState& s) {
    int total = 8 * s.reds() + (s.colour_on ? 7 : 0);
    for (int c = ball::yellow; c <= ball::black; ++c)
        if (s.has(c)) total += snooker_value(c);
    return total;
}

namespace {

bool placed(const Positions& pos, const std::set<int>& on) {
    return pos.count(0) != 0 &&
           std::all_of(on.begin(), on.end(), [&](int b) { return pos.count(b) != 0; });
}

/// Foul and a miss (S3 R14): the ball on not hit first with a clear path to one, unless either
/// player needed snookers. A third miss in a row with a ball on visible at both edges, the
/// balls replaced each time, gives the frame to the opponent.
void call_miss(SnookerVerdict& v, const SnookerOptions& o, const SnookerTable& t,
               const SnookerState& s, const Stroke& k) {
    const Player striker = s.shooter, opponent = other(s.shooter);
    const SnookerState& n = v.state;
    const bool needed = needs_snookers(s, striker) || needs_snookers(s, opponent) ||
                        needs_snookers(n, striker) || needs_snookers(n, opponent);
    v.miss = o.miss_rule &&
             (v.has(SnookerFoul::no_contact) || v.has(SnookerFoul::wrong_ball_first)) && !needed &&
             has_clear_path(s.positions, k.first_on, t.ball_radius);
    const bool full_ball = v.miss && !is_snookered(s.positions, k.first_on, t.ball_radius);
    v.misses = full_ball ? s.misses + 1 : 0;
    if (v.misses >= 3) {
        v.frame_over = true;
        v.winner = opponent;
        v.next_shooter.reset();
        v.may_ask_to_play_again = false;
    }
}

/// A free ball must not be left snookering the incoming striker on every ball on (S3 R12),
/// except when only the pink and black remain; judged when the turn passes (nothing potted).
bool snookered_by_free_ball(const SnookerState& s, const Stroke& k, const SnookerState& after,
                            double R) {
    if (!s.free_ball || !s.nominated || !k.potted.empty() || !after.has(*s.nominated)) return false;
    if (after.on_table == std::set<int>{ball::pink, ball::black}) return false;
    const std::set<int> on = balls_on(after);
    if (!placed(after.positions, on) || after.positions.count(*s.nominated) == 0) return false;
    Positions without = after.positions;
    without.erase(*s.nominated);
    return is_snookered(after.positions, on, R) && !is_snookered(without, on, R);
}

/// After a foul: the points to the opponent, the colours back, the opponent to play (or the
/// frame over on the last black), a free ball if he is snookered, a miss if one is called.
void judge_foul(SnookerVerdict& v, const SnookerOptions& o, const SnookerTable& t,
                const SnookerState& s, const Stroke& k) {
    const Player striker = s.shooter, opponent = other(s.shooter);
    SnookerState& n = v.state;
    v.foul_points = foul_value(s, k);
    n.scores[index(opponent)] += v.foul_points;
    n.break_points = 0;
    n.shooter = opponent;
    v.next_shooter = opponent;
    std::vector<int> colours;
    for (int b : k.potted)
        if (is_colour(b)) colours.push_back(b);
    for (int b : k.facts.off_table)
        if (is_colour(b)) colours.push_back(b);
    const bool last_black = s.respotted_black || (s.reds() == 0 && !s.colour_on &&
                                                  s.on_table == std::set<int>{ball::black});
    if (last_black) {
        end_frame(v, striker);
        if (v.respotted_black) start_respotted_black(v, striker, t);
        return;
    }
    respot(v, colours, t);
    v.may_ask_to_play_again = true;
    call_miss(v, o, t, s, k);
    if (v.frame_over) return;
    const std::set<int> next_on = balls_on(n);
    // In hand in the D the striker chooses where the cue ball goes: no free ball (docs/rules.md).
    if (n.cue_ball == CueBall::on_table && placed(n.positions, next_on))
        v.free_ball = is_snookered(n.positions, next_on, t.ball_radius);
}

/// A legal stroke: the balls potted score; colours after a red go back; the striker goes on
/// if he scored.
void judge_legal(SnookerVerdict& v, const SnookerTable& t, const SnookerState& s, const Stroke& k) {
    SnookerState& n = v.state;
    const int value = s.colour_on || s.reds() > 0 ? 0 : snooker_value(lowest_colour(s));
    std::vector<int> colours;
    int points = 0;
    for (int b : k.potted) {
        const bool free = s.free_ball && s.nominated == b;
        if (s.colour_on) {
            points += snooker_value(b);
            colours.push_back(b);
        } else if (is_red(b)) {
            points += 1;
        } else if (free) {  // scores as the ball on (S3 R12, Snookered after a Foul); back on its
                            // spot
            if (k.potted.size() == 1 || s.reds() > 0) points += s.reds() > 0 ? 1 : value;
            colours.push_back(b);
        } else {
            points += snooker_value(b);
        }
    }
    v.points_scored = points;
    n.scores[index(s.shooter)] += points;
    respot(v, colours, t);
    if (points == 0) {
        n.shooter = other(s.shooter);
        n.break_points = 0;
    } else {
        n.break_points += points;
        n.colour_on = !s.colour_on && s.reds() > 0;  // a red (or a free ball as one) went down
    }
    v.next_shooter = n.shooter;
    if (s.respotted_black && points > 0) return end_frame(v, s.shooter);
    if (!s.respotted_black && n.on_table.empty()) {
        end_frame(v, s.shooter);
        if (v.respotted_black) start_respotted_black(v, s.shooter, t);
    }
}

}  // namespace

SnookerVerdict judge_snooker(const SnookerOptions& options, const SnookerTable& table,
                             const SnookerState& s, std::span<const physics::Event> events) {
    const Stroke k = read_stroke(s, events, table.ball_radius);
    SnookerVerdict v;
    v.fouls = find_fouls(s, k, events);
    if (std::find(v.fouls.begin(), v.fouls.end(), SnookerFoul::no_contact) != v.fouls.end())
        std::erase_if(v.fouls, [](SnookerFoul f) { return f == SnookerFoul::wrong_ball_first; });
    v.state = table_after(s, k, events);
    if (snookered_by_free_ball(s, k, v.state, table.ball_radius))
        v.fouls.push_back(SnookerFoul::snookered_by_free_ball);
    v.foul = !v.fouls.empty();
    if (v.foul)
        judge_foul(v, options, table, s, k);
    else
        judge_legal(v, table, s, k);
    if (!v.frame_over) {
        v.ball_on = ball_on(v.state);
        if (v.state.cue_ball == CueBall::on_table)
            v.touching_ball = touching_ball(v.state.positions, table.ball_radius);
    }
    v.state.free_ball = v.free_ball;
    return v;
}

SnookerState resolve_after_foul(const SnookerVerdict& v, const SnookerState& before,
                                AfterFoul choice) {
    if (choice == AfterFoul::play) return v.state;
    if (!v.may_ask_to_play_again || (choice == AfterFoul::replace && !v.miss))
        throw std::invalid_argument(choice == AfterFoul::replace
                                        ? "resolve_after_foul: no miss was called"
                                        : "resolve_after_foul: the stroke was not a foul");
    SnookerState n = choice == AfterFoul::replace ? before : v.state;
    n.scores = v.state.scores;
    n.shooter = before.shooter;
    n.break_points = 0;
    n.free_ball = false;
    if (choice == AfterFoul::replace) {
        n.colour_on = before.colour_on;
        n.misses = v.misses;  // the balls replaced: the misses in a row go on counting
    }
    return n;
}

}  // namespace rules
