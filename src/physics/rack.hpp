// Racks per docs/rules.md: 8-ball triangle and 9-ball diamond, balls frozen together, seeded;
// the snooker set-up (WPBSA) and the three-cushion starting position (UMB).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"

namespace physics {

enum class RackType { eight_ball, nine_ball, snooker, three_cushion };

/// The object balls racked with the apex on the foot spot, plus the cue ball at `cue_pos`
/// (default: the head spot). Ball 0 first, then the object balls by id. Snooker and
/// three-cushion: see snooker_rack and carom_rack (the seed is not used).
std::vector<BallState> rack(RackType type, const Table& table, const Params& params,
                            std::uint64_t seed, std::optional<Vec2> cue_pos = std::nullopt);

/// The snooker set-up (WPBSA S3 'Position of Balls'): the colours on their spots, the 15 reds
/// (ids 1–15) in a tight triangle whose apex is on the long string 1 mm beyond touching the
/// pink, rows toward the top cushion; the cue ball at `cue_pos` (default: in the D, on the
/// baulk line halfway between the brown and yellow spots).
std::vector<BallState> snooker_rack(const Table& table, const Params& params,
                                    std::optional<Vec2> cue_pos = std::nullopt);

/// The three-cushion starting position (UMB): the red on the top spot, the yellow (the
/// opponent's ball) on the bottom spot, the white on the right-hand starting spot or at
/// `cue_pos`.
std::vector<BallState> carom_rack(const Table& table, std::optional<Vec2> cue_pos = std::nullopt);

/// A small deterministic random generator (SplitMix64), identical on every platform.
class SplitMix64 {
  public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    /// Uniform in [0, 1).
    double uniform();
    /// Uniform integer in [0, n).
    std::uint64_t below(std::uint64_t n);

  private:
    std::uint64_t state_;
};

}  // namespace physics
