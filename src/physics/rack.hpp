// Racks per docs/rules.md: 8-ball triangle and 9-ball diamond, balls frozen together, seeded.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"

namespace physics {

enum class RackType { eight_ball, nine_ball };

/// The object balls racked with the apex on the foot spot, plus the cue ball at `cue_pos`
/// (default: the head spot). Ball 0 first, then the object balls by id.
std::vector<BallState> rack(RackType type, const Table& table, const Params& params,
                            std::uint64_t seed, std::optional<Vec2> cue_pos = std::nullopt);

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
