// The names of the rules' enums as they appear in documents (docs/cli.md, docs/rules.md):
// name(e) and parse<E>(text). Header-only, so save files and the CLI share one spelling.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "rules/game_state.hpp"
#include "rules/options.hpp"
#include "rules/verdict.hpp"

namespace rules {

/// Names of an enum's values, in declaration order.
template <typename E>
struct EnumNames;

template <>
struct EnumNames<Game> {
    static constexpr std::array<std::string_view, 2> names{"8ball", "9ball"};
};
template <>
struct EnumNames<Player> {
    static constexpr std::array<std::string_view, 2> names{"A", "B"};
};
template <>
struct EnumNames<Group> {
    static constexpr std::array<std::string_view, 2> names{"solids", "stripes"};
};
template <>
struct EnumNames<Shot> {
    static constexpr std::array<std::string_view, 5> names{"break", "after_break", "push_out",
                                                           "after_push_out", "normal"};
};
template <>
struct EnumNames<CueBall> {
    static constexpr std::array<std::string_view, 3> names{"on_table", "in_hand",
                                                           "in_hand_kitchen"};
};
template <>
struct EnumNames<CallShots> {
    static constexpr std::array<std::string_view, 3> names{"all", "eight_only", "none"};
};
template <>
struct EnumNames<EightOnBreak> {
    static constexpr std::array<std::string_view, 2> names{"spot_or_rebreak", "wins"};
};
template <>
struct EnumNames<FoulBallInHand> {
    static constexpr std::array<std::string_view, 2> names{"anywhere", "kitchen"};
};
template <>
struct EnumNames<Foul> {
    static constexpr std::array<std::string_view, 9> names{"scratch",
                                                           "cue_ball_off_table",
                                                           "no_contact",
                                                           "wrong_ball_first",
                                                           "no_rail_after_contact",
                                                           "ball_off_table",
                                                           "bad_play_from_kitchen",
                                                           "illegal_break",
                                                           "third_consecutive_foul"};
};
template <>
struct EnumNames<BallInHand> {
    static constexpr std::array<std::string_view, 3> names{"none", "anywhere", "kitchen"};
};
template <>
struct EnumNames<BreakResult> {
    static constexpr std::array<std::string_view, 3> names{"none", "legal", "illegal"};
};
template <>
struct EnumNames<ChoiceOption> {
    static constexpr std::array<std::string_view, 9> names{"accept_table",
                                                           "rerack_and_break",
                                                           "rerack_offender_breaks",
                                                           "spot_8_and_continue",
                                                           "rebreak",
                                                           "spot_8_with_kitchen_ball_in_hand",
                                                           "kitchen_ball_in_hand",
                                                           "shoot",
                                                           "pass_back"};
};

template <typename E>
constexpr std::string_view name(E value) {
    return EnumNames<E>::names[static_cast<std::size_t>(value)];
}

template <typename E>
constexpr std::optional<E> parse(std::string_view text) {
    for (std::size_t i = 0; i < EnumNames<E>::names.size(); ++i)
        if (EnumNames<E>::names[i] == text) return static_cast<E>(i);
    return std::nullopt;
}

}  // namespace rules
