#include "game/match_json.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "game/state_json.hpp"
#include "physics/layout.hpp"
#include "rules/names.hpp"

namespace game::match_json {

using nlohmann::ordered_json;

namespace {

constexpr std::int64_t format_version = 1;
constexpr std::size_t max_name_length = 100;

std::optional<int> id_of(const std::string& key) {
    if (key.empty() || key.size() > 2 || (key.size() == 2 && key[0] == '0')) return std::nullopt;
    if (!std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    return std::stoi(key);
}

}  // namespace

void write_header(ordered_json& j, std::string_view format) {
    j["format"] = format;
    j["version"] = format_version;
}

void check_header(const Field& root, std::string_view format) {
    if (!root.raw().is_object()) root.fail("not a Coolaaber save: expected a JSON object");
    std::optional<Field> f = root.find("format");
    if (!f || !f->raw().is_string() || f->string() != format)
        throw LoadError(root.path() + ".format",
                        fmt::format("not a {} file (expected \"format\": \"{}\")", format, format));
    Field version = root.at("version");
    if (version.integer_in(1, 1000000) != format_version)
        version.fail(fmt::format("version {} is not supported (this build reads version {})",
                                 version.raw().dump(), format_version));
}

ordered_json pair(const std::array<int, 2>& v) {
    return {{"A", v[0]}, {"B", v[1]}};
}

std::array<int, 2> read_pair(const Field& f, int lo, int hi) {
    f.require_fields({"A", "B"});
    std::array<int, 2> v{};
    for (rules::Player p : {rules::Player::A, rules::Player::B})
        v[rules::index(p)] = static_cast<int>(f.at(rules::name(p)).integer_in(lo, hi));
    return v;
}

ordered_json names(const std::array<std::string, 2>& n) {
    return {{"A", n[0]}, {"B", n[1]}};
}

std::array<std::string, 2> read_names(const Field& f) {
    f.require_fields({"A", "B"});
    std::array<std::string, 2> out;
    for (rules::Player p : {rules::Player::A, rules::Player::B}) {
        Field n = f.at(rules::name(p));
        std::string s = n.string();
        if (s.empty() || s.size() > max_name_length)
            n.fail(fmt::format("a player's name has 1 to {} bytes", max_name_length));
        out[rules::index(p)] = std::move(s);
    }
    return out;
}

ordered_json positions(const std::map<int, physics::Vec2>& p) {
    ordered_json j = ordered_json::object();
    for (const auto& [id, v] : p) j[std::to_string(id)] = to_json(v);
    return j;
}

std::map<int, physics::Vec2> read_positions(const Field& f, const physics::Table& table,
                                            const physics::Params& params,
                                            const std::function<bool(int)>& allowed) {
    if (!f.raw().is_object())
        f.fail("expected an object of positions by ball id, e.g. {\"0\": [0.5, 0.6]}");
    std::map<int, physics::Vec2> out;
    std::vector<physics::BallState> balls;
    std::vector<std::string> keys;
    for (const auto& [key, value] : f.raw().items()) {
        Field item = f.at(std::string_view(key));
        const std::optional<int> id = id_of(key);
        if (!id || !allowed(*id))
            item.fail(fmt::format("ball \"{}\" is not a ball on this table", key));
        out[*id] = read_vec2(item);
        physics::BallState b;
        b.id = *id;
        b.pos = out[*id];
        balls.push_back(b);
        keys.push_back(key);
    }
    if (std::optional<physics::LayoutError> e = physics::validate_layout(table, params, balls))
        throw LoadError(f.path() + "." + keys[e->index], e->message);
    return out;
}

}  // namespace game::match_json
