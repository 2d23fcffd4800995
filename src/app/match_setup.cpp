#include "app/match_setup.hpp"

#include "app/seats.hpp"

namespace app {

game::SnookerConfig snooker_config(const NewGame& d) {
    game::SnookerConfig c;
    c.options = d.snooker;
    c.best_of = d.best_of;
    c.names = seat_names(d.names, d.players);
    return c;
}

game::CaromConfig carom_config(const NewGame& d) {
    game::CaromConfig c;
    c.options = d.carom;
    c.names = seat_names(d.names, d.players);
    return c;
}

void start_match(Controller& c, const NewGame& d, ControllerOptions options) {
    if (d.table == TableGame::snooker)
        c.start_snooker(game::SnookerSession(snooker_config(d)), std::move(options));
    else if (d.table == TableGame::three_cushion)
        c.start_carom(game::CaromSession(carom_config(d)), std::move(options));
}

physics::RackType practice_game(const NewGame& d) {
    switch (d.table) {
        case TableGame::snooker:
            return physics::RackType::snooker;
        case TableGame::three_cushion:
            return physics::RackType::three_cushion;
        case TableGame::pool:
            break;
    }
    return d.game == rules::Game::eight_ball ? physics::RackType::eight_ball
                                             : physics::RackType::nine_ball;
}

}  // namespace app
