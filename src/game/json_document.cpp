// Parsing a document into nlohmann::json with our own SAX handler: it builds the value in one
// pass (nlohmann's callback parser rescans the parent array at each object's end, quadratic in
// the array's length), reports a key given twice by its path (nlohmann would keep the last one
// silently), and refuses a document deeper or larger than the limits.
#include <fmt/format.h>

#include <optional>
#include <string>
#include <vector>

#include "game/json_field.hpp"

namespace game {

namespace {

using nlohmann::json;

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    return s;
}

// nlohmann's SAX interface (json::sax_parse); every callback returns true, errors throw.
class DocumentBuilder {
  public:
    explicit DocumentBuilder(std::string root) : root_(std::move(root)) {}

    json take() { return std::move(document_); }

    bool null() { return add(nullptr); }
    bool boolean(bool v) { return add(v); }
    bool number_integer(json::number_integer_t v) { return add(v); }
    bool number_unsigned(json::number_unsigned_t v) { return add(v); }
    bool number_float(json::number_float_t v, const json::string_t& /*text*/) { return add(v); }
    bool string(json::string_t& v) { return add(std::move(v)); }
    bool binary(json::binary_t& v) { return add(std::move(v)); }
    bool start_object(std::size_t /*size*/) { return open(json::value_t::object); }
    bool start_array(std::size_t /*size*/) { return open(json::value_t::array); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(json::string_t& k) {
        Frame& f = open_.back();
        if (f.value->contains(k))
            throw LoadError(path_to(k), "field given twice in one object: keep only one of them");
        f.key = std::move(k);
        return true;
    }

    bool parse_error(std::size_t /*position*/, const std::string& /*token*/,
                     const json::exception& e) {
        const std::string what = e.what();
        if (e.id == 406) {  // a number beyond a double, e.g. 1e400
            const auto pos = what.find("] ");
            throw LoadError(
                root_, one_line(fmt::format("not a usable JSON document ({}); use finite numbers",
                                            what.substr(pos == std::string::npos ? 0 : pos + 2))));
        }
        const auto pos = what.find("parse error");
        throw LoadError(root_,
                        one_line(fmt::format("not valid JSON ({}); check the document's "
                                             "syntax",
                                             what.substr(pos == std::string::npos ? 0 : pos))));
    }

  private:
    // An array or object being read; `key` is the last key read in an object.
    struct Frame {
        json* value;
        std::string key;
    };

    // Puts `v` where the parser is: the document, the next element of an array or the value of
    // the last key of an object. Returns where it went.
    json* place(json&& v) {
        if (open_.empty()) {
            document_ = std::move(v);
            return &document_;
        }
        Frame& f = open_.back();
        if (f.value->is_array()) {
            auto& array = f.value->get_ref<json::array_t&>();
            array.push_back(std::move(v));
            return &array.back();
        }
        auto& object = f.value->get_ref<json::object_t&>();
        return &object.emplace(f.key, std::move(v)).first->second;
    }

    bool add(json&& v) {
        place(std::move(v));
        return true;
    }

    bool open(json::value_t type) {
        if (open_.size() >= max_document_depth)
            throw LoadError(path_to(std::nullopt),
                            fmt::format("nested more than {} levels deep: a document holds at "
                                        "most {} arrays and objects one in another",
                                        max_document_depth, max_document_depth));
        open_.push_back({place(json(type)), {}});
        return true;
    }

    bool close() {
        open_.pop_back();
        return true;
    }

    // The path of the value being read: `key` in the innermost object, or the next element of
    // the innermost array (built only for an error message).
    std::string path_to(const std::optional<std::string>& key) const {
        std::string p = root_;
        for (std::size_t i = 0; i < open_.size(); ++i) {
            const Frame& f = open_[i];
            const bool innermost = i + 1 == open_.size();
            if (f.value->is_object()) {
                const std::string& k = innermost && key ? *key : f.key;
                p += p.empty() ? k : "." + k;
            } else {
                // The element being read is the last one placed, or the next one.
                const std::size_t n = f.value->size();
                p += fmt::format("[{}]", innermost ? n : n - 1);
            }
        }
        return p;
    }

    std::string root_;
    json document_;
    std::vector<Frame> open_;
};

}  // namespace

json parse_document(std::string_view text, const std::string& root) {
    if (text.size() > max_document_bytes)
        throw LoadError(
            root, fmt::format("the document is {} bytes: at most {} ({} MiB) are read", text.size(),
                              max_document_bytes, max_document_bytes >> 20));
    // nlohmann's lexer takes a NUL byte for the end of the text and would ignore what follows.
    if (const auto nul = text.find('\0'); nul != std::string_view::npos)
        throw LoadError(root, fmt::format("a NUL byte at offset {}: JSON text has none (is this a "
                                          "binary file?)",
                                          nul));
    DocumentBuilder builder(root);
    json::sax_parse(text.begin(), text.end(), &builder, json::input_format_t::json, true);
    return builder.take();
}

}  // namespace game
