#include "app/panel.hpp"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>

#include "app/panel_match.hpp"
#include "app/panel_widgets.hpp"
#include "app/plain_words.hpp"
#include "app/seats.hpp"

namespace app {

namespace {

const ImVec4 accent = panel_accent;
const ImVec4 warning = panel_warning;

// The cue ball seen from the shooter, with a dot where the tip will hit; click or drag on it
// to move the dot. Returns the new (side, top) when changed.
std::optional<std::pair<double, double>> spin_picker(double side, double top, bool enabled) {
    const float size = px(96.0f);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 centre{origin.x + size / 2, origin.y + size / 2};
    const float r = size / 2 - px(4.0f);
    ImGui::InvisibleButton("##spin", ImVec2(size, size));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddCircleFilled(centre, r, IM_COL32(238, 236, 226, 255), 48);
    dl->AddCircle(centre, r, IM_COL32(120, 120, 120, 255), 48, 1.5f);
    dl->AddCircle(centre, r * 0.5f, IM_COL32(200, 60, 60, 90), 48, 1.0f);  // the miscue limit
    dl->AddLine({centre.x - r, centre.y}, {centre.x + r, centre.y}, IM_COL32(0, 0, 0, 40));
    dl->AddLine({centre.x, centre.y - r}, {centre.x, centre.y + r}, IM_COL32(0, 0, 0, 40));
    const ImVec2 dot{centre.x + static_cast<float>(side) * r,
                     centre.y - static_cast<float>(top) * r};
    dl->AddCircleFilled(dot, px(5.0f), IM_COL32(30, 80, 200, 255), 16);
    if (enabled && ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        double s = (m.x - centre.x) / r, t = -(m.y - centre.y) / r;
        const double len = std::hypot(s, t);
        const double limit = 0.5;  // physics miscue_limit: beyond it the tip slips
        if (len > limit) {
            s *= limit / len;
            t *= limit / len;
        }
        s = std::round(s * 100.0) / 100.0;
        t = std::round(t * 100.0) / 100.0;
        if (s != side || t != top) return std::pair{s, t};
    }
    return std::nullopt;
}

// The game whose table and balls practice is at, for the title line.
const char* practice_title(physics::RackType game) {
    switch (game) {
        case physics::RackType::eight_ball:
            return "8-ball";
        case physics::RackType::nine_ball:
            return "9-ball";
        case physics::RackType::snooker:
            return "Snooker";
        case physics::RackType::three_cushion:
            return "Three-cushion";
    }
    return "";
}

// "Aim guide: [level]"; returns the level picked, when one was.
std::optional<AimGuide> aim_guide_combo(PanelState& st, AimGuide now) {
    std::optional<AimGuide> picked;
    ImGui::Text("Aim guide");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    const bool open = ImGui::BeginCombo("##aim_guide", aim_guide_words(now));
    remember(st, "Aim guide level");
    if (open) {
        for (AimGuide g : {AimGuide::off, AimGuide::ghost, AimGuide::lines, AimGuide::practice}) {
            if (ImGui::Selectable(aim_guide_words(g), g == now)) picked = g;
            remember(st, aim_guide_words(g));
        }
        ImGui::EndCombo();
    }
    return picked;
}

// The New Game dialog opens with the current settings as its draft.
void open_new_game(PanelState& st, const Settings& settings) {
    // The table game and its options stay as last chosen; the rest comes from the settings.
    st.draft.game = settings.game;
    st.draft.names = settings.names;
    st.draft.players = settings.players;
    st.draft.house_rules = settings.house_rules;
    st.draft.aim_guide = settings.aim_guide;
    st.draft.practice = false;
    st.new_game_open = true;
}

// One row of the New Game dialog: the seat's name and who plays it.
void seat_row(NewGame& d, std::size_t seat, const std::vector<std::string>& kinds) {
    ImGui::PushID(static_cast<int>(seat));
    char buf[41];
    std::snprintf(buf, sizeof buf, "%s", d.names[seat].c_str());
    ImGui::SetNextItemWidth(px(150));
    if (ImGui::InputText("##name", buf, sizeof buf) && buf[0] != '\0') d.names[seat] = buf;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(px(180));
    const std::string& current = d.players[seat];
    if (ImGui::BeginCombo("##kind", seat_words(current).c_str())) {
        for (const std::string& k : kinds) {
            if (ImGui::Selectable(seat_words(k).c_str(), k == current)) d.players[seat] = k;
        }
        ImGui::EndCombo();
    }
    ImGui::PopID();
}

void house_rules_editor(rules::Options& o) {
    int calls = static_cast<int>(o.call_shots);
    ImGui::Text("Calling:");
    ImGui::RadioButton("every shot", &calls, 0);
    ImGui::SameLine();
    ImGui::RadioButton("the 8 only", &calls, 1);
    ImGui::SameLine();
    ImGui::RadioButton("none", &calls, 2);
    o.call_shots = static_cast<rules::CallShots>(calls);
    bool wins = o.eight_on_break == rules::EightOnBreak::wins;
    ImGui::Checkbox("8 on the break wins", &wins);
    o.eight_on_break = wins ? rules::EightOnBreak::wins : rules::EightOnBreak::spot_or_rebreak;
    bool kitchen = o.foul_ball_in_hand == rules::FoulBallInHand::kitchen;
    ImGui::Checkbox("Ball in hand after a foul: kitchen only", &kitchen);
    o.foul_ball_in_hand =
        kitchen ? rules::FoulBallInHand::kitchen : rules::FoulBallInHand::anywhere;
    ImGui::Checkbox("Scratch on the 8 loses", &o.scratch_on_eight_loses);
    ImGui::Checkbox("Groups decided on the break", &o.groups_on_break);
    ImGui::Checkbox("Rail after contact required", &o.rail_after_contact);
}

void new_game_dialog(PanelState& st, PanelActions& out) {
    if (st.new_game_open) {
        ImGui::OpenPopup("New Game");
        st.new_game_open = false;
    }
    ImGui::SetNextWindowSize(ImVec2(px(400), 0), ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal("New Game", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    NewGame& d = st.draft;
    table_game_choice(d, st);
    const bool pool = d.table == TableGame::pool;
    ImGui::Checkbox("Practice (one player, no rules)", &d.practice);
    remember(st, "Practice (one player, no rules)");
    std::vector<std::string> kinds{"human", "random"};
    for (int level = 1; level <= 5; ++level) kinds.push_back(fmt::format("ai:{}", level));
    if (!d.practice)
        for (std::size_t seat = 0; seat < 2; ++seat) seat_row(d, seat, kinds);
    if (auto g = aim_guide_combo(st, d.aim_guide)) d.aim_guide = *g;
    if (!d.practice) match_rules_editor(d, st);
    if (pool && !d.practice && d.game == rules::Game::eight_ball &&
        ImGui::CollapsingHeader("House rules (8-ball)"))
        house_rules_editor(d.house_rules);
    ImGui::Separator();
    const bool start = ImGui::Button("Start", ImVec2(px(120), 0));
    remember(st, "Start");
    if (start) {
        out.new_game = d;
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(px(120), 0))) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

// "Replay" over the table's top-left corner while the last shot is shown again.
void replay_label(const Controller& c) {
    if (!c.replaying()) return;
    const char* text = "REPLAY";
    ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize() * 1.6f;
    const ImVec2 at{px(16.0f), px(12.0f)};
    const ImVec2 extent = font->CalcTextSizeA(size, 1e9f, 0.0f, text);
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    dl->AddRectFilled({at.x - px(8), at.y - px(4)},
                      {at.x + extent.x + px(8), at.y + extent.y + px(4)}, IM_COL32(0, 0, 0, 150),
                      px(4));
    dl->AddText(font, size, at, IM_COL32(242, 204, 90, 255), text);
}

// The title line and any notice (e.g. a saved game set aside), dismissed with OK.
void header(const Controller& c, PanelState& st) {
    const game::Session& s = c.session();
    ImGui::TextColored(accent, "COOLAABER");
    ImGui::SameLine();
    if (c.snooker() || c.carom())
        match_title(c);
    else if (const game::Practice* p = c.practice())
        ImGui::TextDisabled("%s  practice", practice_title(p->game()));
    else
        ImGui::TextDisabled("%s  game %d",
                            s.config().game == rules::Game::eight_ball ? "8-ball" : "9-ball",
                            s.game_number() + 1);
    if (!st.notice.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        if (st.notice_is_error)
            ImGui::TextColored(warning, "%s", st.notice.c_str());
        else
            ImGui::TextUnformatted(st.notice.c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::SmallButton("OK")) st.notice.clear();
    }
    ImGui::Separator();
}

// The Power slider: its label above it, or (`one_row`) beside it.
void power_slider(const Controller& c, PanelActions& out, bool one_row) {
    float power = static_cast<float>(c.aim().power * 100.0);
    if (one_row) ImGui::AlignTextToFramePadding();
    ImGui::Text("Power");
    if (one_row) ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##power", &power, 0.0f, 100.0f, "%.0f %%")) out.power = power / 100.0;
}

void sound_box(const Settings& settings, PanelState& st, PanelActions& out) {
    bool sound = settings.sound;
    if (ImGui::Checkbox("Sound", &sound)) out.sound = sound;
    remember(st, "Sound");
}

void restart_and_exit(const Controller& c, PanelState& st, PanelActions& out) {
    const game::Session& s = c.session();
    const auto [restart, exit] = button_pair(st, "Restart", "Exit");
    if (restart) {
        const bool match = c.snooker() || c.carom();  // a match is never restarted unasked
        if (!match && (s.history().empty() || s.phase() == game::Phase::game_over))
            out.restart = true;
        else
            st.confirm_restart = true;
    }
    if (exit) out.exit = true;
}

// The original game's controls: Power, Sound, Change View, Restart, Exit.
void original_controls(const Controller& c, const Settings& settings, PanelState& st,
                       PanelActions& out) {
    power_slider(c, out, false);
    sound_box(settings, st, out);
    if (full_button(st, "Change View")) out.change_view = true;
    restart_and_exit(c, st, out);
}

// The information bar: whose turn, the groups, the last shot in words; and any pending choice.
void information_bar(const Controller& c, PanelState& st, PanelActions& out) {
    ImGui::Separator();
    ImGui::PushTextWrapPos(0.0f);
    const std::vector<std::string> lines = c.info();
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (i == 0)
            ImGui::TextColored(accent, "%s", lines[i].c_str());
        else
            ImGui::TextUnformatted(lines[i].c_str());
    }
    if (c.computer_thinking()) ImGui::TextDisabled("(thinking...)");
    if (!c.last_shot_words().empty()) ImGui::TextDisabled("%s", c.last_shot_words().c_str());
    if (!c.aim_foul().empty()) ImGui::TextColored(warning, "%s", c.aim_foul().c_str());
    if (!c.refusal().empty()) ImGui::TextColored(warning, "%s", c.refusal().c_str());
    if (!st.link_note.empty() && st.link_note_serial == c.shot_serial()) {
        if (st.link_note_is_error)
            ImGui::TextColored(warning, "%s", st.link_note.c_str());
        else
            ImGui::TextUnformatted(st.link_note.c_str());
    }
    ImGui::PopTextWrapPos();
    if (c.practicing() && !c.busy()) {
        ImGui::BeginDisabled(!c.practice()->can_try_again());
        if (full_button(st, "Try again")) out.try_again = true;
        ImGui::EndDisabled();
        const auto [save, load] = button_pair(st, "Save position", "Load position");
        out.save_position = save;
        out.load_position = load;
    }
    match_choices(c, st, out);
    if (std::optional<rules::Choice> choice = c.session().choice(); choice && c.human_to_act())
        for (rules::ChoiceOption o : choice->options)
            if (full_button(st, choice_words(o).c_str())) out.choice = o;
}

// Spin, elevation, push-out and the calls: what the next stroke will be.
void stroke_controls(const Controller& c, PanelState& st, PanelActions& out) {
    const game::Session& s = c.session();
    const bool mine = c.human_to_act();
    // Practice: no push-out, no calls; snooker nominates instead, three-cushion calls nothing.
    const bool with_rules = !c.practicing() && !c.snooker() && !c.carom();
    nomination_controls(c, st, out);
    ImGui::Separator();
    ImGui::Text("Tip (spin)");
    if (auto spin = spin_picker(c.aim().side, c.aim().top, mine)) out.spin = spin;
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::Text("side %+.2f", c.aim().side);
    ImGui::Text("top  %+.2f", c.aim().top);
    if (ImGui::SmallButton("Centre")) out.spin = std::pair{0.0, 0.0};
    ImGui::EndGroup();
    float elevation = static_cast<float>(c.aim().elevation_deg);
    ImGui::Text("Cue elevation");
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##elevation", &elevation, 0.0f, 60.0f, "%.0f deg"))
        out.elevation_deg = elevation;
    // The stroke is played at the elevation in use: the rail's where it lifts the cue.
    // Always one line, so that the panel does not jump as the aim turns.
    if (const double forced = c.forced_elevation_deg(); forced > c.aim().elevation_deg)
        ImGui::TextWrapped("In use: %.1f deg (the rail lifts the cue)", forced);
    else
        ImGui::TextDisabled("In use: as set");
    if (with_rules && s.push_out_available() && mine) {
        bool push = s.state().shot == rules::Shot::push_out;
        if (ImGui::Checkbox("Push-out", &push)) out.push_out = push;
    }
    if (with_rules && s.config().game == rules::Game::eight_ball &&
        s.state().shot != rules::Shot::break_shot && mine && s.phase() == game::Phase::shoot) {
        if (ImGui::Button("Call safety")) out.call_safety = true;
        if (c.call_is_manual()) {
            ImGui::SameLine();
            if (ImGui::Button("Call from aim")) out.clear_call = true;
        }
    }
}

// The height of `rows` rows of buttons kept at the panel's foot.
float footer_height(int rows) {
    return static_cast<float>(rows) * ImGui::GetFrameHeightWithSpacing() +
           ImGui::GetStyle().ItemSpacing.y;
}

// Strike and Hint when the human may strike, else an empty row (the buttons below stay put).
void strike_and_hint(const Controller& c, PanelState& st, PanelActions& out) {
    const bool choosing = c.snooker() && c.snooker()->phase() == game::MatchPhase::choose;
    const bool shoot = c.human_to_act() && c.session().phase() == game::Phase::shoot && !choosing;
    if (shoot && c.hint_available()) {
        const auto [strike, hint] = button_pair(st, "Strike", "Hint");
        out.strike = strike;
        out.hint = hint;
    } else if (shoot) {
        out.strike = full_button(st, "Strike");  // no Hint where no player knows the table
    } else {
        ImGui::Dummy(ImVec2(0.0f, ImGui::GetFrameHeight()));
    }
}

// Skip while the balls move, Replay after a shot, else room for them; `width` wide.
void skip_or_replay(const Controller& c, PanelState& st, PanelActions& out, float width) {
    if (c.moving()) {
        if (ImGui::Button("Skip", ImVec2(width, 0.0f))) out.skip = true;
        remember(st, "Skip");
    } else if (c.playback().has_shot() && !c.busy()) {
        if (ImGui::Button("Replay", ImVec2(width, 0.0f))) out.replay = true;
        remember(st, "Replay");
    } else {
        ImGui::Dummy(ImVec2(width, ImGui::GetFrameHeight()));
    }
}

void copy_link_button(const Controller& c, PanelState& st, PanelActions& out, float width) {
    // Practice off the pool tables has no rules' position to share (shot_sharing.hpp).
    ImGui::BeginDisabled(c.practicing() && c.look() != render::GameLook::pool);
    if (ImGui::Button("Copy shot link", ImVec2(width, 0.0f))) out.copy_link = true;
    ImGui::EndDisabled();
    remember(st, "Copy shot link");
}

void new_game_and_controls(const Settings& settings, PanelState& st) {
    const auto [new_game, controls] = button_pair(st, "New Game...", "Controls");
    if (new_game) open_new_game(st, settings);
    if (controls) st.controls_open = true;
}

// Aim guide, Strike and Hint, Skip or Replay, New Game and Controls: one row each, always in
// view at the panel's foot.
void play_buttons(const Controller& c, const Settings& settings, PanelState& st,
                  PanelActions& out) {
    ImGui::Separator();
    if (auto g = aim_guide_combo(st, settings.aim_guide)) out.aim_guide = g;
    strike_and_hint(c, st, out);
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) / 2;
    skip_or_replay(c, st, out, half);
    ImGui::SameLine();
    copy_link_button(c, st, out, half);
    new_game_and_controls(settings, st);
}

// The mouse and the keys, in a window of their own so that they never push the buttons away.
void controls_dialog(PanelState& st) {
    if (st.controls_open) {
        ImGui::OpenPopup("Controls");
        st.controls_open = false;
    }
    if (!ImGui::BeginPopupModal("Controls", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    for (const char* line :
         {"Right-drag: aim; release: strike", "Left-drag: aim (or move the ball in hand)",
          "Shift while aiming: finer", "Click a ball, then a pocket: call",
          "Arrows: aim (Shift finer) and power", "Space: strike", "S or Enter: skip the shot",
          "P: replay it", "H: hint", "Ctrl+V: open a shot link", "G: aim guide level",
          "V: change view, O: free view", "Wheel: zoom", "R: restart, Esc: menu, F11: fullscreen"})
        ImGui::TextUnformatted(line);
    const bool close = ImGui::Button("Close", ImVec2(-1.0f, 0.0f));
    remember(st, "Close");
    if (close) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

void restart_dialog(PanelState& st, PanelActions& out) {
    if (st.confirm_restart) {
        ImGui::OpenPopup("Restart?");
        st.confirm_restart = false;
    }
    if (!ImGui::BeginPopupModal("Restart?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::Text("Abandon this game and rack again?");
    const bool yes = ImGui::Button("Yes, restart", ImVec2(px(130), 0));
    remember(st, "Yes, restart");
    if (yes) {
        out.restart = true;
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("No", ImVec2(px(130), 0))) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

// The Esc menu.
void menu_dialog(const Settings& settings, PanelState& st, PanelActions& out) {
    if (st.menu) {
        ImGui::OpenPopup("Menu");
        st.menu = false;
    }
    if (!ImGui::BeginPopupModal("Menu", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (ImGui::Button("Resume", ImVec2(px(200), 0))) ImGui::CloseCurrentPopup();
    if (ImGui::Button("New Game...", ImVec2(px(200), 0))) {
        open_new_game(st, settings);
        ImGui::CloseCurrentPopup();
    }
    if (ImGui::Button("Restart", ImVec2(px(200), 0))) {
        st.confirm_restart = true;
        ImGui::CloseCurrentPopup();
    }
    if (ImGui::Button("Save and exit", ImVec2(px(200), 0))) {
        out.exit = true;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

// A finger drags the scrolling part of the panel (ImGui scrolls by the wheel and the bar only).
void drag_to_scroll() {
    // A press on no control makes the window itself active (ImGui's move, refused: NoMove).
    const ImGuiID active = ImGui::GetActiveID();
    if (ImGui::IsWindowHovered() && (active == 0 || active == ImGui::GetCurrentWindow()->MoveId) &&
        ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f))
        ImGui::SetScrollY(ImGui::GetScrollY() - ImGui::GetIO().MouseDelta.y);
}

// At the right of the table: the original controls on top, the play buttons at the foot, the
// information bar and the stroke's controls scrolling between them.
void panel_at_the_right(const Controller& c, const Settings& settings, PanelState& st,
                        PanelActions& out) {
    original_controls(c, settings, st, out);
    ImGui::BeginChild("##middle", ImVec2(0.0f, -footer_height(4)));
    drag_to_scroll();
    information_bar(c, st, out);
    stroke_controls(c, st, out);
    ImGui::EndChild();
    play_buttons(c, settings, st, out);
}

// Under the table (a tall window): the information bar first, where the eye leaves the table,
// then the stroke's and the game's controls scrolling; Power, Strike, Hint, Change View and
// Skip or Replay at the foot, under the thumb.
void panel_below(const Controller& c, const Settings& settings, PanelState& st, PanelActions& out) {
    // The foot's controls are twice as padded: a thumb's target, about 40 px tall on a phone.
    const ImVec2 pad = ImGui::GetStyle().FramePadding;
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(pad.x, 2.0f * pad.y));
    const float foot = footer_height(3);
    ImGui::PopStyleVar();
    ImGui::BeginChild("##middle", ImVec2(0.0f, -foot));
    drag_to_scroll();
    information_bar(c, st, out);
    stroke_controls(c, st, out);
    ImGui::Separator();
    if (auto g = aim_guide_combo(st, settings.aim_guide)) out.aim_guide = g;
    sound_box(settings, st, out);
    copy_link_button(c, st, out, -1.0f);
    restart_and_exit(c, st, out);
    new_game_and_controls(settings, st);
    ImGui::EndChild();
    ImGui::Separator();
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(pad.x, 2.0f * pad.y));
    power_slider(c, out, true);
    strike_and_hint(c, st, out);
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) / 2;
    if (ImGui::Button("Change View", ImVec2(half, 0.0f))) out.change_view = true;
    remember(st, "Change View");
    ImGui::SameLine();
    skip_or_replay(c, st, out, half);
    ImGui::PopStyleVar();
}

}  // namespace

PanelActions draw_panel(const Controller& c, const Settings& settings, PanelState& st, float width,
                        float height, const PanelLayout& layout) {
    PanelActions out;
    st.widgets.clear();
    const bool below = layout.place == PanelPlace::below;
    ImGui::SetNextWindowPos(below ? ImVec2(0, height - layout.height)
                                  : ImVec2(width - layout.width, 0));
    ImGui::SetNextWindowSize(ImVec2(layout.width, below ? layout.height : height));
    ImGui::Begin("Coolaaber", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                     ImGuiWindowFlags_NoScrollWithMouse);
    header(c, st);
    scoreboard(c);
    if (below)
        panel_below(c, settings, st, out);
    else
        panel_at_the_right(c, settings, st, out);
    new_game_dialog(st, out);
    restart_dialog(st, out);
    menu_dialog(settings, st, out);
    controls_dialog(st);
    replay_label(c);
    ImGui::End();
    return out;
}

}  // namespace app
