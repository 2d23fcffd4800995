#include "game/shot_link.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <optional>

#include "game/json_field.hpp"
#include "game/session.hpp"
#include "game/state_json.hpp"
#include "physics/table.hpp"
#include "rules/names.hpp"

namespace game {

namespace {

constexpr std::string_view kPrefix = "shot=";
constexpr std::string_view kVersion = "1";
constexpr std::string_view kAlphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
/// Far above a full 9-ball position (about 2 kB of link); bounds what a pasted text can cost.
constexpr std::size_t kMaxLinkBytes = 64 * 1024;

/// FNV-1a, 32 bits: catches a link cut short or mistyped (not a forgery: the reading checks
/// every field of what it decodes anyway).
std::uint32_t checksum(std::string_view text) {
    std::uint32_t h = 2166136261u;
    for (unsigned char c : text) h = (h ^ c) * 16777619u;
    return h;
}

std::string base64url(std::string_view bytes) {
    std::string out;
    std::uint32_t bits = 0;
    int count = 0;
    for (unsigned char c : bytes) {
        bits = (bits << 8) | c;
        count += 8;
        for (; count >= 6; count -= 6) out += kAlphabet[(bits >> (count - 6)) & 63];
    }
    if (count > 0) out += kAlphabet[(bits << (6 - count)) & 63];
    return out;
}

/// The bytes of a base64url text (no padding); LoadError at the first character outside the
/// alphabet.
std::string from_base64url(std::string_view text) {
    std::string out;
    std::uint32_t bits = 0;
    int count = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const std::size_t value = kAlphabet.find(text[i]);
        if (value == std::string_view::npos)
            throw LoadError("link", fmt::format("character {} of the shot ('{}') cannot be in a "
                                                "link: copy the whole link again",
                                                i + 1, text[i]));
        bits = (bits << 6) | static_cast<std::uint32_t>(value);
        count += 6;
        if (count >= 8) {
            out += static_cast<char>((bits >> (count - 8)) & 255);
            count -= 8;
        }
    }
    return out;
}

std::string_view trimmed(std::string_view t) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!t.empty() && space(t.front())) t.remove_prefix(1);
    while (!t.empty() && space(t.back())) t.remove_suffix(1);
    return t;
}

/// "1.<checksum>.<payload>" from an address or a link; LoadError if it is not one.
std::string_view link_body(std::string_view text) {
    text = trimmed(text);
    if (text.size() > kMaxLinkBytes)
        throw LoadError("link", fmt::format("{} characters is too long for a shot link (at most "
                                            "{})",
                                            text.size(), kMaxLinkBytes));
    if (const std::size_t hash = text.find('#'); hash != std::string_view::npos)
        text.remove_prefix(hash + 1);
    if (!text.starts_with(kPrefix))
        throw LoadError("link",
                        "not a shot link: it starts with \"shot=\" (or is an address "
                        "whose part after '#' does)");
    return text.substr(kPrefix.size());
}

nlohmann::ordered_json shot_json(const SharedShot& s) {
    return {{"game", rules::name(s.game)}, {"options", to_json(s.options)},
            {"table", to_json(s.table)},   {"params", to_json(s.params)},
            {"state", to_json(s.state)},   {"stroke", to_json(s.stroke)}};
}

SharedShot read_pool_shot(const Field& f) {
    f.require_fields({"game", "options", "table", "params", "state", "stroke"});
    SharedShot s;
    s.game = f.at("game").name_of<rules::Game>();
    s.options = read_options(f.at("options"), Fields::all);
    s.params = read_params(f.at("params"), Fields::all);
    s.table = read_table(f.at("table"), s.params.ball_radius, Fields::all);
    const physics::Table table = physics::build_table(s.table);
    s.state = read_state(f.at("state"), {s.game, table, s.params}, Fields::all);
    s.stroke = read_stroke(f.at("stroke"));
    return s;
}

nlohmann::ordered_json match_json(std::string_view game, const std::string& save,
                                  const physics::Stroke& stroke) {
    return {{"game", game},
            {"session", nlohmann::ordered_json::parse(save)},
            {"stroke", to_json(stroke)}};
}

/// A match session from its save format inside a link; its errors' paths are put under
/// `f`'s ("snooker.state.…" becomes "link.shot.session.state.…").
template <class MatchSession>
MatchSession read_session(const Field& f, std::string_view root) {
    try {
        return MatchSession::from_json(f.raw().dump());
    } catch (const LoadError& e) {
        std::string path = e.path();
        if (path.starts_with(root)) path = f.path() + path.substr(root.size());
        throw LoadError(path, e.detail());
    }
}

AnyShot read_shot(const Field& f) {
    const std::string game = f.at("game").one_of({"8ball", "9ball", "snooker", "three_cushion"});
    if (game != "snooker" && game != "three_cushion") return read_pool_shot(f);
    f.require_fields({"game", "session", "stroke"});
    const physics::Stroke stroke = read_stroke(f.at("stroke"));
    if (game == "snooker")
        return SharedSnookerShot{read_session<SnookerSession>(f.at("session"), "snooker"), stroke};
    return SharedCaromShot{read_session<CaromSession>(f.at("session"), "carom"), stroke};
}

}  // namespace

std::vector<physics::BallState> SharedShot::balls() const {
    return balls_at_rest(state);
}

std::string link_of_payload(std::string_view json) {
    return fmt::format("{}{}.{:08x}.{}", kPrefix, kVersion, checksum(json), base64url(json));
}

std::string shot_link(const SharedShot& shot) {
    return link_of_payload(shot_json(shot).dump());
}

std::string shot_link(const SharedSnookerShot& shot) {
    return link_of_payload(match_json("snooker", shot.before.to_json(), shot.stroke).dump());
}

std::string shot_link(const SharedCaromShot& shot) {
    return link_of_payload(match_json("three_cushion", shot.before.to_json(), shot.stroke).dump());
}

std::string shot_link(const AnyShot& shot) {
    return std::visit([](const auto& s) { return shot_link(s); }, shot);
}

AnyShot read_any_shot_link(std::string_view text) {
    const std::string_view body = link_body(text);
    const std::size_t dot1 = body.find('.'), dot2 = body.find('.', dot1 + 1);
    if (dot1 == std::string_view::npos || dot2 == std::string_view::npos)
        throw LoadError("link", "cut short: copy the whole link again");
    if (body.substr(0, dot1) != kVersion)
        throw LoadError("link", fmt::format("version {} of the link format is not known here "
                                            "(this game reads version {}): update the game",
                                            body.substr(0, dot1), kVersion));
    const std::string json = from_base64url(body.substr(dot2 + 1));
    if (fmt::format("{:08x}", checksum(json)) != body.substr(dot1 + 1, dot2 - dot1 - 1))
        throw LoadError("link",
                        "the shot does not match its checksum (the link was cut short "
                        "or changed): copy the whole link again");
    const nlohmann::json doc = parse_document(json, "link.shot");
    return read_shot(Field(doc, "link.shot"));
}

SharedShot read_shot_link(std::string_view text) {
    AnyShot shot = read_any_shot_link(text);
    if (SharedShot* pool = std::get_if<SharedShot>(&shot)) return std::move(*pool);
    throw LoadError("link.shot.game",
                    "a snooker or three-cushion shot: open it in the game, which plays all four");
}

}  // namespace game
