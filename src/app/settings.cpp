#include "app/settings.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <stdio.h>

#include <cerrno>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "game/atomic_file.hpp"
#include "game/json_field.hpp"
#include "game/state_json.hpp"
#include "game/text_file.hpp"
#include "rules/names.hpp"

namespace app {

namespace {

std::filesystem::path xdg_folder(const char* variable, const char* fallback) {
    if (const char* v = std::getenv(variable); v && *v)
        return std::filesystem::path(v) / "coolaaber";
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home && *home ? home : ".") / fallback / "coolaaber";
}

constexpr std::string_view view_name(ViewMode v) {
    return v == ViewMode::overhead ? "overhead" : "cueball";
}

// "aim_guide": a level's name; true and false (files written before the levels) read as the
// default level and off.
AimGuide read_aim_guide(const game::Field& v) {
    if (v.raw().is_boolean()) return v.boolean() ? AimGuide::lines : AimGuide::off;
    const std::string name = v.string();
    for (AimGuide g : {AimGuide::off, AimGuide::ghost, AimGuide::lines, AimGuide::practice})
        if (name == aim_guide_name(g)) return g;
    v.fail("unknown aim guide \"" + name +
           "\" (expected \"off\", \"ghost\", \"lines\" or \"practice\")");
}

}  // namespace

std::string_view aim_guide_name(AimGuide g) {
    switch (g) {
        case AimGuide::off:
            return "off";
        case AimGuide::ghost:
            return "ghost";
        case AimGuide::lines:
            return "lines";
        case AimGuide::practice:
            return "practice";
    }
    return "lines";
}

AimGuide next_aim_guide(AimGuide g) {
    return g == AimGuide::practice ? AimGuide::off : static_cast<AimGuide>(static_cast<int>(g) + 1);
}

const char* aim_guide_words(AimGuide g) {
    switch (g) {
        case AimGuide::off:
            return "Off";
        case AimGuide::ghost:
            return "Ghost ball";
        case AimGuide::lines:
            return "Ghost ball and lines";
        case AimGuide::practice:
            return "Practice (full paths)";
    }
    return "?";
}

std::filesystem::path config_folder() {
    return xdg_folder("XDG_CONFIG_HOME", ".config");
}
std::filesystem::path data_folder() {
    return xdg_folder("XDG_DATA_HOME", ".local/share");
}

bool valid_player_kind(const std::string& kind) {
    if (kind == "human" || kind == "random") return true;
    return kind.size() == 4 && kind.rfind("ai:", 0) == 0 && kind[3] >= '1' && kind[3] <= '5';
}

std::string settings_to_json(const Settings& s) {
    nlohmann::ordered_json j;
    j["format"] = "coolaaber-settings";
    j["version"] = 1;
    j["game"] = rules::name(s.game);
    j["view"] = view_name(s.view);
    j["sound"] = s.sound;
    j["power"] = s.power;
    j["aim_guide"] = aim_guide_name(s.aim_guide);
    j["names"] = s.names;
    j["players"] = s.players;
    j["noise"] = s.noise;
    j["house_rules"] = game::to_json(s.house_rules);
    j["window"] = {
        {"width", s.window_width}, {"height", s.window_height}, {"fullscreen", s.fullscreen}};
    return j.dump(2) + "\n";
}

Settings settings_from_json(const std::string& text) {
    const nlohmann::json doc = game::parse_document(text, "settings");
    const game::Field f(doc, "settings");
    f.require_fields({"format", "version"}, {"game", "view", "sound", "power", "aim_guide", "names",
                                             "players", "noise", "house_rules", "window"});
    if (f.at("format").string() != "coolaaber-settings")
        f.at("format").fail("not a Coolaaber settings file (expected \"coolaaber-settings\")");
    if (f.at("version").integer_in(1, 1000) != 1)
        f.at("version").fail("written by a newer Coolaaber (this one reads version 1)");
    Settings s;
    if (auto g = f.find("game")) s.game = g->name_of<rules::Game>();
    if (auto v = f.find("view")) {
        const std::string name = v->string();
        if (name == "overhead")
            s.view = ViewMode::overhead;
        else if (name == "cueball")
            s.view = ViewMode::cue_ball;
        else
            v->fail("unknown view \"" + name + "\" (expected \"overhead\" or \"cueball\")");
    }
    if (auto v = f.find("sound")) s.sound = v->boolean();
    if (auto v = f.find("power")) s.power = v->number_in(0.0, 1.0);
    if (auto v = f.find("aim_guide")) s.aim_guide = read_aim_guide(*v);
    if (auto v = f.find("names")) {
        if (v->array_size() != 2) v->fail("expected two names, e.g. [\"Player 1\", \"Player 2\"]");
        for (std::size_t i = 0; i < 2; ++i) {
            s.names[i] = v->at(i).string();
            if (s.names[i].empty() || s.names[i].size() > 40)
                v->at(i).fail("a name has 1 to 40 characters");
        }
    }
    if (auto v = f.find("players")) {
        if (v->array_size() != 2) v->fail("expected two players, e.g. [\"human\", \"ai:3\"]");
        for (std::size_t i = 0; i < 2; ++i) {
            s.players[i] = v->at(i).string();
            if (!valid_player_kind(s.players[i]))
                v->at(i).fail("unknown player \"" + s.players[i] +
                              "\" (expected \"human\", \"random\" or \"ai:1\" to \"ai:5\")");
        }
    }
    if (auto v = f.find("noise")) s.noise = v->number_in(0.0, 10.0);
    if (auto v = f.find("house_rules")) s.house_rules = game::read_options(*v, game::Fields::all);
    if (auto w = f.find("window")) {
        w->require_fields({}, {"width", "height", "fullscreen"});
        if (auto v = w->find("width")) s.window_width = static_cast<int>(v->integer_in(320, 16384));
        if (auto v = w->find("height"))
            s.window_height = static_cast<int>(v->integer_in(240, 16384));
        if (auto v = w->find("fullscreen")) s.fullscreen = v->boolean();
    }
    return s;
}

namespace {

enum class Renamed { yes, name_taken, failed };

// Renames `from` to `to` unless `to` exists: never replaces a file kept aside before, even by
// another instance of the game starting at the same moment.
Renamed rename_no_replace(const std::filesystem::path& from, const std::filesystem::path& to) {
#ifdef RENAME_NOREPLACE  // Linux; the browser's file system (one page) has no renameat2
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
        return Renamed::yes;
    if (errno == EEXIST) return Renamed::name_taken;
    if (errno != EINVAL && errno != ENOSYS) return Renamed::failed;
#endif
    // A file system without RENAME_NOREPLACE: check, then rename.
    std::error_code ec;
    if (std::filesystem::exists(to, ec)) return Renamed::name_taken;
    std::filesystem::rename(from, to, ec);
    return ec ? Renamed::failed : Renamed::yes;
}

}  // namespace

std::filesystem::path keep_aside(const std::filesystem::path& path) {
    for (int k = 1; k < 1000; ++k) {
        std::filesystem::path aside = path;
        aside += k == 1 ? std::string(".bad") : fmt::format(".bad-{}", k);
        const Renamed r = rename_no_replace(path, aside);
        if (r == Renamed::yes) return aside;
        if (r == Renamed::failed) return {};
    }
    return {};
}

LoadedSettings load_settings(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return {};
    try {
        return {settings_from_json(game::read_regular_file(path)), std::nullopt};
    } catch (const game::LoadError& e) {
        const std::filesystem::path aside = keep_aside(path);
        const std::string where = e.path() == path.string() ? "" : path.string() + ": ";
        if (aside.empty())
            return {Settings{},
                    fmt::format("{}{}; it could not be renamed, so it is left as it is and the "
                                "default settings are used without being saved",
                                where, e.what()),
                    true};
        return {Settings{}, fmt::format("{}{}; it was kept as {} and the default settings are used",
                                        where, e.what(), aside.string())};
    }
}

void save_settings(const std::filesystem::path& path, const Settings& s) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec)
        throw std::runtime_error(
            fmt::format("cannot create {}: {}", path.parent_path().string(), ec.message()));
    game::write_file_atomically(path, settings_to_json(s));
}

}  // namespace app
