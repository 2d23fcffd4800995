// How well the AI's analytic chance of a direct pot (src/ai/ghost_ball.hpp) predicts the engine
// (docs/ai.md): not a test, a measurement.
//   shot_calibration [--n N] [--seed S] [--noise X] [--layouts FILE] [--pockets all|side|corner]
//                    [--dump FILE]
// Layouts: N random ones (the cue ball and one object ball), and with --layouts every layout of
// an `AI_VERBOSE=1 AI_VERBOSE_LAYOUT=1 ai_strength runouts` log with the cue ball on the table
// (8-ball rules, the group as logged). For every direct pot of a target ball the four firm
// strokes of the candidate grid (1.3 and 2.1 × the pot speed, stun and follow) are each played
// with 48 noise draws; potted means the ball in the aimed pocket. Prints the model's chance
// against the share potted in ten bins, and the log-likelihood of the strokes' outcomes for
// heading σ from 0.06 to 0.30° (the model's is ai::heading_sigma_deg). --dump writes one line per
// stroke (pocket, approach cosine, cut, distances, potted, played) for fitting elsewhere.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/position.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"
#include "two_ball_layout.hpp"

namespace {

struct Args {
    int n = 1000;
    std::uint64_t seed = 1;
    double noise = 1.0;
    std::string layouts;
    std::string pockets = "all";
    std::string dump;
};

struct Row {
    ai::Aim aim;
    int potted = 0;
    int played = 0;
};

ai::Position empty_position(rules::Game game) {
    ai::Position p;
    p.ruleset.game = game;
    p.table = physics::build_table(physics::TableSpec{});
    p.state = rules::initial_state(game, rules::Player::A);
    p.state.shot = rules::Shot::normal;
    p.state.cue_ball = rules::CueBall::on_table;
    p.state.positions.clear();
    p.state.on_table.clear();
    return p;
}

// The cue ball and the 9 (9-ball: the 9 is the target).
ai::Position random_layout(physics::SplitMix64& rng) {
    ai::Position pos = empty_position(rules::Game::nine_ball);
    pos.state.positions = bench::two_ball_layout(pos.table, pos.params.ball_radius, rng);
    pos.state.on_table = {9};
    return pos;
}

// Every logged layout with the cue ball on the table: "layout 0:x,y 3:x,y ... group_a G".
std::vector<ai::Position> logged_layouts(const std::string& path) {
    std::vector<ai::Position> out;
    FILE* f = std::fopen(path.c_str(), "r");
    if (!f) {
        std::fprintf(stderr, "error: --layouts %s: cannot be read\n", path.c_str());
        std::exit(2);
    }
    std::vector<char> line(1 << 16);
    while (std::fgets(line.data(), static_cast<int>(line.size()), f)) {
        const char* l = std::strstr(line.data(), "layout 0:");
        if (!l) continue;
        ai::Position pos = empty_position(rules::Game::eight_ball);
        l += std::strlen("layout ");
        int id = 0, used = 0;
        double x = 0, y = 0;
        while (std::sscanf(l, " %d:%lf,%lf%n", &id, &x, &y, &used) == 3) {
            pos.state.positions[id] = {x, y};
            if (id != 0) pos.state.on_table.insert(id);
            l += used;
        }
        if (const char* g = std::strstr(l, "group_a "); g && std::atoi(g + 8) >= 0)
            pos.state.group_a =
                std::atoi(g + 8) == 0 ? rules::Group::solids : rules::Group::stripes;
        out.push_back(pos);
    }
    std::fclose(f);
    return out;
}

bool is_side(int pocket) {
    return pocket == static_cast<int>(physics::PocketId::S) ||
           pocket == static_cast<int>(physics::PocketId::N);
}

// Every direct pot of `pos`, its four firm strokes each played with every draw.
void play_pots(const ai::Position& pos, const Args& a, const std::vector<ai::NoiseDraw>& draws,
               std::vector<Row>& rows) {
    ai::Effort effort = ai::effort_for(pos.ruleset.game, ai::max_level);
    effort.speeds = 2;  // 1.3 and 2.1 × the speed that just gets the ball there
    effort.spins = 2;   // stun and follow
    std::int64_t simulations = 0;
    const physics::Vec2 cue = pos.state.positions.at(0);
    const std::vector<physics::BallState> balls = ai::layout(pos.state, cue);
    for (const ai::RankedAim& r : ai::ranked_aims(pos, cue, ai::heading_sigma_deg(pos.params))) {
        if (a.pockets != "all" && is_side(r.aim.pocket) != (a.pockets == "side")) continue;
        for (const ai::Candidate& c : ai::pot_strokes(pos, cue, false, r, effort, simulations)) {
            Row row{r.aim};
            for (const ai::NoiseDraw& d : draws) {
                const physics::Stroke stroke = ai::with_draw(c.stroke, d, a.noise);
                const physics::Shot shot = physics::simulate(pos.table, pos.params, balls, &stroke);
                for (const physics::Event& e : shot.events())
                    if (e.type == physics::EventType::pocket && e.balls[0].id == r.aim.ball &&
                        e.pocket == r.aim.pocket)
                        ++row.potted;
                ++row.played;
            }
            rows.push_back(row);
        }
    }
}

void dump(const std::string& path, const std::vector<Row>& rows) {
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        std::fprintf(stderr, "error: --dump %s: cannot be written\n", path.c_str());
        std::exit(2);
    }
    const physics::Table table = physics::build_table(physics::TableSpec{});
    std::fprintf(f, "# pocket approach_cos cut_deg cue_m object_m potted played\n");
    for (const Row& r : rows) {
        const physics::Pocket& pk = table.pockets[static_cast<std::size_t>(r.aim.pocket)];
        std::fprintf(f, "%d %.6f %.4f %.6f %.6f %d %d\n", r.aim.pocket,
                     physics::dot(r.aim.object_dir, pk.inward), r.aim.cut_deg, r.aim.cue_distance,
                     r.aim.object_distance, r.potted, r.played);
    }
    std::fclose(f);
}

void report(const Args& a, const std::vector<Row>& rows) {
    const physics::Params params;
    const double R = params.ball_radius;
    const double model_sigma = ai::heading_sigma_deg(params);
    std::vector<double> model(10, 0.0), engine(10, 0.0);
    std::vector<int> count(10, 0);
    for (const Row& r : rows) {
        const double q = ai::aim_chance(r.aim, R, model_sigma * a.noise);
        const auto b = static_cast<std::size_t>(std::clamp(static_cast<int>(q * 10.0), 0, 9));
        model[b] += q;
        engine[b] += static_cast<double>(r.potted) / r.played;
        ++count[b];
    }
    std::printf("{\"strokes\": %zu, \"noise\": %g, \"pockets\": \"%s\", \"bins\": [", rows.size(),
                a.noise, a.pockets.c_str());
    for (std::size_t b = 0; b < 10; ++b)
        std::printf("%s{\"model\": %.3f, \"engine\": %.3f, \"strokes\": %d}", b ? ", " : "",
                    count[b] ? model[b] / count[b] : 0.0, count[b] ? engine[b] / count[b] : 0.0,
                    count[b]);
    std::printf("], \"log_likelihood\": [");
    double best_sigma = 0.0, best = -1e300;
    for (int k = 0; k <= 16; ++k) {
        const double sigma = 0.06 + 0.015 * k;
        double ll = 0.0;
        for (const Row& r : rows) {
            const double q = std::clamp(ai::aim_chance(r.aim, R, sigma * a.noise), 1e-4, 1 - 1e-4);
            ll += r.potted * std::log(q) + (r.played - r.potted) * std::log(1.0 - q);
        }
        if (ll > best) {
            best = ll;
            best_sigma = sigma;
        }
        std::printf("%s{\"sigma_deg\": %.3f, \"value\": %.1f}", k ? ", " : "", sigma, ll);
    }
    std::printf("], \"best_sigma_deg\": %.3f, \"model_sigma_deg\": %.3f}\n", best_sigma,
                model_sigma);
}

}  // namespace

int main(int argc, char** argv) {
    Args a;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--n")
            a.n = std::atoi(v.c_str());
        else if (k == "--seed")
            a.seed = std::strtoull(v.c_str(), nullptr, 10);
        else if (k == "--noise")
            a.noise = std::atof(v.c_str());
        else if (k == "--layouts")
            a.layouts = v;
        else if (k == "--pockets" && (v == "all" || v == "side" || v == "corner"))
            a.pockets = v;
        else if (k == "--dump")
            a.dump = v;
        else {
            std::fprintf(stderr,
                         "usage: shot_calibration [--n N] [--seed S] [--noise X] "
                         "[--layouts FILE] [--pockets all|side|corner] [--dump FILE]\n");
            return 2;
        }
    }
    std::vector<ai::Position> layouts;
    if (!a.layouts.empty()) layouts = logged_layouts(a.layouts);
    physics::SplitMix64 rng(a.seed);
    for (int i = 0; i < a.n; ++i) layouts.push_back(random_layout(rng));
    const std::vector<ai::NoiseDraw> draws = ai::noise_draws(a.seed ^ 0x77ULL, 48);
    std::vector<Row> rows;
    for (const ai::Position& pos : layouts) play_pots(pos, a, draws, rows);
    if (!a.dump.empty()) dump(a.dump, rows);
    report(a, rows);
    return 0;
}
