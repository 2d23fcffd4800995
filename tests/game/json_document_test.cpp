// The one JSON reader's parser (game/json_field.hpp): linear time, the limits of a document,
// NUL bytes, duplicate keys by path.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "game/json_field.hpp"

namespace game {
namespace {

std::string error_of(std::string_view text, const std::string& root = "") {
    try {
        (void)parse_document(text, root);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "";
}

std::string array_of_objects(std::size_t n) {
    std::string s = "[";
    for (std::size_t i = 0; i < n; ++i) s += i ? ",{}" : "{}";
    return s + "]";
}

TEST(ParseDocument, AMillionObjectsInOneArrayParseInLinearTime) {
    // nlohmann's callback parser rescans the array at each object's end: minutes here.
    const std::string text = array_of_objects(1'000'000);
    const auto start = std::chrono::steady_clock::now();
    const nlohmann::json doc = parse_document(text, "");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(doc.size(), 1'000'000u);
    EXPECT_LT(seconds, 10.0);
}

TEST(ParseDocument, ANulByteIsRefusedNamingItsOffset) {
    using namespace std::string_literals;
    const std::string text = "{\"balls\":[]}\0{{{{ not json"s;
    EXPECT_EQ(error_of(text),
              "input: a NUL byte at offset 12: JSON text has none (is this a "
              "binary file?)");
    EXPECT_EQ(error_of("\0"s, "session").rfind("session: a NUL byte at offset 0", 0), 0u);
}

TEST(ParseDocument, NestingUpToTheLimitIsRead) {
    const std::string deepest =
        std::string(max_document_depth, '[') + std::string(max_document_depth, ']');
    EXPECT_EQ(error_of(deepest), "");
    const std::string deeper = "[" + deepest + "]";
    EXPECT_NE(error_of(deeper).find("nested more than 64 levels"), std::string::npos);
    // The too-deep value is named by its path: three levels above `deepest`, so its 62nd array.
    std::string path = "settings.a[0].b";
    for (std::size_t k = 0; k < max_document_depth - 3; ++k) path += "[0]";
    EXPECT_EQ(error_of("{\"a\": [{\"b\": " + deepest + "}]}", "settings").rfind(path + ": ", 0), 0u)
        << error_of("{\"a\": [{\"b\": " + deepest + "}]}", "settings");
}

TEST(ParseDocument, ADocumentOverTheSizeLimitIsRefused) {
    const std::string big(max_document_bytes + 1, ' ');
    EXPECT_EQ(error_of(big, "session").rfind("session: the document is 67108865 bytes: at most", 0),
              0u)
        << error_of(big, "session");
    // A document of exactly the limit is read.
    const std::string at_limit = "\"" + std::string(max_document_bytes - 2, ' ') + "\"";
    EXPECT_EQ(error_of(at_limit), "");
}

TEST(ParseDocument, DuplicateKeysAreNamedByTheirPath) {
    EXPECT_EQ(error_of(R"({"a": [1, {"b": 1, "b": 2}]})", "session")
                  .rfind("session.a[1].b: field given twice", 0),
              0u);
    EXPECT_EQ(error_of(R"([[], [{"k": 1}, {"k": 2, "k": 3}]])").rfind("[1][1].k: ", 0), 0u)
        << error_of(R"([[], [{"k": 1}, {"k": 2, "k": 3}]])");
}

TEST(ParseDocument, ValuesAreThoseNlohmannReads) {
    const std::string text =
        R"({"n": null, "t": true, "i": -3, "u": 18446744073709551615, "d": 0.1,)"
        R"( "s": "\u00e9\n", "a": [1, [2, {}]], "o": {"x": {}}})";
    EXPECT_EQ(parse_document(text, ""), nlohmann::json::parse(text));
}

}  // namespace
}  // namespace game
