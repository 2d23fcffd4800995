// The shot pipeline (docs/physics.md): find the next event → advance the balls it involves to
// it → resolve it → record it → re-predict only what it changed. Between events every ball
// follows its closed form, so nothing is stepped and nothing tunnels.
#include "physics/simulate.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "physics/collide.hpp"
#include "physics/cue_strike.hpp"
#include "physics/detect.hpp"
#include "physics/energy.hpp"
#include "physics/motion.hpp"

namespace physics {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kMaxBalls = 16;

constexpr std::array<std::array<double, kMaxBalls>, kMaxBalls> all_pairs(double v) {
    std::array<std::array<double, kMaxBalls>, kMaxBalls> m{};
    for (auto& row : m) row.fill(v);
    return m;
}

/// What a predicted event is about. The order is the tie order of simultaneous events.
enum class Kind : int { ball_ball = 0, line = 1, nose = 2, drop = 3, transition = 4 };

struct Candidate {
    double time = kInf;
    Kind kind = Kind::transition;
    int a = -1;  ///< ball index
    int b = -1;  ///< second ball index, or geometry index
    bool pushing = false;

    /// Total order: time, then kind, then ball and geometry indices (determinism).
    /// (Written out: the same order as std::tie(time, kind, a, b) < …, NaN times included,
    /// which compare as neither before nor after; the event loop's scan calls it 136 times
    /// per event.)
    bool before(const Candidate& o) const {
        if (time < o.time) return true;
        if (!(time == o.time)) return false;
        if (kind != o.kind) return kind < o.kind;
        if (a != o.a) return a < o.a;
        return b < o.b;
    }
};

class Simulation {
    /// Per ball, for its current segment: where and when it starts (a copy of the segment's
    /// start, kept next to the rest), the constant acceleration and its size, the end, and
    /// the speed at the start (units: m, m/s, m/s², s, m/s).
    struct Live {
        Vec2 pos, vel, acc;
        double t0 = 0.0;
        double end = kInf;
        double speed = 0.0;
        double accel = 0.0;
        Motion motion = Motion::stationary;
    };
    /// Where ball k can be until its own next event: within `reach` of `centre`, its position
    /// when it was last predicted (the reach bound from then to own_[k]).
    struct Disc {
        Vec2 centre;
        double reach = 0.0;
    };

  public:
    Simulation(const Table& table, const Params& params, std::span<const BallState> balls,
               const SimOptions& options)
        : table_(table), params_(params), options_(options), n_(balls.size()) {
        assert(n_ <= kMaxBalls && "at most 16 balls (ids 0-15)");
        // Each pocket's lateral window for the drop test, once per simulation (the same
        // expression as before, so the same bits).
        drop_lateral_.reserve(table_.pockets.size());
        for (const Pocket& pk : table_.pockets)
            drop_lateral_.push_back(0.5 * norm(pk.mouth_b - pk.mouth_a) + table_.spec.jaw_depth);
        group_faces();
        segments_.resize(n_);
        // Room for a typical shot's events and segments up front, so that few of them grow
        // (and copy) their storage: a break of 16 balls has 141 events, and its busiest balls
        // a dozen segments or so.
        events_.reserve(std::min<std::size_t>(options_.max_events, 32 + 8 * n_));
        for (auto& segs : segments_) segs.reserve(16);
        for (std::size_t k = 0; k < kMaxBalls; ++k) first_with_[k] = k;
        for (std::size_t i = 0; i < n_; ++i) {
            BallState s = balls[i];
            if (s.motion != Motion::pocketed) s = motion::settle(params_, s);
            segments_[i].push_back({0.0, s});
            set_live(i, s, 0.0);
        }
        // Pair (i, j > i) is predicted by predict_for(j), once own_[j] is known.
        for (std::size_t i = 0; i < n_; ++i) predict_for(i, ~0u << i << 1);
    }

    void strike(const Stroke& stroke) {
        const std::size_t cue = index_of(0);
        const StrikeResult r = physics::strike(params_, stroke);
        BallState s = current(cue).start;
        s.vel = r.vel;
        s.spin = r.spin;
        start_segment(cue, motion::settle(params_, s));
        Event e = make_event(r.miscue ? EventType::miscue : EventType::strike, {cue});
        events_.push_back(e);
        predict_for(cue);
    }

    /// One turn of the pipeline. False once every ball is at rest, or at the event cap.
    bool step() {
        const Candidate next = earliest();
        if (std::isinf(next.time)) {
            // No event left. With a friction of zero a ball can move forever: that shot never
            // ends, and is reported like one cut at the cap.
            for (std::size_t i = 0; i < n_; ++i) {
                const Motion m = current(i).start.motion;
                truncated_ = truncated_ || (m != Motion::stationary && m != Motion::pocketed);
            }
            return false;
        }
        if (events_.size() >= options_.max_events) {
            truncated_ = true;
            return false;
        }
        now_ = next.time;
        resolve(next);
        return true;
    }

    Shot finish() && { return Shot(params_, std::move(events_), std::move(segments_), truncated_); }

  private:
    std::size_t index_of(int id) const {
        for (std::size_t i = 0; i < n_; ++i)
            if (segments_[i].front().start.id == id) return i;
        assert(false && "the struck ball 0 must be in the layout");
        return 0;
    }

    const Segment& current(std::size_t i) const { return segments_[i].back(); }
    double segment_end(std::size_t i) const { return live_[i].end; }
    /// Kinematics of ball i now, from its current segment's closed form.
    motion::Kinematics kinematics(std::size_t i) const {
        const Live& s = live_[i];
        const double dt = now_ - s.t0;
        const Vec2 a = s.acc;
        return {s.pos + dt * s.vel + (0.5 * dt * dt) * a, s.vel + dt * a, a};
    }
    BallState state_now(std::size_t i) const {
        const Segment& s = current(i);
        return motion::evolve(params_, s.start, now_ - s.t0);
    }
    detect::Mover mover(std::size_t i, double until) const {
        return detect::make_mover(kinematics(i), until - now_, rolling(i));
    }
    bool active(std::size_t i) const { return ((active_ >> i) & 1u) != 0; }
    bool rolling(std::size_t i) const { return live_[i].motion == Motion::rolling; }

    void start_segment(std::size_t i, const BallState& s) {
        segments_[i].push_back({now_, s});
        set_live(i, s, now_);
    }
    /// Sets ball i's Live entry for a segment starting at t0 in state s, and its bits in
    /// active_ and still_.
    void set_live(std::size_t i, const BallState& s, double t0) {
        const Live& l = live_[i] = make_live(s, t0);
        const std::uint32_t bit = 1u << i;
        active_ = s.motion == Motion::pocketed ? active_ & ~bit : active_ | bit;
        const bool still = l.vel.x == 0.0 && l.vel.y == 0.0 && l.acc.x == 0.0 && l.acc.y == 0.0 &&
                           std::isfinite(l.pos.x) && std::isfinite(l.pos.y);
        still_ = still ? still_ | bit : still_ & ~bit;
    }
    Live make_live(const BallState& s, double t0) const {
        const Vec2 a = motion::acceleration(params_, s);
        return {s.pos,       s.vel,   a,       t0, t0 + motion::duration(params_, s),
                norm(s.vel), norm(a), s.motion};
    }

    Event make_event(EventType type, std::initializer_list<std::size_t> balls) const {
        Event e;
        e.time = now_;
        e.type = type;
        e.ball_count = static_cast<std::uint8_t>(balls.size());
        std::size_t k = 0;
        for (std::size_t i : balls) {
            const BallState& s = current(i).start;
            e.balls[k++] = {s.id, s.pos, s.vel, s.spin};
        }
        return e;
    }

    // ---- detect ----

    /// The first of all candidates (own and pair) in the total order, or Candidate{} if none
    /// is before it: the first of the per-ball firsts, which predict_for keeps up to date.
    /// (A pointer to the best so far, not a copy of it at each improvement.)
    Candidate earliest() const {
        const Candidate* best = &none_;
        for (std::size_t i = 0; i < n_; ++i)
            if (first_[i].before(*best)) best = &first_[i];
        return *best;
    }

    /// The first of ball k's own candidate and all its pairs. Pairs of k of equal time are
    /// ordered by the other ball's index (their lower index, then their higher), so the first
    /// of the earliest found by a strict < in increasing j is the first in the total order; at
    /// a tie with the own candidate the pair wins (ball_ball is the first kind). Pairs with no
    /// contact (time ∞) and NaN times never win, as with before(); which of several candidates
    /// at time ∞ is kept does not matter, since no event is ever taken at ∞.
    /// Sets first_[k] to it, and first_with_[k] to the other ball where it is a pair (else k).
    /// Only the pairs with a contact (paired_) are looked at, in increasing j.
    void update_first(std::size_t k) {
        const std::array<double, kMaxBalls>& row = pair_time_[k];
        double t = kInf;
        std::size_t best = k;
        for (std::uint32_t m = paired_[k]; m != 0; m &= m - 1) {
            const auto j = static_cast<std::size_t>(std::countr_zero(m));
            if (row[j] < t) {
                t = row[j];
                best = j;
            }
        }
        if (best == k || !(t <= own_[k].time)) {
            first_[k] = own_[k];
            set_first_with(k, k);
        } else {
            first_[k] = pair(k, best);
            set_first_with(k, best);
        }
    }

    /// Sets first_with_[k], keeping firsts_on_ in step.
    void set_first_with(std::size_t k, std::size_t other) {
        const std::size_t was = first_with_[k];
        if (was != k) firsts_on_[was] &= ~(1u << k);
        if (other != k) firsts_on_[other] |= 1u << k;
        first_with_[k] = other;
    }

    /// Re-predicts everything that involves ball i (see predict_candidates), then brings the
    /// per-ball firsts up to date: ball i's afresh; another ball j's only where its pair with i
    /// changed its first (it was that pair, or the new pair comes before it).
    void predict_for(std::size_t i, std::uint32_t later = 0) {
        predict_candidates(i, later);
        update_first(i);
        // (the other balls whose first is a pair with i, and those with a new pair with i;
        // for the rest nothing changes)
        for (std::uint32_t m = (firsts_on_[i] | paired_[i]) & ~(1u << i); m != 0; m &= m - 1) {
            const auto j = static_cast<std::size_t>(std::countr_zero(m));
            if (first_with_[j] == i) {
                update_first(j);
            } else if (pair_time_[i][j] < kInf && pair_time_[i][j] <= first_[j].time) {
                // (a tie is settled by before)
                const Candidate c = pair(i, j);
                if (c.before(first_[j])) {
                    first_[j] = c;
                    set_first_with(j, i);
                }
            }
        }
    }

    /// Re-predicts everything that involves ball i: its own next event, and its pairs. The
    /// pairs with the balls in `later` (a bit per ball) are only cleared: the caller
    /// re-predicts those balls next, which predicts those pairs again (with their new own
    /// events), so a prediction here would be overwritten unread.
    void predict_candidates(std::size_t i, std::uint32_t later) {
        const int ii = static_cast<int>(i);
        own_[i] = Candidate{};
        for (std::uint32_t m = paired_[i]; m != 0; m &= m - 1) {
            const auto j = static_cast<std::size_t>(std::countr_zero(m));
            pair_time_[i][j] = pair_time_[j][i] = kInf;
            paired_[j] &= ~(1u << i);
        }
        paired_[i] = 0;
        if (!active(i)) return;
        const double R = params_.ball_radius;
        // Own events: the transition, then cushions, noses and drops, each searched only up to
        // the earliest found so far (which also tightens the reach bound).
        Candidate own{segment_end(i), Kind::transition, ii, -1, false};
        detect::Mover m = mover(i, own.time);
        auto consider = [&](double tau, Kind kind, int g, bool pushing) {
            Candidate c{now_ + tau, kind, ii, g, pushing};
            if (std::isinf(tau) || !c.before(own)) return;
            own = c;
            m = m.within(tau);
        };
        // The faces and noses of a pocket out of the ball's reach are skipped (see
        // group_faces); the rest are tried in the same order as ever. (The tables' vectors as
        // spans held here: through the references the compiler reloads each vector's bounds
        // at every use, since the stores in between might alias them.)
        const std::span<const CushionLine> faces = table_.lines;
        const std::span<const JawNose> jaw_noses = table_.noses;
        const std::span<const Pocket> pockets = table_.pockets;
        const std::span<const double> drop_lateral = drop_lateral_;
        auto try_line = [&](std::size_t g) {
            const detect::Prediction p = detect::line(m, faces[g], R);
            consider(p.tau, Kind::line, static_cast<int>(g), p.pushing);
        };
        auto try_nose = [&](std::size_t g) {
            const detect::Prediction p = detect::nose(m, jaw_noses[g], R);
            consider(p.tau, Kind::nose, static_cast<int>(g), p.pushing);
        };
        if (!grouped_) {
            for (std::size_t g = 0; g < faces.size(); ++g) try_line(g);
            for (std::size_t g = 0; g < jaw_noses.size(); ++g) try_nose(g);
        }
        std::uint64_t lines = lines_always_, noses = noses_always_;
        for (const FaceGroup& fg : std::span<const FaceGroup>(groups_)) {
            const double limit = fg.radius + R + m.reach * (1.0 + 1e-9) + 1e-5;
            if (norm2(m.k.p - fg.centre) > limit * limit) continue;  // (false if reach is ∞)
            lines |= fg.lines;
            noses |= fg.noses;
        }
        for (; lines != 0; lines &= lines - 1)
            try_line(static_cast<std::size_t>(std::countr_zero(lines)));
        for (; noses != 0; noses &= noses - 1)
            try_nose(static_cast<std::size_t>(std::countr_zero(noses)));
        for (std::size_t g = 0; g < pockets.size(); ++g) {
            consider(detect::drop(m, pockets[g], drop_lateral[g]), Kind::drop, static_cast<int>(g),
                     false);
        }
        own_[i] = own;
        // Pairs: a contact after either ball's own next event need not be searched, since that
        // event re-predicts every pair of the ball. Pairs farther apart than both balls can
        // travel by then are skipped before any polynomial is built.
        const motion::Kinematics ki = kinematics(i);
        const double speed_i = norm(ki.v);
        const bool rolling_i = rolling(i);
        // Ball i's reach up to its own next event, for the pairs that end there (the same
        // call with the same arguments as in the loop, so the same bits).
        const double reach_i_own =
            detect::reach_bound(speed_i, live_[i].accel, own_[i].time - now_, rolling_i);
        disc_[i] = {ki.p, reach_i_own};
        // Ball i's values used by every pair, held here: each store below, and each call of
        // the solver, would make the compiler load them again from the members.
        const double now = now_, own_i = own_[i].time, accel_i = live_[i].accel;
        std::uint32_t paired_i = 0;
        // (the other active balls not in `later`, in increasing j: a bit walk, not a test of
        // every index; two still balls are skipped, see still_)
        std::uint32_t others = active_ & ~later & ~(1u << i);
        if (((still_ >> i) & 1u) != 0) others &= ~still_;
        for (; others != 0; others &= others - 1) {
            const auto j = static_cast<std::size_t>(std::countr_zero(others));
            // Both discs (up to each ball's own next event, which bounds the pair's horizon)
            // more than 2R + 1e-5 m apart: the balls stay that far apart, so the contact
            // quartic is ≥ 4R·1e-5 on the whole horizon, far above its rounding (its terms are
            // below (|Δp| + 3·(reach_i + reach_j))², a few m², kept so by the 50 m cap), and
            // the tests below or the solver would give none. One test instead of the reach
            // bounds and positions.
            const double apart = reach_i_own + disc_[j].reach;  // (disc_[i].reach)
            const double clear = 2 * R + apart + 1e-5;
            if (apart < 50.0 && norm2(disc_[j].centre - ki.p) > clear * clear) continue;
            const double until = std::min(own_i, own_[j].time);
            if (!(until >= now)) continue;
            const double h = until - now;
            const bool rolling_j = rolling(j);
            // |v_j(now)| ≤ |v_j(t0)| + |a_j|·(now − t0): no square root per pair.
            const double speed_j = live_[j].speed + live_[j].accel * (now - live_[j].t0);
            const double reach_i =
                until == own_i ? reach_i_own : detect::reach_bound(speed_i, accel_i, h, rolling_i);
            // (reach_bound is at least 1e-12, never 0: no test for two balls that cannot move)
            const double reach_j = detect::reach_bound(speed_j, live_[j].accel, h, rolling_j);
            const motion::Kinematics kj = kinematics(j);
            const double limit = 2 * R + reach_i + reach_j;
            if (norm2(kj.p - ki.p) > limit * limit) continue;
            // (screened: |Δp|² ≤ limit² here, and circle_contact's limit is the same sum up to
            // an ulp, its test 1e-9 looser). What detect::ball_ball computes, with the same
            // arguments, less its test for two reaches of 0, which reach_bound never returns.
            const detect::Prediction p = detect::detail::circle_contact(
                kj.p - ki.p, kj.v - ki.v, kj.a - ki.a, 2.0 * R, reach_i + reach_j, h, true);
            if (std::isinf(p.tau)) continue;
            pair_time_[i][j] = pair_time_[j][i] = now + p.tau;
            pair_pushing_[i][j] = pair_pushing_[j][i] = p.pushing;
            paired_i |= 1u << j;
            paired_[j] |= 1u << i;
        }
        paired_[i] = paired_i;
    }

    /// Groups each pocket's jaw faces and noses in a circle about the pocket's centre that holds
    /// them all. A face or nose reports a contact only where the ball's centre comes within R
    /// (up to ~1e-6 m: the touching tolerance, rounding) of it, at a point no farther from the
    /// centre now than the reach; so a ball farther than radius + R + reach (+ 1e-5 m) from the
    /// group's centre gets none from any of them, and skipping them changes nothing. Faces and
    /// noses of no pocket (the rails), or tables with more than 64 of either, are always tried.
    void group_faces() {
        const std::size_t nl = table_.lines.size(), nn = table_.noses.size();
        if (nl > 64 || nn > 64) return;  // not grouped: every face and nose is tried
        grouped_ = true;
        groups_.assign(table_.pockets.size(), FaceGroup{});
        for (std::size_t k = 0; k < groups_.size(); ++k)
            groups_[k].centre = table_.pockets[k].centre;
        auto grow = [](FaceGroup& fg, Vec2 at, double extent) {
            const double r = (norm(at - fg.centre) + extent) * (1.0 + 1e-9) + 1e-9;
            if (r > fg.radius) fg.radius = r;
        };
        for (std::size_t g = 0; g < nl; ++g) {
            const CushionLine& l = table_.lines[g];
            const auto bit = std::uint64_t{1} << g;
            if (l.pocket < 0 || static_cast<std::size_t>(l.pocket) >= groups_.size()) {
                lines_always_ |= bit;
                continue;
            }
            FaceGroup& fg = groups_[static_cast<std::size_t>(l.pocket)];
            // (the contact point a + along·dir, 0 ≤ along ≤ length, on the face: detect::line)
            grow(fg, l.a + (0.5 * l.length) * l.dir, 0.5 * l.length);
            fg.lines |= bit;
        }
        for (std::size_t g = 0; g < nn; ++g) {
            const JawNose& n = table_.noses[g];
            const auto bit = std::uint64_t{1} << g;
            if (n.pocket < 0 || static_cast<std::size_t>(n.pocket) >= groups_.size()) {
                noses_always_ |= bit;
                continue;
            }
            FaceGroup& fg = groups_[static_cast<std::size_t>(n.pocket)];
            grow(fg, n.centre, n.radius);
            fg.noses |= bit;
        }
    }

    /// Pair (i, j)'s candidate (i ≠ j), from pair_time_ and pair_pushing_.
    Candidate pair(std::size_t i, std::size_t j) const {
        const auto [lo, hi] = std::minmax(i, j);
        return Candidate{pair_time_[i][j], Kind::ball_ball, static_cast<int>(lo),
                         static_cast<int>(hi), pair_pushing_[i][j]};
    }

    // ---- resolve ----

    void resolve(const Candidate& c) {
        const std::size_t a = static_cast<std::size_t>(c.a);
        switch (c.kind) {
            case Kind::transition: {
                const Motion from = current(a).start.motion;
                start_segment(a, motion::transition(params_, current(a).start));
                Event e = make_event(EventType::transition, {a});
                e.from = from;
                e.to = current(a).start.motion;
                record(e, {a});
                break;
            }
            case Kind::ball_ball: {
                const std::size_t b = static_cast<std::size_t>(c.b);
                BallState sa = state_now(a), sb = state_now(b);
                const double speed =
                    collide::ball_ball(params_, options_.models.ball_ball, sa, sb, c.pushing);
                if (speed < collide::kInelasticSpeed && jammed(a, b)) {
                    // Resolving a slow ball wedged between others one contact at a time
                    // converges too slowly (nearly opposite contacts); a jammed ball stops.
                    for (BallState* st : {&sa, &sb}) {
                        st->vel = {};
                        st->spin.x = st->spin.y = 0.0;
                        *st = motion::settle(params_, *st);
                    }
                }
                start_segment(a, sa);  // collide leaves the balls settled
                start_segment(b, sb);
                Event e = make_event(EventType::ball_ball, {a, b});
                e.speed = speed;
                record(e, {a, b});
                break;
            }
            case Kind::line:
            case Kind::nose: {
                BallState s = state_now(a);
                Vec2 toward;
                Event proto;
                if (c.kind == Kind::line) {
                    const CushionLine& l = table_.lines[static_cast<std::size_t>(c.b)];
                    toward = -1.0 * l.normal;
                    proto.rail = l.rail;
                    proto.pocket = l.pocket;
                } else {
                    const JawNose& n = table_.noses[static_cast<std::size_t>(c.b)];
                    toward = (1.0 / norm(n.centre - s.pos)) * (n.centre - s.pos);
                    proto.pocket = n.pocket;
                }
                const double speed =
                    collide::cushion(params_, options_.models.cushion, table_.spec.cushion_height,
                                     toward, s, c.pushing);
                start_segment(a, s);
                Event e = make_event(EventType::cushion, {a});
                e.speed = speed;
                e.rail = proto.rail;
                e.pocket = proto.pocket;
                record(e, {a});
                break;
            }
            case Kind::drop: {
                BallState s = state_now(a);
                s.vel = {};
                s.spin = {};
                s.motion = Motion::pocketed;
                s.pocket = table_.pockets[static_cast<std::size_t>(c.b)].id;
                start_segment(a, s);
                Event e = make_event(EventType::pocket, {a});
                e.pocket = s.pocket;
                record(e, {a});
                break;
            }
        }
    }

    /// Counts slow contacts of each ball at the current instant; true once either ball of a
    /// pair has had more than kJamContacts of them.
    bool jammed(std::size_t a, std::size_t b) {
        if (now_ != jam_time_) {
            jam_time_ = now_;
            jam_count_.fill(0);
        }
        return ++jam_count_[a] > kJamContacts || ++jam_count_[b] > kJamContacts;
    }

    void record(const Event& e, std::initializer_list<std::size_t> changed) {
#ifndef NDEBUG
        // Energy audit: no event may add energy (the segments before it end at now_).
        double before = 0, after = 0;
        for (std::size_t i : changed) {
            const auto& segs = segments_[i];
            const Segment& prev = segs[segs.size() - 2];
            before += kinetic_energy(params_, motion::evolve(params_, prev.start, now_ - prev.t0));
            after += kinetic_energy(params_, current(i).start);
        }
        assert(after <= before * (1.0 + 1e-9) + 1e-12 &&
               "an event added kinetic energy: check the collision model");
#endif
        events_.push_back(e);
        std::uint32_t later = 0;
        for (std::size_t i : changed) later |= 1u << i;
        for (std::size_t i : changed) predict_for(i, later &= ~(1u << i));
    }

    const Table& table_;
    const Params& params_;
    const SimOptions& options_;
    std::size_t n_;
    double now_ = 0.0;
    bool truncated_ = false;
    std::vector<std::vector<Segment>> segments_;
    std::vector<Event> events_;
    std::vector<double> drop_lateral_;  ///< per pocket: the drop test's lateral window
    /// A pocket's jaw faces and noses (bits of table_.lines, table_.noses) and a circle about
    /// the pocket's centre that holds them.
    struct FaceGroup {
        Vec2 centre{};
        double radius = 0.0;
        std::uint64_t lines = 0, noses = 0;
    };
    std::vector<FaceGroup> groups_;
    std::uint64_t lines_always_ = 0, noses_always_ = 0;  ///< faces and noses of no pocket
    bool grouped_ = false;  ///< false: more than 64 faces or noses, none skipped
    std::array<Live, kMaxBalls> live_{};
    /// A bit per ball that is not pocketed (live_[i].motion != Motion::pocketed), kept by
    /// set_live: the pair loop walks these bits.
    std::uint32_t active_ = 0;
    /// A bit per ball whose segment has velocity and acceleration exactly 0 (at rest, or
    /// spinning in place) at a finite position, kept by set_live. Two such balls have no
    /// contact: their Δv and Δa are ±0, so circle_contact either returns none before the
    /// solver (out of reach; or touching, with a rate and a curvature of ±0, neither
    /// approaching nor pushing) or builds the quartic {|Δp|² − D², ±0, ±0, ±0, ±0}, a constant
    /// (degree 0), for which first_downward_crossing returns none; so their pair is not tried.
    std::uint32_t still_ = 0;
    std::array<Candidate, kMaxBalls> own_{};
    std::array<Disc, kMaxBalls> disc_{};  ///< per ball, set by predict_candidates
    /// Per ball k, the first of own_[k] and every pair of k (kept by predict_for).
    std::array<Candidate, kMaxBalls> first_{};
    const Candidate none_{};  ///< no candidate (time ∞): where earliest starts
    /// Per ball k, the other ball of first_[k] where that is a pair of k, else k.
    std::array<std::size_t, kMaxBalls> first_with_{};
    /// Per ball i, a bit for each other ball k whose first is its pair with i (first_with_[k]
    /// == i).
    std::array<std::uint32_t, kMaxBalls> firsts_on_{};
    static constexpr int kJamContacts = 16;
    double jam_time_ = -1.0;
    std::array<int, kMaxBalls> jam_count_{};
    /// Per pair, both ways round (pair_time_[i][j] == pair_time_[j][i], so a ball's pairs are
    /// one row): the predicted contact time (∞: none, and always on the diagonal) and whether
    /// it is a push.
    std::array<std::array<double, kMaxBalls>, kMaxBalls> pair_time_ = all_pairs(kInf);
    std::array<std::array<bool, kMaxBalls>, kMaxBalls> pair_pushing_{};
    /// Per ball, a bit for each other ball it has a predicted contact with (pair_time_ < ∞).
    std::array<std::uint32_t, kMaxBalls> paired_{};
};

}  // namespace

Shot simulate(const Table& table, const Params& params, std::span<const BallState> balls,
              const Stroke* stroke, const SimOptions& options) {
    Simulation sim(table, params, balls, options);
    if (stroke) sim.strike(*stroke);
    while (sim.step()) {
    }
    return std::move(sim).finish();
}

}  // namespace physics
