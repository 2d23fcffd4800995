#include "app/shot_sharing.hpp"

#include <fmt/format.h>

#include "app/controller.hpp"

namespace app {

namespace {

game::SharedShot shared(const game::Config& c, rules::GameState state, physics::Stroke stroke) {
    return {c.game, c.options, c.table, c.params, std::move(state), stroke};
}

ShotToShare none(bool cue_ball_in_hand) {
    return {std::nullopt, cue_ball_in_hand
                              ? "Place the cue ball first: a shot link needs it on the table."
                              : "There is no shot to share yet."};
}

/// Before a frame's first stroke: the match now, nominated as the stroke would be.
ShotToShare snooker_as_aimed(const Controller& c, const physics::Stroke& aimed) {
    const game::SnookerSession& now = *c.snooker();
    if (now.phase() != game::MatchPhase::shoot)
        return none(now.phase() == game::MatchPhase::place_cue_ball);
    game::SnookerSession before = now;
    if (before.may_nominate()) before.nominate(c.nomination());
    return {game::SharedSnookerShot{std::move(before), aimed}, {}};
}

ShotToShare carom_as_aimed(const game::CaromSession& now, const physics::Stroke& aimed) {
    if (now.phase() != game::MatchPhase::shoot)
        return none(now.phase() == game::MatchPhase::place_cue_ball);
    return {game::SharedCaromShot{now, aimed}, {}};
}

std::size_t balls_in(const game::AnyShot& shot) {
    struct Count {
        std::size_t operator()(const game::SharedShot& s) const { return s.state.positions.size(); }
        std::size_t operator()(const game::SharedSnookerShot& s) const {
            return s.before.state().positions.size();
        }
        std::size_t operator()(const game::SharedCaromShot& s) const {
            return s.before.state().positions.size();
        }
    };
    return std::visit(Count{}, shot);
}

}  // namespace

ShotToShare shot_to_share(const game::Session& session, const physics::Stroke& aimed) {
    const game::Config& c = session.config();
    if (!session.history().empty()) {
        const game::ShotRecord& last = session.history().back();
        return {shared(c, last.before, last.stroke), {}, true};
    }
    if (session.phase() != game::Phase::shoot)
        return none(session.phase() == game::Phase::place_cue_ball);
    return {shared(c, session.state(), aimed), {}};
}

ShotToShare shot_to_share(const Controller& c) {
    const physics::Stroke aimed = c.stroke_of(c.aim());
    if (c.practicing() && c.look() != render::GameLook::pool)
        return {std::nullopt,
                "Practice on this table has no shot links: a link holds a pool position or a "
                "snooker or three-cushion match."};
    if (c.last_match_shot()) return {*c.last_match_shot(), {}, true};
    if (c.snooker()) return snooker_as_aimed(c, aimed);
    if (c.carom()) return carom_as_aimed(*c.carom(), aimed);
    return shot_to_share(c.session(), aimed);
}

game::Session session_of(const game::SharedShot& shot, const std::array<std::string, 2>& names,
                         std::uint64_t seed) {
    game::Config c;
    c.game = shot.game;
    c.options = shot.options;
    c.table = shot.table;
    c.params = shot.params;
    c.names = names;
    c.seed = seed;
    return game::Session::at_position(std::move(c), shot.state);
}

void open_shot(Controller& controller, game::AnyShot shot, const std::array<std::string, 2>& names,
               const ControllerOptions& options) {
    if (auto* pool = std::get_if<game::SharedShot>(&shot)) {
        controller.replace(session_of(*pool, names, options.seed), options);
        return controller.play_shared(pool->stroke);
    }
    if (auto* snooker = std::get_if<game::SharedSnookerShot>(&shot)) {
        controller.start_snooker(std::move(snooker->before), options);
        return controller.play_shared(snooker->stroke);
    }
    auto& carom = std::get<game::SharedCaromShot>(shot);
    controller.start_carom(std::move(carom.before), options);
    controller.play_shared(carom.stroke);
}

std::string copied_notice(const ShotToShare& share) {
    return fmt::format("Copied the link of {} ({} balls) to the clipboard: paste it to share it.",
                       share.last_shot ? "the last shot" : "the shot as aimed",
                       share.shot ? balls_in(*share.shot) : 0);
}

}  // namespace app
