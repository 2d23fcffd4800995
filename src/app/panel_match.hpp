// The panel's parts for snooker and three-cushion: the rule options in the New Game dialog,
// the scoreboard, the nomination, the after-foul choice and Next frame / Next game.
#pragma once

#include "app/controller.hpp"
#include "app/panel.hpp"

namespace app {

/// The game radio buttons of the New Game dialog (8-ball, 9-ball, snooker, three-cushion).
void table_game_choice(NewGame& d, PanelState& st);
/// Snooker: the miss rule, best of N frames; three-cushion: points to win, equal innings.
void match_rules_editor(NewGame& d, PanelState& st);
/// "Snooker  frame 2" / "Three-cushion  game 1" under the title.
void match_title(const Controller& c);
/// Snooker: both scores, the break, points remaining, snookers required, frames won;
/// three-cushion: points, innings, average, high run, the run.
void scoreboard(const Controller& c);
/// The after-foul buttons, Next frame / Next game.
void match_choices(const Controller& c, PanelState& st, PanelActions& out);
/// Snooker: the nomination (proposed from the aim, or picked).
void nomination_controls(const Controller& c, PanelState& st, PanelActions& out);

}  // namespace app
