#include "app/shot_sharing.hpp"

#include <fmt/format.h>

namespace app {

namespace {

game::SharedShot shared(const game::Config& c, rules::GameState state, physics::Stroke stroke) {
    return {c.game, c.options, c.table, c.params, std::move(state), stroke};
}

}  // namespace

ShotToShare shot_to_share(const game::Session& session, const physics::Stroke& aimed) {
    const game::Config& c = session.config();
    if (!session.history().empty()) {
        const game::ShotRecord& last = session.history().back();
        return {shared(c, last.before, last.stroke), {}};
    }
    if (session.phase() != game::Phase::shoot)
        return {std::nullopt, session.phase() == game::Phase::place_cue_ball
                                  ? "Place the cue ball first: a shot link needs it on the table."
                                  : "There is no shot to share yet."};
    return {shared(c, session.state(), aimed), {}};
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

std::string copied_notice(const game::SharedShot& shot, bool last_shot) {
    return fmt::format("Copied the link of {} ({} balls) to the clipboard: paste it to share it.",
                       last_shot ? "the last shot" : "the shot as aimed",
                       shot.state.positions.size());
}

}  // namespace app
