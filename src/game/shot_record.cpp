#include "game/shot_record.hpp"

#include <algorithm>

namespace game {

ShotSummary summarize(std::span<const physics::Event> events, std::optional<double> rest_time,
                      bool truncated) {
    using physics::EventType;
    ShotSummary s;
    s.events = static_cast<int>(events.size());
    s.truncated = truncated;
    s.duration = truncated ? 0.0 : rest_time.value_or(0.0);
    auto is_down = [&](int id) {
        return std::any_of(s.down.begin(), s.down.end(),
                           [id](const BallDown& d) { return d.ball == id; });
    };
    for (const physics::Event& e : events) {
        switch (e.type) {
            case EventType::ball_ball:
                ++s.ball_contacts;
                if (!s.first_contact && e.involves(0))
                    s.first_contact = e.ball(e.ball(0) == 0 ? 1 : 0);
                break;
            case EventType::cushion:
                ++s.cushions;
                break;
            case EventType::pocket:
                if (!is_down(e.ball(0))) s.down.push_back({e.ball(0), e.pocket});
                break;
            case EventType::off_table:
                if (!is_down(e.ball(0))) s.down.push_back({e.ball(0), -1});
                break;
            case EventType::strike:
            case EventType::miscue:
            case EventType::transition:
                break;
        }
    }
    return s;
}

}  // namespace game
