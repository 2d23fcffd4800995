// Start-up with odd files (app/game_setup.hpp): a settings file or a saved game that is a
// directory or a FIFO is kept aside with a message and the game starts with the defaults; a
// --load file that is not a regular file is refused at once. Nothing blocks, nothing is lost.
#include "app/game_setup.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "game/json_field.hpp"

namespace {

namespace fs = std::filesystem;

// XDG folders of its own for one test, restored afterwards.
class Folders {
  public:
    explicit Folders(const std::string& name)
        : root_(fs::temp_directory_path() /
                ("coolaaber-setup-" + name + "-" + std::to_string(::getpid()))) {
        fs::remove_all(root_);
        fs::create_directories(config());
        fs::create_directories(data());
        ::setenv("XDG_CONFIG_HOME", (root_ / "config").c_str(), 1);
        ::setenv("XDG_DATA_HOME", (root_ / "data").c_str(), 1);
    }
    ~Folders() {
        ::unsetenv("XDG_CONFIG_HOME");
        ::unsetenv("XDG_DATA_HOME");
        fs::remove_all(root_);
    }
    fs::path config() const { return root_ / "config" / "coolaaber"; }
    fs::path data() const { return root_ / "data" / "coolaaber"; }
    fs::path root() const { return root_; }

  private:
    fs::path root_;
};

app::AppOptions options() {
    app::AppOptions o;
    o.seed = 5;
    return o;
}

TEST(GameSetup, SettingsThatAreADirectoryAreKeptAsideLikeASavedGame) {
    const Folders f("settings-dir");
    fs::create_directories(f.config() / "settings.json" / "inside");
    fs::create_directories(f.data() / "saved-game.json");
    const app::GameSetup g = app::set_up_game(options());
    EXPECT_EQ(g.settings, app::Settings{});
    ASSERT_TRUE(g.session.has_value());
    EXPECT_NE(g.notice.find("settings.json: is a directory, not a regular file"), std::string::npos)
        << g.notice;
    EXPECT_NE(g.notice.find("saved game could not be resumed"), std::string::npos) << g.notice;
    // Both kept, nothing lost.
    EXPECT_TRUE(fs::is_directory(f.config() / "settings.json.bad" / "inside"));
    EXPECT_TRUE(fs::is_directory(f.data() / "saved-game.json.bad"));
}

TEST(GameSetup, FifosAsSettingsOrSavedGameDoNotBlock) {
    const Folders f("fifo");
    ASSERT_EQ(::mkfifo((f.config() / "settings.json").c_str(), 0600), 0);
    ASSERT_EQ(::mkfifo((f.data() / "saved-game.json").c_str(), 0600), 0);
    const app::GameSetup g = app::set_up_game(options());
    EXPECT_EQ(g.settings, app::Settings{});
    EXPECT_NE(g.notice.find("settings.json: is a FIFO (named pipe), not a regular file"),
              std::string::npos)
        << g.notice;
    EXPECT_NE(g.notice.find("saved-game.json: is a FIFO"), std::string::npos) << g.notice;
    EXPECT_TRUE(fs::is_fifo(f.config() / "settings.json.bad"));
    EXPECT_TRUE(fs::is_fifo(f.data() / "saved-game.json.bad"));
}

TEST(GameSetup, ALoadFileThatIsAFifoIsRefused) {
    const Folders f("load-fifo");
    const fs::path fifo = f.root() / "game.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    app::AppOptions o = options();
    o.load = fifo;
    try {
        (void)app::set_up_game(o);
        FAIL() << "a FIFO was loaded";
    } catch (const game::LoadError& e) {
        EXPECT_EQ(e.path(), fifo.string());
        EXPECT_EQ(e.detail().rfind("is a FIFO (named pipe), not a regular file", 0), 0u);
    }
    EXPECT_TRUE(fs::is_fifo(fifo));  // untouched
}

// Every name keep_aside would use (.bad, .bad-2 … .bad-999) is taken.
void take_every_aside_name(const fs::path& path) {
    std::ofstream(fs::path(path).concat(".bad")) << "";
    for (int k = 2; k < 1000; ++k)
        std::ofstream(fs::path(path).concat(".bad-" + std::to_string(k))) << "";
}

std::string contents(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(GameSetup, BadFilesThatCannotBeSetAsideAreNeverWrittenOver) {
    const Folders f("no-aside");
    const fs::path settings = f.config() / "settings.json", save = f.data() / "saved-game.json";
    std::ofstream(settings) << "{ not settings";
    std::ofstream(save) << "{ not a saved game";
    take_every_aside_name(settings);
    take_every_aside_name(save);
    app::GameSetup g = app::set_up_game(options());
    ASSERT_TRUE(g.session.has_value());
    EXPECT_NE(g.notice.find("left as it is"), std::string::npos) << g.notice;
    EXPECT_TRUE(g.settings_path.empty());
    EXPECT_TRUE(g.autosave_path.empty());
    EXPECT_EQ(app::save_on_exit(*g.session, g.autosave_path), "");
    EXPECT_EQ(contents(settings), "{ not settings");
    EXPECT_EQ(contents(save), "{ not a saved game");
}

// A computer seat is called what it is, unless the player named it.
TEST(GameSetup, ComputerSeatsAreCalledByWhatTheyAre) {
    app::Settings s;
    s.players = {"human", "ai:3"};
    EXPECT_EQ(app::new_game_config(s, 1).names,
              (std::array<std::string, 2>{"Player 1", "Computer (level 3)"}));
    s.players = {"random", "human"};
    EXPECT_EQ(app::new_game_config(s, 1).names,
              (std::array<std::string, 2>{"Computer (random)", "Player 2"}));
    s.players = {"ai:5", "ai:5"};
    EXPECT_EQ(app::new_game_config(s, 1).names,
              (std::array<std::string, 2>{"Computer 1 (level 5)", "Computer 2 (level 5)"}));
    s.names = {"Deep Blue", "Player 2"};
    EXPECT_EQ(app::new_game_config(s, 1).names,
              (std::array<std::string, 2>{"Deep Blue", "Computer 2 (level 5)"}));
}

}  // namespace

namespace {

std::string read_all(const fs::path& p) {
    std::ifstream in(p);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(GameSetup, ASnookerMatchOrAThreeCushionGameLeftUnfinishedIsResumed) {
    const Folders f("resume-match");
    game::SnookerConfig sc;
    sc.names = {"Ann", "Bob"};
    ASSERT_EQ(app::save_on_exit(game::SnookerSession(sc), f.data() / "saved-game.json"), "");
    app::GameSetup g = app::set_up_game(options());
    ASSERT_TRUE(g.snooker.has_value());
    EXPECT_EQ(g.snooker->config().names[1], "Bob");
    EXPECT_TRUE(g.session.has_value()) << "a pool session behind the match";
    EXPECT_EQ(g.notice, "Resumed the game saved when you last exited.");

    game::CaromConfig cc;
    cc.options.target = 7;
    ASSERT_EQ(app::save_on_exit(game::CaromSession(cc), f.data() / "saved-game.json"), "");
    g = app::set_up_game(options());
    ASSERT_TRUE(g.carom.has_value());
    EXPECT_EQ(g.carom->config().options.target, 7);
    EXPECT_FALSE(g.snooker.has_value());
}

TEST(GameSetup, ACorruptSnookerSaveIsKeptAsideNamingTheField) {
    const Folders f("corrupt-match");
    ASSERT_EQ(app::save_on_exit(game::SnookerSession(game::SnookerConfig{}),
                                f.data() / "saved-game.json"),
              "");
    std::string text = read_all(f.data() / "saved-game.json");
    const std::string best_of = "\"best_of\":1";
    ASSERT_NE(text.find(best_of), std::string::npos) << text.substr(0, 300);
    text.replace(text.find(best_of), best_of.size(), "\"best_of\":\"one\"");
    std::ofstream(f.data() / "saved-game.json") << text;
    const app::GameSetup g = app::set_up_game(options());
    EXPECT_FALSE(g.snooker.has_value());
    ASSERT_TRUE(g.session.has_value());
    EXPECT_TRUE(g.notice_is_error);
    EXPECT_NE(g.notice.find("best_of"), std::string::npos) << g.notice;
    EXPECT_NE(g.notice.find("it was kept as"), std::string::npos) << g.notice;
    EXPECT_FALSE(fs::exists(f.data() / "saved-game.json")) << "moved aside, not written over";
}

namespace {

// --game snooker|three_cushion: a new match on its own table; with --practice, practice there.
TEST(GameSetup, TheGameOptionStartsSnookerAndThreeCushionOrPracticeOnTheirTables) {
    const Folders f("game-option");
    app::AppOptions o = options();
    o.game = physics::RackType::snooker;
    app::GameSetup g = app::set_up_game(o);
    ASSERT_TRUE(g.snooker.has_value());
    EXPECT_FALSE(g.practice.has_value());
    EXPECT_TRUE(g.session.has_value()) << "the pool session behind the match";
    o.game = physics::RackType::three_cushion;
    g = app::set_up_game(o);
    EXPECT_TRUE(g.carom.has_value());
    EXPECT_FALSE(g.snooker.has_value());
    o.practice = true;
    g = app::set_up_game(o);
    EXPECT_EQ(g.practice, physics::RackType::three_cushion);
    EXPECT_FALSE(g.carom.has_value()) << "practice, not a match";
    o.game.reset();
    g = app::set_up_game(o);
    EXPECT_EQ(g.practice, physics::RackType::eight_ball) << "the settings' pool game";
}

}  // namespace
