// Starting a snooker match, a three-cushion game or practice from the New Game dialog.
#pragma once

#include "app/controller.hpp"
#include "app/panel.hpp"

namespace app {

game::SnookerConfig snooker_config(const NewGame& d);
game::CaromConfig carom_config(const NewGame& d);
/// Replaces the controller's game by the dialog's snooker or three-cushion game (both seats
/// human). Throws std::invalid_argument for options out of range.
void start_match(Controller& c, const NewGame& d, ControllerOptions options);
/// The game whose table and balls the dialog's practice sets out.
physics::RackType practice_game(const NewGame& d);

}  // namespace app
