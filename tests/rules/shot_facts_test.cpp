// Distilling events into ShotFacts, and the foul predicates over them.
#include "rules/shot_facts.hpp"

#include "rules/fouls.hpp"
#include "scenario.hpp"

namespace rules::test {
namespace {

constexpr double head = 0.635;

TEST(ShotFacts, FirstContactIsTheCueBallsFirstCollision) {
    std::vector<Event> e{hit(3, 4), rail(0), hit(5, 0), hit(0, 6), rail(6)};
    ShotFacts f = distill(e, head);
    EXPECT_EQ(f.first_contact, 5);
    EXPECT_TRUE(f.cushion_after_contact);
}

TEST(ShotFacts, CushionsBeforeTheFirstContactDoNotCountAfterIt) {
    ShotFacts f = distill(std::vector<Event>{rail(0), rail(3), hit(0, 3)}, head);
    EXPECT_FALSE(f.cushion_after_contact);
    EXPECT_EQ(f.object_balls_to_cushion, (std::set<int>{3}));
    EXPECT_TRUE(is_no_rail_after_contact(f));
}

TEST(ShotFacts, PocketsInOrderAndTheCueBall) {
    ShotFacts f = distill(
        std::vector<Event>{hit(0, 1), pot(7, P::NE), pot(2, P::S), pot(0, P::SW), off(4)}, head);
    EXPECT_EQ(f.pocketed, (std::vector<PocketedBall>{{7, pocket(P::NE)}, {2, pocket(P::S)}}));
    EXPECT_TRUE(f.cue_pocketed);
    EXPECT_FALSE(f.cue_off_table);
    EXPECT_EQ(f.off_table, (std::vector<int>{4}));
    EXPECT_EQ(f.pocket_of(2), pocket(P::S));
    EXPECT_FALSE(f.pocket_of(4).has_value());
    EXPECT_TRUE(is_scratch(f));
    EXPECT_TRUE(is_ball_off_table(f));
    EXPECT_TRUE(f.cue_ball_lost());
}

TEST(ShotFacts, ABallLeavesTheTableOnce) {
    ShotFacts f = distill(std::vector<Event>{hit(0, 1), pot(1, P::N), pot(1, P::S), off(1)}, head);
    EXPECT_EQ(f.pocketed.size(), 1u);
    EXPECT_TRUE(f.off_table.empty());
}

TEST(ShotFacts, IgnoresStrikeTransitionAndMiscueForContacts) {
    std::vector<Event> e{event(EventType::strike, {0}), roll(0), event(EventType::miscue, {0})};
    ShotFacts f = distill(e, head);
    EXPECT_FALSE(f.first_contact.has_value());
    EXPECT_TRUE(is_no_contact(f));
    EXPECT_FALSE(is_no_rail_after_contact(f));  // no_contact stands alone
    EXPECT_FALSE(is_wrong_ball_first(f, {1}));
}

TEST(ShotFacts, CueBallLeavesTheKitchenJudgedFromEventPositions) {
    // Positions of events after the first contact do not count.
    ShotFacts late =
        distill(std::vector<Event>{at(hit(0, 3), {0.5, 0.3}), at(rail(0), {2.0, 0.1})}, head);
    EXPECT_FALSE(late.cue_left_kitchen);
    ShotFacts early =
        distill(std::vector<Event>{at(roll(0), {0.7, 0.3}), at(hit(0, 3), {0.5, 0.3})}, head);
    EXPECT_TRUE(early.cue_left_kitchen);
    ShotFacts unknown = distill(std::vector<Event>{rail(0), hit(0, 3)}, head);
    EXPECT_FALSE(unknown.cue_left_kitchen);
    // The other ball's position in a collision is not the cue ball's.
    ShotFacts other =
        distill(std::vector<Event>{at(hit(3, 0), {0.9, 0.3}, physics::Vec2{0.5, 0.3})}, head);
    EXPECT_FALSE(other.cue_left_kitchen);
}

TEST(ShotFacts, BreakRequirement) {
    EXPECT_TRUE(meets_break_requirement(distill(four_rail_break(), head)));
    EXPECT_TRUE(
        meets_break_requirement(distill(std::vector<Event>{hit(0, 1), pot(5, P::N)}, head)));
    EXPECT_FALSE(meets_break_requirement(
        distill(std::vector<Event>{hit(0, 1), rail(1), rail(2), rail(3), rail(0)}, head)));
}

TEST(FoulList, CanonicalOrderAndNoContactStandsAlone) {
    FoulList fouls;
    fouls.add_if(true, Foul::ball_off_table);
    fouls.add_if(true, Foul::scratch);
    fouls.add_if(false, Foul::cue_ball_off_table);
    fouls.add_if(true, Foul::wrong_ball_first);
    EXPECT_EQ(fouls.canonical(),
              (std::vector<Foul>{Foul::scratch, Foul::wrong_ball_first, Foul::ball_off_table}));
    fouls.add_if(true, Foul::no_contact);
    fouls.add_if(true, Foul::illegal_break);
    EXPECT_EQ(fouls.canonical(),
              (std::vector<Foul>{Foul::scratch, Foul::no_contact, Foul::ball_off_table}));
}

TEST(Names, RoundTrip) {
    for (std::string_view n : EnumNames<Foul>::names) EXPECT_EQ(name(*parse<Foul>(n)), n);
    for (std::string_view n : EnumNames<ChoiceOption>::names)
        EXPECT_EQ(name(*parse<ChoiceOption>(n)), n);
    EXPECT_EQ(name(Shot::break_shot), "break");
    EXPECT_EQ(parse<Game>("9ball"), Game::nine_ball);
    EXPECT_FALSE(parse<CallShots>("some").has_value());
}

}  // namespace
}  // namespace rules::test
