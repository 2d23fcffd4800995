// Save and resume: the round trip, every kind of corrupt or foreign input with the path of the
// offending field, loading never touching the file, saving replacing it atomically.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

#include "game/json_field.hpp"
#include "game/random_player.hpp"
#include "game/session.hpp"
#include "session_support.hpp"

namespace game::test {
namespace {

namespace fs = std::filesystem;

// A game in progress: 8-ball, some shots played by random players.
Session in_progress(bool keep_events = false, rules::Game game = rules::Game::eight_ball,
                    int played = 12) {
    Config c = config_for(game, 21);
    c.keep_events = keep_events;
    Session s(c);
    RandomPlayer a(5), b(6);
    play_shots(s, a, b, played);
    if (s.phase() == Phase::choose) s.choose(s.choice()->options.front());
    EXPECT_NE(s.phase(), Phase::game_over) << "pick another seed: the game is over";
    return s;
}

fs::path fresh_dir() {
    static std::atomic<int> counter{0};
    fs::path d = fs::path(::testing::TempDir()) /
                 ("game-save-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

std::vector<fs::path> listing(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
    std::sort(out.begin(), out.end());
    return out;
}

TEST(SaveLoad, RoundTrip) {
    for (bool keep : {false, true}) {
        const Session s = in_progress(keep);
        ASSERT_FALSE(s.history().empty());
        const std::string text = s.to_json();
        const Session back = Session::from_json(text);
        EXPECT_EQ(back.to_json(), text);
        EXPECT_EQ(back.phase(), s.phase());
        EXPECT_EQ(back.history().size(), s.history().size());
        EXPECT_EQ(back.state().positions, s.state().positions);  // exact doubles
        EXPECT_EQ(back.last_shot(), nullptr);  // the physics of the last shot is not saved
        if (keep) {
            EXPECT_FALSE(back.history().back().events.empty());
        }
    }
    const Session nine = in_progress(false, rules::Game::nine_ball, 3);
    EXPECT_EQ(Session::from_json(nine.to_json()).to_json(), nine.to_json());
}

TEST(SaveLoad, RoundTripOfTheConfig) {
    Config c = config_for(rules::Game::eight_ball, std::numeric_limits<std::uint64_t>::max());
    c.options.call_shots = rules::CallShots::eight_only;
    c.options.scratch_on_eight_loses = true;
    c.table = *physics::table_preset("8ft");
    c.params.mu_ball = 0.06;
    c.params.e_cushion = 0.8;
    c.names = {"Ünïcode \"quoted\"", "B"};
    c.first_breaker = B;
    const Session s(c);
    const Session back = Session::from_json(s.to_json());
    EXPECT_EQ(back.config().seed, c.seed);
    EXPECT_EQ(back.config().options, c.options);
    EXPECT_EQ(back.config().table.length, c.table.length);
    EXPECT_EQ(back.config().params.mu_ball, c.params.mu_ball);
    EXPECT_EQ(back.config().names, c.names);
    EXPECT_EQ(back.to_act(), B);
    EXPECT_EQ(back.to_json(), s.to_json());
}

struct Corrupt {
    std::string name;
    std::function<void(json&)> edit;  // applied to a valid document
    std::string path;                 // the LoadError's path
    std::string message;              // a part of its message
};

std::string load_error(const std::string& text) {
    try {
        (void)Session::from_json(text);
    } catch (const LoadError& e) {
        EXPECT_EQ(std::string(e.what()), e.path() + ": " + e.detail());
        return e.what();
    }
    return "(loaded)";
}

TEST(SaveLoad, CorruptDocumentsNameTheField) {
    const Session s = in_progress();
    const json valid = json::parse(s.to_json());
    ASSERT_GE(valid["state"]["on_table"].size(), 4u);
    const int first = valid["state"]["on_table"][0];
    const std::string first_key = std::to_string(first);
    int down = 0;  // a ball not on the table
    for (int id = 1; id <= 15 && !down; ++id) {
        bool on = false;
        for (const json& b : valid["state"]["on_table"]) on = on || b == id;
        if (!on) down = id;
    }
    ASSERT_NE(down, 0);

    const std::vector<Corrupt> cases = {
        {"unknown field", [](json& d) { d["colour"] = "red"; }, "session.colour", "unknown field"},
        {"unknown nested field", [](json& d) { d["state"]["spin"] = 1; }, "session.state.spin",
         "unknown field"},
        {"missing field", [](json& d) { d.erase("history"); }, "session.history", "missing field"},
        {"wrong type", [](json& d) { d["state"]["shooter"] = 3; }, "session.state.shooter",
         "expected a string, got a number"},
        {"wrong type (number)", [](json& d) { d["game_number"] = "1"; }, "session.game_number",
         "expected an integer"},
        {"fraction", [](json& d) { d["rack_number"] = 0.5; }, "session.rack_number",
         "expected an integer"},
        {"negative seed", [](json& d) { d["config"]["seed"] = -1; }, "session.config.seed",
         "negative"},
        {"unknown name", [](json& d) { d["state"]["shot"] = "jump"; }, "session.state.shot",
         "unknown value \"jump\""},
        {"ball that does not exist", [](json& d) { d["state"]["on_table"][3] = 17; },
         "session.state.on_table[3]", "ball 17 does not exist"},
        {"ball listed twice",
         [&](json& d) { d["state"]["on_table"][1] = d["state"]["on_table"][0]; },
         "session.state.on_table[1]", "listed twice"},
        {"overlapping balls",
         [&](json& d) {
             const json p = d["state"]["positions"][first_key];
             for (auto& [key, value] : d["state"]["positions"].items())
                 if (key != first_key && key != "0") {
                     value = p;
                     break;
                 }
         },
         "session.state.positions.", "overlaps ball"},
        {"ball off the table",
         [&](json& d) {
             d["state"]["positions"][first_key] = {3.0, 0.5};
         },
         "session.state.positions." + first_key, "off the table"},
        {"position of a pocketed ball",
         [&](json& d) {
             d["state"]["positions"][std::to_string(down)] = {1.0, 0.2};
         },
         "session.state.positions." + std::to_string(down), "not on the table"},
        {"ball on the table and pocketed",
         [&](json& d) {
             d["pocketed"].push_back({{"ball", first}, {"pocket", "NE"}, {"by", "A"}});
         },
         "session.pocketed[", "also on the table"},
        {"ball neither on the table nor pocketed",
         [&](json& d) {
             json& on = d["state"]["on_table"];
             int gone = 0;
             for (std::size_t i = 0; i < on.size(); ++i)
                 if (on[i] != 8) {
                     gone = on[i];
                     on.erase(i);
                     break;
                 }
             d["state"]["positions"].erase(std::to_string(gone));
         },
         "session.pocketed", "neither on the table nor pocketed"},
        {"no 8",
         [](json& d) {
             json& on = d["state"]["on_table"];
             for (std::size_t i = 0; i < on.size(); ++i)
                 if (on[i] == 8) on.erase(i);
             d["state"]["positions"].erase("8");
         },
         "session.state.on_table", "8 must be on the table"},
        {"bad table", [](json& d) { d["config"]["table"]["corner_mouth"] = 0.01; },
         "session.config.table", ""},
        {"bad parameter", [](json& d) { d["config"]["params"]["e_ball"] = 1.5; },
         "session.config.params.e_ball", "out of range"},
        {"empty name", [](json& d) { d["config"]["players"]["B"] = ""; },
         "session.config.players.B", "name"},
        {"winner without an end", [](json& d) { d["winner"] = "A"; }, "session.winner", ""},
        {"verdict inconsistent",
         [](json& d) { d["history"][0]["verdict"]["foul"] = !d["history"][0]["verdict"]["foul"]; },
         "session.history[0].verdict.foul", ""},
        {"choice never offered", [](json& d) { d["history"][0]["choice"] = "pass_back"; },
         "session.history[0].choice", "not offered"},
        {"stroke out of range", [](json& d) { d["history"][0]["stroke"]["speed"] = 50; },
         "session.history[0].stroke.speed", "out of range"},
        {"events where none are kept", [](json& d) { d["history"][0]["events"] = json::array(); },
         "session.history[0].events", "unknown field"},
        {"foreign document",
         [](json& d) { d = json::parse(R"({"balls": [{"id": 0, "pos": [0.5, 0.5]}]})"); },
         "session.format", "not a Coolaaber session"},
        {"newer version", [](json& d) { d["version"] = 2; }, "session.version", "not supported"},
        {"not an object",
         [](json& d) {
             d = json::array({1, 2});
         },
         "session", "expected a JSON object"},
    };
    for (const Corrupt& c : cases) {
        json doc = valid;
        c.edit(doc);
        const std::string error = load_error(doc.dump());
        EXPECT_EQ(error.rfind(c.path, 0), 0u) << c.name << ": " << error;
        EXPECT_NE(error.find(c.message), std::string::npos) << c.name << ": " << error;
    }
}

// A game played to its end by random players.
Session finished(rules::Game game) {
    Session s(config_for(game, 21));
    RandomPlayer a(5), b(6);
    play_shots(s, a, b, 2000);
    EXPECT_EQ(s.phase(), Phase::game_over);
    return s;
}

TEST(SaveLoad, TheWinnerMustBeTheOneTheLastShotGave) {
    const json valid = json::parse(finished(rules::Game::nine_ball).to_json());
    ASSERT_TRUE(valid["winner"].is_string());
    json no_winner = valid;
    no_winner["winner"] = nullptr;
    EXPECT_EQ(load_error(no_winner.dump()).rfind("session.winner: ", 0), 0u)
        << load_error(no_winner.dump());
    json other = valid;
    other["winner"] = valid["winner"] == "A" ? "B" : "A";
    EXPECT_EQ(load_error(other.dump()).rfind("session.winner: ", 0), 0u)
        << load_error(other.dump());
    EXPECT_EQ(load_error(valid.dump()), "(loaded)");
}

TEST(SaveLoad, MalformedText) {
    const std::string valid = in_progress().to_json();
    EXPECT_EQ(load_error("").rfind("session: not valid JSON", 0), 0u);
    EXPECT_EQ(load_error(valid.substr(0, valid.size() / 2)).rfind("session: not valid JSON", 0),
              0u);
    EXPECT_EQ(load_error("{\"format\": \"coolaaber-session\"} trailing").rfind("session:", 0), 0u);
    // A key given twice: nlohmann would keep the last one silently.
    std::string twice = valid;
    twice.insert(1, "\"game_number\":0,");
    EXPECT_EQ(load_error(twice).rfind("session.game_number: field given twice", 0), 0u)
        << load_error(twice);
}

TEST(SaveLoad, SaveAndLoadFiles) {
    const fs::path dir = fresh_dir();
    const fs::path file = dir / "game.json";
    const Session s = in_progress();
    s.save_file(file);
    EXPECT_EQ(slurp(file), s.to_json());
    EXPECT_EQ(Session::load_file(file).to_json(), s.to_json());
    EXPECT_EQ(listing(dir), std::vector<fs::path>{"game.json"});
}

TEST(SaveLoad, LoadNeverModifiesTheFile) {
    const fs::path dir = fresh_dir();
    const fs::path good = dir / "good.json", bad = dir / "bad.json";
    in_progress().save_file(good);
    std::string corrupt = slurp(good);
    corrupt[corrupt.size() / 2] = '#';
    write(bad, corrupt);
    const auto good_time = fs::last_write_time(good), bad_time = fs::last_write_time(bad);
    const std::string good_text = slurp(good);

    (void)Session::load_file(good);
    EXPECT_THROW((void)Session::load_file(bad), LoadError);
    EXPECT_EQ(slurp(good), good_text);
    EXPECT_EQ(slurp(bad), corrupt);
    EXPECT_EQ(fs::last_write_time(good), good_time);
    EXPECT_EQ(fs::last_write_time(bad), bad_time);
    EXPECT_EQ(listing(dir), (std::vector<fs::path>{"bad.json", "good.json"}));

    try {
        (void)Session::load_file(dir / "missing.json");
        FAIL();
    } catch (const LoadError& e) {
        EXPECT_EQ(e.path(), (dir / "missing.json").string());
    }
    EXPECT_THROW((void)Session::load_file(dir), LoadError);
    EXPECT_FALSE(fs::exists(dir / "missing.json"));
}

TEST(SaveLoad, SaveReplacesAtomically) {
    const fs::path dir = fresh_dir();
    const fs::path file = dir / "game.json";
    const Session first = in_progress();
    Session second = first;
    second.restart();
    first.save_file(file);
    second.save_file(file);
    EXPECT_EQ(slurp(file), second.to_json());
    EXPECT_EQ(listing(dir), std::vector<fs::path>{"game.json"});  // no temporary file left

    // A save that cannot complete leaves what was there untouched, and no temporary file.
    const fs::path occupied = dir / "occupied";
    fs::create_directories(occupied / "inside");
    EXPECT_THROW(first.save_file(occupied), std::runtime_error);
    EXPECT_TRUE(fs::is_directory(occupied / "inside"));
    EXPECT_THROW(first.save_file(dir / "no-such-dir" / "game.json"), std::runtime_error);
    EXPECT_EQ(listing(dir), (std::vector<fs::path>{"game.json", "occupied"}));
    EXPECT_EQ(slurp(file), second.to_json());
}

TEST(SaveLoad, SavingThroughALinkKeepsTheLink) {
    const fs::path dir = fresh_dir();
    fs::create_directories(dir / "dotfiles");
    const fs::path real = dir / "dotfiles" / "game.json", link = dir / "game.json";
    fs::create_symlink(real, link);
    const Session s = in_progress();
    s.save_file(link);
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(slurp(real), s.to_json());
    EXPECT_EQ(listing(dir / "dotfiles"), std::vector<fs::path>{"game.json"});
}

TEST(SaveLoad, AFifoIsNeitherReadNorReplaced) {
    const fs::path dir = fresh_dir();
    const fs::path fifo = dir / "game.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Without a writer: opening it to read must not wait for one.
    try {
        (void)Session::load_file(fifo);
        FAIL();
    } catch (const LoadError& e) {
        EXPECT_EQ(e.path(), fifo.string());
        EXPECT_EQ(e.detail().rfind("is a FIFO (named pipe), not a regular file", 0), 0u)
            << e.detail();
    }
    EXPECT_THROW(in_progress().save_file(fifo), std::runtime_error);
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_EQ(listing(dir), std::vector<fs::path>{"game.json"});
}

}  // namespace
}  // namespace game::test
