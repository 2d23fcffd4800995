#include "app/panel_match.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>

#include "app/match_words.hpp"
#include "app/panel_widgets.hpp"

namespace app {

namespace {

using rules::Player;
namespace sb = physics::snooker_ball;

// One row of the scoreboard: a label, then a column per player.
void score_row(const char* label, const std::string& a, const std::string& b, bool strong = false) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("%s", label);
    for (int i = 0; i < 2; ++i) {
        ImGui::TableSetColumnIndex(i + 1);
        const std::string& v = i == 0 ? a : b;
        if (strong)
            ImGui::TextColored(panel_accent, "%s", v.c_str());
        else
            ImGui::TextUnformatted(v.c_str());
    }
}

bool begin_board(const std::array<std::string, 2>& names, std::optional<Player> at_table) {
    if (!ImGui::BeginTable("##score", 3, ImGuiTableFlags_SizingStretchSame)) return false;
    ImGui::TableNextRow();
    for (int i = 0; i < 2; ++i) {
        ImGui::TableSetColumnIndex(i + 1);
        const bool on = at_table && rules::index(*at_table) == static_cast<std::size_t>(i);
        ImGui::TextWrapped("%s%s", on ? "> " : "", names[static_cast<std::size_t>(i)].c_str());
    }
    return true;
}

void snooker_board(const game::SnookerSession& s) {
    const rules::SnookerState& st = s.state();
    if (!begin_board(s.config().names, s.frame_winner() ? std::nullopt : s.to_act())) return;
    score_row("Score", std::to_string(st.score(Player::A)), std::to_string(st.score(Player::B)),
              true);
    const bool a_at_table = st.shooter == Player::A && !s.frame_winner();
    const std::string brk = std::to_string(st.break_points);
    score_row("Break", a_at_table ? brk : "", a_at_table ? "" : brk);
    score_row("Frames", std::to_string(s.frames_won()[0]), std::to_string(s.frames_won()[1]));
    ImGui::EndTable();
    ImGui::Text("Remaining %d  ·  best of %d", s.points_remaining(), s.config().best_of);
    for (Player p : {Player::A, Player::B})
        if (const int n = snookers_required(s, p); n > 0 && !s.frame_winner())
            ImGui::TextColored(panel_warning, "%s: snookers required (%d)", s.name(p).c_str(), n);
}

void carom_board(const game::CaromSession& s) {
    const rules::CaromState& st = s.state();
    if (!begin_board(s.config().names, s.to_act())) return;
    auto pair = [](const std::array<int, 2>& v) {
        return std::pair{std::to_string(v[0]), std::to_string(v[1])};
    };
    const auto [pa, pb] = pair(st.scores);
    score_row("Points", pa, pb, true);
    const auto [ia, ib] = pair(st.innings);
    score_row("Innings", ia, ib);
    score_row("Average", fmt::format("{:.3f}", s.average(Player::A)),
              fmt::format("{:.3f}", s.average(Player::B)));
    const auto [ha, hb] = pair(st.high_run);
    score_row("High run", ha, hb);
    const auto [ga, gb] = pair(s.games_won());
    score_row("Games", ga, gb);
    ImGui::EndTable();
    ImGui::Text("Run %d  ·  game to %d%s", st.run, s.config().options.target,
                s.config().options.equal_innings ? ", equal innings" : "");
}

}  // namespace

void table_game_choice(NewGame& d, PanelState& st) {
    int game = d.table == TableGame::snooker         ? 2
               : d.table == TableGame::three_cushion ? 3
               : d.game == rules::Game::eight_ball   ? 0
                                                     : 1;
    const char* labels[] = {"8-ball", "9-ball", "Snooker", "Three-cushion"};
    for (int i = 0; i < 4; ++i) {
        if (i > 0) ImGui::SameLine();
        ImGui::RadioButton(labels[i], &game, i);
        remember(st, labels[i]);
    }
    d.table = game == 2   ? TableGame::snooker
              : game == 3 ? TableGame::three_cushion
                          : TableGame::pool;
    if (game < 2) d.game = game == 0 ? rules::Game::eight_ball : rules::Game::nine_ball;
}

void match_rules_editor(NewGame& d, PanelState& st) {
    if (d.table == TableGame::snooker) {
        ImGui::Checkbox("Miss rule (off: a casual game)", &d.snooker.miss_rule);
        remember(st, "Miss rule");
        ImGui::SetNextItemWidth(px(120));
        if (ImGui::InputInt("Best of (frames)", &d.best_of, 2)) {
            d.best_of = std::clamp(d.best_of, 1, 35);
            if (d.best_of % 2 == 0) ++d.best_of;
        }
        remember(st, "Best of");
    } else if (d.table == TableGame::three_cushion) {
        ImGui::SetNextItemWidth(px(120));
        if (ImGui::InputInt("Points to win", &d.carom.target, 5))
            d.carom.target = std::clamp(d.carom.target, 1, 1000);
        remember(st, "Points to win");
        ImGui::Checkbox("Equal innings", &d.carom.equal_innings);
        remember(st, "Equal innings");
    }
}

void match_title(const Controller& c) {
    if (const game::SnookerSession* s = c.snooker())
        ImGui::TextDisabled("Snooker  frame %d", s->frame_number() + 1);
    if (const game::CaromSession* g = c.carom())
        ImGui::TextDisabled("Three-cushion  game %d", g->game_number() + 1);
}

void scoreboard(const Controller& c) {
    if (const game::SnookerSession* s = c.snooker()) snooker_board(*s);
    if (const game::CaromSession* g = c.carom()) carom_board(*g);
}

void match_choices(const Controller& c, PanelState& st, PanelActions& out) {
    if (c.busy()) return;
    if (const game::SnookerSession* s = c.snooker()) {
        if (s->phase() == game::MatchPhase::choose && c.human_to_act()) {
            const std::string offender = s->name(s->before().shooter);
            for (rules::AfterFoul a : s->choices()) {
                const std::string label =
                    a == rules::AfterFoul::play         ? std::string("Play from here")
                    : a == rules::AfterFoul::play_again ? "Ask " + offender + " to play again"
                                                        : "Replace the balls for " + offender;
                if (full_button(st, label.c_str())) out.after_foul = a;
            }
        }
        if (s->phase() == game::MatchPhase::frame_over && full_button(st, "Next frame"))
            out.next_frame = true;
    }
    if (const game::CaromSession* g = c.carom(); g && g->game_over())
        if (full_button(st, "Next game")) out.next_frame = true;
}

void nomination_controls(const Controller& c, PanelState& st, PanelActions& out) {
    const game::SnookerSession* s = c.snooker();
    if (!s || !s->may_nominate() || !c.human_to_act() || s->phase() != game::MatchPhase::shoot)
        return;
    const std::optional<int> nom = c.nomination();
    const std::string now = nom ? game::snooker_ball_name(*nom) : "(from the aim)";
    ImGui::Text(s->state().free_ball ? "Free ball" : "Nominate");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(px(120));
    const bool open = ImGui::BeginCombo("##nominate", now.c_str());
    remember(st, "Nominate");
    if (open) {
        for (int id : s->state().on_table) {
            if (s->state().colour_on ? !physics::is_colour(id)
                                     : physics::is_red(id) && id != *s->state().on_table.begin())
                continue;  // one "red" entry is enough for a free ball
            const std::string name = game::snooker_ball_name(id);
            if (ImGui::Selectable(name.c_str(), nom == id)) out.nominate = std::optional<int>(id);
            remember(st, "nominate " + name);
        }
        ImGui::EndCombo();
    }
    if (c.nomination_is_manual()) {
        ImGui::SameLine();
        if (ImGui::SmallButton("From aim")) out.nominate = std::optional<int>();
    }
}

}  // namespace app
