// The offline tuning of the AI's break (candidates.hpp's `tuned_breaks`, docs/ai.md):
// not a test, a measurement.
//   break_tuning [--game 8ball|9ball] [--n N] [--draws D] [--seed S]
// For N seeded racks, every break of a grid (the cue ball's spot across the table, full or off
// the apex ball's centre, five cue speeds) is played with D draws of the execution noise at 1×
// and judged by the rules. Prints one JSON line per break: how many object balls it leaves with
// no clear path to any pocket (`stuck`: a cluster or a ball in the way, as table_value.hpp counts
// them), the balls pocketed, the share of fouls (mostly scratches) and of breaks that pocket the
// 8 (9).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/position.hpp"
#include "game/stroke_noise.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"
#include "rules/judge.hpp"

namespace {

struct Args {
    std::string game = "8ball";
    int n = 200;
    int draws = 4;
    std::uint64_t seed = 1;
};

struct Tally {
    ai::BreakSpec spec;
    double stuck = 0.0, down = 0.0, fouls = 0.0, key_down = 0.0, played = 0.0;
};

int stuck_objects(const ai::Position& pos, const rules::GameState& s) {
    int stuck = 0;
    for (int ball : s.on_table) {
        bool open = false;
        for (int pocket = 0; pocket < 6 && !open; ++pocket)
            open = ai::object_path(pos.table, pos.params.ball_radius, ball, pocket, s.positions)
                       .has_value();
        stuck += open ? 0 : 1;
    }
    return stuck;
}

}  // namespace

int main(int argc, char** argv) {
    Args a;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--game")
            a.game = v;
        else if (k == "--n")
            a.n = std::atoi(v.c_str());
        else if (k == "--draws")
            a.draws = std::atoi(v.c_str());
        else if (k == "--seed")
            a.seed = std::strtoull(v.c_str(), nullptr, 10);
        else {
            std::fprintf(stderr,
                         "usage: break_tuning [--game 8ball|9ball] [--n N] [--draws D] "
                         "[--seed S]\n");
            return 2;
        }
    }
    const rules::Game game = a.game == "9ball" ? rules::Game::nine_ball : rules::Game::eight_ball;
    const int key = game == rules::Game::eight_ball ? 8 : 9;
    std::vector<Tally> grid;
    for (double offset : {0.0, 0.08, -0.08, 0.15, -0.15, 0.32, -0.32})
        for (double contact : {0.0, 0.25})
            for (double speed : {6.5, 8.0, 9.5, 10.0, 10.5})
                grid.push_back({{offset, contact, speed}});
    ai::Position pos;
    pos.ruleset.game = game;
    pos.table = physics::build_table(physics::TableSpec{});
    physics::SplitMix64 noise(a.seed ^ 0xb4eaULL);
    for (int i = 0; i < a.n; ++i) {
        pos.state = rules::initial_state(game, rules::Player::A);
        pos.state.positions.clear();
        for (const physics::BallState& b : physics::rack(
                 game == rules::Game::eight_ball ? physics::RackType::eight_ball
                                                 : physics::RackType::nine_ball,
                 pos.table, pos.params, a.seed * 1000003ULL + static_cast<std::uint64_t>(i)))
            if (b.id != 0) pos.state.positions[b.id] = b.pos;
        for (Tally& t : grid) {
            const std::optional<ai::Candidate> c = ai::break_candidate(pos, t.spec);
            if (!c) continue;
            rules::GameState s = pos.state;
            s.positions[0] = *c->cue_pos;
            for (int d = 0; d < a.draws; ++d) {
                const physics::Stroke stroke = game::with_noise(c->stroke, 1.0, noise);
                const physics::Shot shot =
                    physics::simulate(pos.table, pos.params, ai::layout(s, *c->cue_pos), &stroke);
                const rules::Verdict v = rules::judge(pos.ruleset, s, shot.events());
                t.stuck += stuck_objects(pos, v.state);
                t.down += static_cast<double>(s.on_table.size() - v.state.on_table.size());
                t.fouls += v.foul ? 1.0 : 0.0;
                t.key_down += v.game_over || !v.state.has(key) ? 1.0 : 0.0;
                t.played += 1.0;
            }
        }
    }
    for (const Tally& t : grid) {
        const double n = t.played > 0.0 ? t.played : 1.0;
        std::printf(
            "{\"game\": \"%s\", \"offset\": %.2f, \"contact\": %.2f, \"speed\": %.1f, "
            "\"breaks\": %.0f, \"stuck\": %.3f, \"down\": %.3f, \"fouls\": %.3f, "
            "\"key_ball_down\": %.3f}\n",
            a.game.c_str(), t.spec.offset, t.spec.contact, t.spec.speed, t.played, t.stuck / n,
            t.down / n, t.fouls / n, t.key_down / n);
    }
    return 0;
}
