#include "app/settings.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "game/json_field.hpp"

namespace {

std::filesystem::path fresh_folder(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("coolaaber-settings-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string read(const std::filesystem::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Settings, RoundTripThroughTheFile) {
    const auto dir = fresh_folder("round-trip");
    app::Settings s;
    s.game = rules::Game::nine_ball;
    s.view = app::ViewMode::cue_ball;
    s.sound = false;
    s.power = 0.8;
    s.names = {"Efren", "Earl"};
    s.players = {"human", "ai:4"};
    s.house_rules.call_shots = rules::CallShots::eight_only;
    s.window_width = 1600;
    s.fullscreen = true;
    s.aim_guide = app::AimGuide::practice;
    app::save_settings(dir / "sub" / "settings.json", s);
    const app::LoadedSettings back = app::load_settings(dir / "sub" / "settings.json");
    EXPECT_FALSE(back.message.has_value());
    EXPECT_EQ(back.settings, s);
    EXPECT_NE(read(dir / "sub" / "settings.json").find("\"aim_guide\": \"practice\""),
              std::string::npos);
}

// Settings written before the guide had levels still load: the key missing gives the default
// level, true (the guide on) the default level, false off.
TEST(Settings, TheAimGuideLevelReadsOldFiles) {
    const std::string head = "{\"format\": \"coolaaber-settings\", \"version\": 1";
    EXPECT_EQ(app::Settings{}.aim_guide, app::AimGuide::lines);
    EXPECT_EQ(app::settings_from_json(head + "}").aim_guide, app::AimGuide::lines);
    EXPECT_EQ(app::settings_from_json(head + ", \"aim_guide\": true}").aim_guide,
              app::AimGuide::lines);
    EXPECT_EQ(app::settings_from_json(head + ", \"aim_guide\": false}").aim_guide,
              app::AimGuide::off);
    for (app::AimGuide g : {app::AimGuide::off, app::AimGuide::ghost, app::AimGuide::lines,
                            app::AimGuide::practice}) {
        app::Settings s;
        s.aim_guide = g;
        EXPECT_EQ(app::settings_from_json(app::settings_to_json(s)).aim_guide, g);
    }
    try {
        (void)app::settings_from_json(head + ", \"aim_guide\": \"full\"}");
        ADD_FAILURE() << "an unknown level was read";
    } catch (const game::LoadError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "settings.aim_guide: unknown aim guide \"full\" (expected \"off\", \"ghost\", "
                  "\"lines\" or \"practice\")");
    }
    EXPECT_THROW((void)app::settings_from_json(head + ", \"aim_guide\": 2}"), game::LoadError);
}

TEST(Settings, AMissingFileGivesTheDefaultsSilently) {
    const auto dir = fresh_folder("missing");
    const app::LoadedSettings s = app::load_settings(dir / "settings.json");
    EXPECT_FALSE(s.message.has_value());
    EXPECT_EQ(s.settings, app::Settings{});
}

TEST(Settings, ACorruptFileIsKeptAsideAndTheDefaultsUsed) {
    const auto dir = fresh_folder("corrupt");
    const auto path = dir / "settings.json";
    const std::string text = "{\"format\": \"coolaaber-settings\", \"version\": 1, \"power\": 7}";
    std::ofstream(path) << text;
    const app::LoadedSettings s = app::load_settings(path);
    ASSERT_TRUE(s.message.has_value());
    EXPECT_NE(s.message->find("settings.power"), std::string::npos) << *s.message;
    EXPECT_NE(s.message->find("settings.json.bad"), std::string::npos) << *s.message;
    EXPECT_EQ(s.settings, app::Settings{});
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_EQ(read(dir / "settings.json.bad"), text);  // nothing lost
    // A second bad file does not overwrite the first one kept aside.
    std::ofstream(path) << "not json";
    const app::LoadedSettings again = app::load_settings(path);
    ASSERT_TRUE(again.message.has_value());
    EXPECT_EQ(read(dir / "settings.json.bad"), text);
    EXPECT_EQ(read(dir / "settings.json.bad-2"), "not json");
}

TEST(Settings, ErrorsNameTheField) {
    auto error = [](const std::string& text) {
        try {
            (void)app::settings_from_json(text);
        } catch (const game::LoadError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string head = "{\"format\": \"coolaaber-settings\", \"version\": 1, ";
    EXPECT_NE(error(head + "\"colour\": 1}").find("colour"), std::string::npos);
    EXPECT_NE(error(head + "\"view\": \"side\"}").find("settings.view"), std::string::npos);
    EXPECT_NE(error(head + "\"players\": [\"human\", \"ai:9\"]}").find("settings.players[1]"),
              std::string::npos);
    EXPECT_NE(error(head + "\"window\": {\"width\": 10}}").find("settings.window.width"),
              std::string::npos);
    EXPECT_NE(error("{\"format\": \"pool\", \"version\": 1}").find("not a Coolaaber settings file"),
              std::string::npos);
    // Fields left out keep their defaults.
    EXPECT_EQ(app::settings_from_json(head + "\"sound\": false}").power, app::Settings{}.power);
}

}  // namespace
