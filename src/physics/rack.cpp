#include "physics/rack.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <utility>

#include "physics/markings.hpp"

namespace physics {

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double SplitMix64::uniform() {
    return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

std::uint64_t SplitMix64::below(std::uint64_t n) {
    return n == 0 ? 0 : next() % n;
}

namespace {

/// Fisher–Yates with our own generator, so racks are the same on every platform.
void shuffle(std::span<int> a, SplitMix64& rng) {
    for (std::size_t i = a.size(); i > 1; --i)
        std::swap(a[i - 1], a[static_cast<std::size_t>(rng.below(i))]);
}

/// Centres of a tight rack whose rows have `counts` balls, apex on the foot spot, rows going
/// toward the foot cushion. Neighbours are exactly 2R apart (frozen).
std::vector<Vec2> rack_slots(const Table& t, double R, std::initializer_list<int> counts) {
    std::vector<Vec2> slots;
    const Vec2 apex = t.foot_spot();
    const double row_step = std::sqrt(3.0) * R;
    int row = 0;
    for (int n : counts) {
        for (int j = 0; j < n; ++j)
            slots.push_back({apex.x + row * row_step, apex.y + (j - (n - 1) / 2.0) * 2.0 * R});
        ++row;
    }
    return slots;
}

BallState ball_at(int id, Vec2 pos) {
    BallState b;
    b.id = id;
    b.pos = pos;
    return b;
}

}  // namespace

std::vector<BallState> rack(RackType type, const Table& table, const Params& params,
                            std::uint64_t seed, std::optional<Vec2> cue_pos) {
    if (type == RackType::snooker) return snooker_rack(table, params, cue_pos);
    if (type == RackType::three_cushion) return carom_rack(table, cue_pos);
    SplitMix64 rng(seed);
    const double R = params.ball_radius;
    std::vector<BallState> balls{ball_at(0, cue_pos.value_or(table.head_spot()))};
    std::array<int, 15> slot_ball{};  // ball id in each rack slot
    std::vector<Vec2> slots;
    if (type == RackType::eight_ball) {
        slots = rack_slots(table, R, {1, 2, 3, 4, 5});
        // The 8 in the centre of the third row (slot 4); a solid and a stripe in the back
        // corners (slots 10 and 14); the rest random.
        int solid = 1 + static_cast<int>(rng.below(7));
        int stripe = 9 + static_cast<int>(rng.below(7));
        if (rng.below(2) == 1) std::swap(solid, stripe);
        std::array<int, 12> rest{};
        std::size_t k = 0;
        for (int id = 1; id <= 15; ++id)
            if (id != 8 && id != solid && id != stripe) rest[k++] = id;
        shuffle(rest, rng);
        k = 0;
        for (std::size_t s = 0; s < 15; ++s) {
            if (s == 4)
                slot_ball[s] = 8;
            else if (s == 10)
                slot_ball[s] = solid;
            else if (s == 14)
                slot_ball[s] = stripe;
            else
                slot_ball[s] = rest[k++];
        }
    } else {
        slots = rack_slots(table, R, {1, 2, 3, 2, 1});
        // The 1 at the apex (slot 0), the 9 in the centre (slot 4), 2–8 random.
        std::array<int, 7> rest{2, 3, 4, 5, 6, 7, 8};
        shuffle(rest, rng);
        std::size_t k = 0;
        for (std::size_t s = 0; s < 9; ++s) slot_ball[s] = s == 0 ? 1 : s == 4 ? 9 : rest[k++];
    }
    std::vector<BallState> objects;
    for (std::size_t s = 0; s < slots.size(); ++s)
        objects.push_back(ball_at(slot_ball[s], slots[s]));
    std::sort(objects.begin(), objects.end(),
              [](const BallState& a, const BallState& b) { return a.id < b.id; });
    balls.insert(balls.end(), objects.begin(), objects.end());
    return balls;
}

std::vector<BallState> snooker_rack(const Table& table, const Params& params,
                                    std::optional<Vec2> cue_pos) {
    const SnookerMarkings m = snooker_markings(table);
    const double R = params.ball_radius;
    constexpr double kGapToPink = 0.001;  ///< "as near as possible without touching" (unit: m)
    const Vec2 brown = m.spot(snooker_ball::brown), yellow = m.spot(snooker_ball::yellow);
    std::vector<BallState> balls{ball_at(0, cue_pos.value_or(0.5 * (brown + yellow)))};
    const Vec2 pink = m.spot(snooker_ball::pink);
    const Vec2 apex{pink.x + 2.0 * R + kGapToPink, pink.y};
    const double row_step = std::sqrt(3.0) * R;
    int id = snooker_ball::first_red;
    for (int row = 0; row < 5; ++row)
        for (int j = 0; j <= row; ++j)
            balls.push_back(
                ball_at(id++, {apex.x + row * row_step, apex.y + (j - row / 2.0) * 2.0 * R}));
    for (int colour = snooker_ball::yellow; colour <= snooker_ball::black; ++colour)
        balls.push_back(ball_at(colour, m.spot(colour)));
    return balls;
}

std::vector<BallState> carom_rack(const Table& table, std::optional<Vec2> cue_pos) {
    const CaromSpots spots = carom_spots(table);
    return {ball_at(carom_ball::white, cue_pos.value_or(spots.start_right)),
            ball_at(carom_ball::yellow, spots.bottom), ball_at(carom_ball::red, spots.top)};
}

}  // namespace physics
