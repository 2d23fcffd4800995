// The JSON input layer: paths in error messages, duplicate fields, numbers.
#include "cli/json_in.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/json_out.hpp"

namespace {

std::string error_of(const std::string& text) {
    try {
        cli::parse_document(text);
    } catch (const cli::BadInput& e) {
        return e.what();
    }
    return "";
}

TEST(ParseDocument, DuplicateFieldIsNamedByItsPath) {
    EXPECT_EQ(error_of(R"({"a": 1, "a": 2})").rfind("a: ", 0), 0u);
    EXPECT_EQ(error_of(R"({"balls": [{"id": 0}, {"id": 1, "pos": [], "id": 2}]})")
                  .rfind("balls[1].id: ", 0),
              0u)
        << error_of(R"({"balls": [{"id": 0}, {"id": 1, "pos": [], "id": 2}]})");
    EXPECT_EQ(error_of(R"({"x": [1, [2, 3], {"k": {"z": 1, "z": 1}}]})").rfind("x[2].k.z: ", 0), 0u)
        << error_of(R"({"x": [1, [2, 3], {"k": {"z": 1, "z": 1}}]})");
    // The same key in different objects is fine.
    EXPECT_EQ(error_of(R"({"a": {"k": 1}, "b": {"k": 1}, "c": [{"k": 1}, {"k": 2}]})"), "");
}

TEST(ParseDocument, MalformedAndOverflowingDocumentsAreBadInput) {
    EXPECT_EQ(error_of("{").rfind("input: not valid JSON", 0), 0u);
    EXPECT_EQ(error_of("[1e999]").rfind("input: ", 0), 0u);
    EXPECT_EQ(error_of("\"\\ud800\"").rfind("input: ", 0), 0u);
    EXPECT_EQ(error_of("{\"a\":\n\n 1,}").find('\n'), std::string::npos);
}

TEST(ParseDocument, DeepNestingIsBadInputNotACrash) {
    std::string deep(100000, '[');
    deep += std::string(100000, ']');
    EXPECT_EQ(error_of(deep).rfind("[0][0]", 0), 0u) << error_of(deep);
    EXPECT_NE(error_of(deep).find("nested more than 64 levels"), std::string::npos);
}

TEST(JsonIn, PathsOfNestedValues) {
    nlohmann::json doc = nlohmann::json::parse(R"({"balls": [{"pos": [1, "x"]}]})");
    cli::JsonIn root(doc, "");
    try {
        root.at("balls").at(std::size_t{0}).at("pos").at(std::size_t{1}).number();
        FAIL();
    } catch (const cli::BadInput& e) {
        EXPECT_EQ(e.path(), "balls[0].pos[1]");
        EXPECT_EQ(std::string(e.what()), "balls[0].pos[1]: expected a number, got a string");
    }
    try {
        root.expect_object({"table"});
        FAIL();
    } catch (const cli::BadInput& e) {
        EXPECT_EQ(e.path(), "balls");
    }
    try {
        cli::JsonIn(nlohmann::json(3), "").expect_object({});
        FAIL();
    } catch (const cli::BadInput& e) {
        EXPECT_EQ(e.path(), "input");
    }
}

TEST(JsonIn, IntegersAndRanges) {
    nlohmann::json doc = nlohmann::json::parse(R"([3.0, 3.5, 18446744073709551615, 0.5])");
    cli::JsonIn a(doc, "a");
    EXPECT_EQ(a.at(std::size_t{0}).integer(), 3);
    EXPECT_THROW(a.at(std::size_t{1}).integer(), cli::BadInput);
    EXPECT_THROW(a.at(std::size_t{2}).integer(), cli::BadInput);
    EXPECT_EQ(a.at(std::size_t{3}).positive_up_to(1.0), 0.5);
    EXPECT_THROW(a.at(std::size_t{3}).positive_up_to(0.25), cli::BadInput);
}

TEST(WriteDocument, NegativeZeroIsWrittenAsZero) {
    nlohmann::ordered_json doc = {{"a", -0.0}, {"b", {-0.0, 1.5}}};
    EXPECT_EQ(cli::write_document(doc, false), "{\"a\":0.0,\"b\":[0.0,1.5]}\n");
}

TEST(WriteDocument, DoublesRoundTrip) {
    nlohmann::ordered_json doc = {0.1 + 0.2, 1.0 / 3.0, 2.5e-300, 123456.789};
    std::string text = cli::write_document(doc, false);
    nlohmann::json back = nlohmann::json::parse(text);
    for (std::size_t i = 0; i < doc.size(); ++i)
        EXPECT_EQ(back[i].get<double>(), doc[i].get<double>());
}

TEST(WriteDocument, NonFiniteNumberIsAnInternalErrorWithItsPath) {
    nlohmann::ordered_json doc = {{"events", {{{"pos", {1.0, std::nan("")}}}}}};
    try {
        cli::write_document(doc, false);
        FAIL();
    } catch (const cli::InternalError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("events[0].pos[1]: ", 0), 0u) << e.what();
    }
}

}  // namespace
