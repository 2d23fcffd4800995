// The shot pipeline (docs/physics.md): take the earliest predicted event, resolve it (advance
// the balls it involves to it and apply the collision or transition), record it, and
// re-predict only what it changed. Between events every ball follows its closed form, so
// nothing is stepped and nothing tunnels.
#include "physics/simulate.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "physics/cue_strike.hpp"
#include "physics/energy.hpp"
#include "physics/internal/candidate_queue.hpp"
#include "physics/internal/collide.hpp"
#include "physics/internal/detect.hpp"
#include "physics/internal/motion.hpp"

namespace physics {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::size_t kMaxBalls = CandidateQueue::kMaxBalls;
using Kind = CandidateKind;

/// A pocket's jaw faces and noses (bits of Table::lines, Table::noses) and a circle about the
/// pocket's centre that holds them all. A face or nose reports a contact only where the ball's
/// centre comes within R (up to ~1e-6 m: the touching tolerance, rounding) of it, at a point
/// no farther from the centre now than the reach; so a ball farther than radius + R + reach
/// (+ 1e-5 m) from the group's centre gets none from any of them, and they are skipped.
struct FaceGroup {
    Vec2 centre{};
    double radius = 0.0;
    std::uint64_t lines = 0, noses = 0;
};

/// The face groups of a table, and the faces and noses of no pocket (the rails), which are
/// always tried. Tables with more than 64 faces or noses are not grouped: all are tried.
struct FaceGroups {
    bool grouped = false;
    std::vector<FaceGroup> groups;
    std::uint64_t lines_always = 0, noses_always = 0;

    explicit FaceGroups(const Table& table);
};

FaceGroups::FaceGroups(const Table& table) {
    const std::size_t nl = table.lines.size(), nn = table.noses.size();
    if (nl > 64 || nn > 64) return;
    grouped = true;
    groups.assign(table.pockets.size(), FaceGroup{});
    for (std::size_t k = 0; k < groups.size(); ++k) groups[k].centre = table.pockets[k].centre;
    auto grow = [](FaceGroup& fg, Vec2 at, double extent) {
        const double r = (norm(at - fg.centre) + extent) * (1.0 + 1e-9) + 1e-9;
        if (r > fg.radius) fg.radius = r;
    };
    auto group_of = [&](int pocket) -> FaceGroup* {
        if (pocket < 0 || static_cast<std::size_t>(pocket) >= groups.size()) return nullptr;
        return &groups[static_cast<std::size_t>(pocket)];
    };
    for (std::size_t g = 0; g < nl; ++g) {
        const CushionLine& l = table.lines[g];
        const auto bit = std::uint64_t{1} << g;
        FaceGroup* fg = group_of(l.pocket);
        if (fg == nullptr) {
            lines_always |= bit;
            continue;
        }
        // (the contact point a + along·dir, 0 ≤ along ≤ length, on the face: detect::line)
        grow(*fg, l.a + (0.5 * l.length) * l.dir, 0.5 * l.length);
        fg->lines |= bit;
    }
    for (std::size_t g = 0; g < nn; ++g) {
        const JawNose& n = table.noses[g];
        const auto bit = std::uint64_t{1} << g;
        FaceGroup* fg = group_of(n.pocket);
        if (fg == nullptr) {
            noses_always |= bit;
            continue;
        }
        grow(*fg, n.centre, n.radius);
        fg->noses |= bit;
    }
}

template <typename T, std::size_t N>
constexpr std::array<T, N> filled(T v) {
    std::array<T, N> a{};
    a.fill(v);
    return a;
}

/// A resolved event and the balls whose motion it changed (to be re-predicted).
struct Resolved {
    Event event;
    std::array<std::size_t, 2> balls{};
    std::size_t count = 1;
};

class Simulation {
    /// Per ball, for its current segment: where and when it starts, the constant acceleration
    /// and its size, the end, and the speed at the start (units: m, m/s, m/s², s, m/s).
    struct Live {
        Vec2 pos, vel, acc;
        double t0 = 0.0;
        double end = kInf;
        double speed = 0.0;
        double accel = 0.0;
        Motion motion = Motion::stationary;
    };
    /// Where ball k can be until its own next event: within `reach` of `centre`, its position
    /// when it was last predicted.
    struct Disc {
        Vec2 centre;
        double reach = 0.0;
    };

  public:
    Simulation(const Table& table, const Params& params, std::span<const BallState> balls,
               const SimOptions& options)
        : table_(table),
          params_(params),
          options_(options),
          n_(balls.size()),
          faces_(table),
          queue_(balls.size()) {
        assert(n_ <= kMaxBalls && "at most 22 balls (ids 0-21)");
        drop_lateral_.reserve(table_.pockets.size());
        for (const Pocket& pk : table_.pockets)
            drop_lateral_.push_back(0.5 * norm(pk.mouth_b - pk.mouth_a) + table_.spec.jaw_depth);
        segments_.resize(n_);
        // Room for a typical shot up front (a break of 16 balls has 141 events, its busiest
        // balls a dozen segments or so), so that few vectors grow and copy.
        events_.reserve(std::min<std::size_t>(options_.max_events, 32 + 8 * n_));
        for (auto& segs : segments_) segs.reserve(16);
        for (std::size_t i = 0; i < n_; ++i) {
            BallState s = balls[i];
            if (s.motion != Motion::pocketed) s = motion::settle(params_, s);
            segments_[i].push_back({0.0, s});
            set_live(i, s, 0.0);
        }
        // Pair (i, j > i) is predicted by predict_for(j), once ball j's own event is known.
        for (std::size_t i = 0; i < n_; ++i) predict_for(i, ~0u << i << 1);
    }

    void strike(const Stroke& stroke) {
        const std::size_t cue = index_of(stroke.ball);
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
        const Candidate next = queue_.earliest();
        if (!(next.time <= kHorizon)) {
            // With a friction of zero a ball can move forever: that shot never ends, and is
            // reported like one cut at the cap.
            truncated_ = truncated_ || any_moving();
            return false;
        }
        if (events_.size() >= options_.max_events) {
            truncated_ = true;
            return false;
        }
        now_ = next.time;
        record(resolve(next));
        return true;
    }

    Shot finish() && { return Shot(params_, std::move(events_), std::move(segments_), truncated_); }

  private:
    std::size_t index_of(int id) const {
        for (std::size_t i = 0; i < n_; ++i)
            if (segments_[i].front().start.id == id) return i;
        assert(false && "the struck ball must be in the layout");
        return 0;
    }

    bool any_moving() const {
        for (std::size_t i = 0; i < n_; ++i) {
            const Motion m = current(i).start.motion;
            if (m != Motion::stationary && m != Motion::pocketed) return true;
        }
        return false;
    }

    const Segment& current(std::size_t i) const { return segments_[i].back(); }
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
    bool rolling(std::size_t i) const { return live_[i].motion == Motion::rolling; }

    void start_segment(std::size_t i, const BallState& s) {
        segments_[i].push_back({now_, s});
        set_live(i, s, now_);
    }
    /// Sets ball i's Live entry for a segment starting at t0 in state s, and tells the queue
    /// whether the ball takes part and is still.
    void set_live(std::size_t i, const BallState& s, double t0) {
        const Live& l = live_[i] = make_live(s, t0);
        const bool still = l.vel.x == 0.0 && l.vel.y == 0.0 && l.acc.x == 0.0 && l.acc.y == 0.0 &&
                           std::isfinite(l.pos.x) && std::isfinite(l.pos.y);
        queue_.set_ball(i, s.motion != Motion::pocketed, still);
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

    // ---- predict ----

    /// Re-predicts everything that involves ball i, its own next event and its pairs, and
    /// refreshes the queue's firsts. The pairs with the balls in `later` (a bit per ball) are
    /// only cleared: the caller re-predicts those balls next, which predicts those pairs again
    /// (with their new own events).
    void predict_for(std::size_t i, std::uint32_t later = 0) {
        queue_.clear(i);
        if (queue_.active(i)) {
            queue_.set_own(i, predict_own(i));
            predict_pairs(i, later);
        }
        queue_.refresh(i);
    }

    /// Ball i's own next event: the end of its segment, then cushions, noses and drops, each
    /// searched only up to the earliest found so far (which also tightens the reach bound).
    Candidate predict_own(std::size_t i) const {
        const int ii = static_cast<int>(i);
        const double R = params_.ball_radius;
        Candidate own{live_[i].end, Kind::transition, ii, -1, false};
        detect::Mover m = detect::make_mover(kinematics(i), own.time - now_, rolling(i));
        auto consider = [&](double tau, Kind kind, int g, bool pushing) {
            Candidate c{now_ + tau, kind, ii, g, pushing};
            if (std::isinf(tau) || !c.before(own)) return;
            own = c;
            m = m.within(tau);
        };
        // (The tables' vectors as spans: through references the compiler would reload their
        // bounds at every use, since the stores in between might alias them.)
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
        if (!faces_.grouped) {
            for (std::size_t g = 0; g < faces.size(); ++g) try_line(g);
            for (std::size_t g = 0; g < jaw_noses.size(); ++g) try_nose(g);
        }
        // The faces and noses of a pocket out of the ball's reach are skipped (FaceGroup).
        std::uint64_t lines = faces_.lines_always, noses = faces_.noses_always;
        for (const FaceGroup& fg : std::span<const FaceGroup>(faces_.groups)) {
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
        return own;
    }

    /// Ball i's pairs with its partners (see CandidateQueue::partners), in increasing j. A
    /// contact after either ball's own next event need not be searched, since that event
    /// re-predicts every pair of the ball; pairs farther apart than both balls can travel by
    /// then are skipped before any polynomial is built.
    void predict_pairs(std::size_t i, std::uint32_t later) {
        const double R = params_.ball_radius;
        const motion::Kinematics ki = kinematics(i);
        const double speed_i = norm(ki.v);
        const bool rolling_i = rolling(i);
        // Ball i's values used by every pair, held here: each store below, and each call of
        // the solver, would make the compiler load them again from the members.
        const double now = now_, own_i = queue_.own(i).time, accel_i = live_[i].accel;
        // Ball i's reach up to its own next event, for the pairs that end there.
        const double reach_i_own = detect::reach_bound(speed_i, accel_i, own_i - now, rolling_i);
        disc_[i] = {ki.p, reach_i_own};
        for (std::uint32_t others = queue_.partners(i, later); others != 0; others &= others - 1) {
            const auto j = static_cast<std::size_t>(std::countr_zero(others));
            // Both discs (up to each ball's own next event, which bounds the pair's horizon)
            // more than 2R + 1e-5 m apart: the balls stay that far apart, so the contact
            // quartic is ≥ 4R·1e-5 on the whole horizon, far above its rounding (its terms are
            // below (|Δp| + 3·(reach_i + reach_j))², a few m², kept so by the 50 m cap).
            const double apart = reach_i_own + disc_[j].reach;
            const double clear = 2 * R + apart + 1e-5;
            if (apart < 50.0 && norm2(disc_[j].centre - ki.p) > clear * clear) continue;
            const double until = std::min(own_i, queue_.own(j).time);
            if (!(until >= now)) continue;
            const double h = until - now;
            // |v_j(now)| ≤ |v_j(t0)| + |a_j|·(now − t0): no square root per pair.
            const double speed_j = live_[j].speed + live_[j].accel * (now - live_[j].t0);
            const double reach_i =
                until == own_i ? reach_i_own : detect::reach_bound(speed_i, accel_i, h, rolling_i);
            // (reach_bound is at least 1e-12, never 0: no test for two balls that cannot move)
            const double reach_j = detect::reach_bound(speed_j, live_[j].accel, h, rolling(j));
            const motion::Kinematics kj = kinematics(j);
            const double limit = 2 * R + reach_i + reach_j;
            if (norm2(kj.p - ki.p) > limit * limit) continue;
            // What detect::ball_ball computes, already screened (|Δp|² ≤ limit² here).
            const detect::Prediction p = detect::detail::circle_contact(
                kj.p - ki.p, kj.v - ki.v, kj.a - ki.a, 2.0 * R, reach_i + reach_j, h, true);
            if (std::isinf(p.tau)) continue;
            queue_.set_pair(i, j, now + p.tau, p.pushing);
        }
    }

    // ---- resolve ----

    Resolved resolve(const Candidate& c) {
        const std::size_t a = static_cast<std::size_t>(c.a);
        switch (c.kind) {
            case Kind::transition:
                return resolve_transition(a);
            case Kind::ball_ball:
                return resolve_ball_ball(a, static_cast<std::size_t>(c.b), c.pushing);
            case Kind::line:
            case Kind::nose:
                return resolve_cushion(a, c);
            case Kind::drop:
                return resolve_drop(a, static_cast<std::size_t>(c.b));
        }
        return {};
    }

    Resolved resolve_transition(std::size_t a) {
        const Motion from = current(a).start.motion;
        start_segment(a, motion::transition(params_, current(a).start));
        Resolved r{make_event(EventType::transition, {a}), {a}};
        r.event.from = from;
        r.event.to = current(a).start.motion;
        return r;
    }

    Resolved resolve_ball_ball(std::size_t a, std::size_t b, bool pushing) {
        BallState sa = state_now(a), sb = state_now(b);
        const bool after_slow = now_ - slow_at_[a] < collide::kContactTime ||
                                now_ - slow_at_[b] < collide::kContactTime;
        const double speed =
            collide::ball_ball(params_, options_.models.ball_ball, sa, sb, pushing, after_slow);
        if (speed < collide::kSlowSpeed) slow_at_[a] = slow_at_[b] = now_;
        if (speed < collide::kSlowSpeed && jammed(a, b)) {
            // Resolving a slow ball wedged between others one contact at a time converges too
            // slowly (nearly opposite contacts); a jammed ball stops.
            for (BallState* st : {&sa, &sb}) {
                st->vel = {};
                st->spin.x = st->spin.y = 0.0;
                *st = motion::settle(params_, *st);
            }
        }
        start_segment(a, sa);  // collide leaves the balls settled
        start_segment(b, sb);
        Resolved r{make_event(EventType::ball_ball, {a, b}), {a, b}, 2};
        r.event.speed = speed;
        return r;
    }

    Resolved resolve_cushion(std::size_t a, const Candidate& c) {
        BallState s = state_now(a);
        Vec2 toward;
        int rail = -1, pocket = -1;
        if (c.kind == Kind::line) {
            const CushionLine& l = table_.lines[static_cast<std::size_t>(c.b)];
            toward = -1.0 * l.normal;
            rail = l.rail;
            pocket = l.pocket;
        } else {
            const JawNose& n = table_.noses[static_cast<std::size_t>(c.b)];
            toward = (1.0 / norm(n.centre - s.pos)) * (n.centre - s.pos);
            pocket = n.pocket;
        }
        const double speed = collide::cushion(params_, options_.models.cushion,
                                              table_.spec.cushion_height, toward, s, c.pushing);
        if (speed < collide::kSlowSpeed) slow_at_[a] = now_;
        start_segment(a, s);
        Resolved r{make_event(EventType::cushion, {a}), {a}};
        r.event.speed = speed;
        r.event.rail = rail;
        r.event.pocket = pocket;
        return r;
    }

    Resolved resolve_drop(std::size_t a, std::size_t pocket) {
        BallState s = state_now(a);
        s.vel = {};
        s.spin = {};
        s.motion = Motion::pocketed;
        s.pocket = table_.pockets[pocket].id;
        start_segment(a, s);
        Resolved r{make_event(EventType::pocket, {a}), {a}};
        r.event.pocket = s.pocket;
        return r;
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

    // ---- record ----

    void record(const Resolved& r) {
#ifndef NDEBUG
        audit_energy(r);
#endif
        events_.push_back(r.event);
        std::uint32_t later = 0;
        for (std::size_t k = 0; k < r.count; ++k) later |= 1u << r.balls[k];
        for (std::size_t k = 0; k < r.count; ++k)
            predict_for(r.balls[k], later &= ~(1u << r.balls[k]));
    }

    /// No event may add energy (the segments before it end at now_).
    void audit_energy(const Resolved& r) const {
        double before = 0, after = 0;
        for (std::size_t k = 0; k < r.count; ++k) {
            const auto& segs = segments_[r.balls[k]];
            const Segment& prev = segs[segs.size() - 2];
            before += kinetic_energy(params_, motion::evolve(params_, prev.start, now_ - prev.t0));
            after += kinetic_energy(params_, segs.back().start);
        }
        assert(after <= before * (1.0 + 1e-9) + 1e-12 &&
               "an event added kinetic energy: check the collision model");
        (void)before;
        (void)after;
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
    FaceGroups faces_;
    std::array<Live, kMaxBalls> live_{};
    std::array<Disc, kMaxBalls> disc_{};  ///< per ball, set by predict_pairs
    CandidateQueue queue_;
    /// Per ball, the time of its latest slow contact (collide::kSlowSpeed), for after_slow.
    std::array<double, kMaxBalls> slow_at_ = filled<double, kMaxBalls>(-kInf);
    static constexpr int kJamContacts = 16;
    double jam_time_ = -1.0;
    std::array<int, kMaxBalls> jam_count_{};
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
