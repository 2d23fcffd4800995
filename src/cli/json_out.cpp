#include "cli/json_out.hpp"

#include <fmt/format.h>

#include <cmath>

namespace cli {

nlohmann::ordered_json to_json(physics::Vec2 v) {
    return nlohmann::ordered_json::array({v.x, v.y});
}

nlohmann::ordered_json to_json(physics::Vec3 v) {
    return nlohmann::ordered_json::array({v.x, v.y, v.z});
}

namespace {

// Where a value sits in the document; turned into a path string only for an error message.
struct Where {
    const Where* parent = nullptr;
    const std::string* key = nullptr;  // member of an object, or
    std::size_t index = 0;             // element of an array

    std::string path() const {
        if (!parent) return "output";
        std::string up = parent->parent ? parent->path() : "";
        if (key) return up.empty() ? *key : up + "." + *key;
        return fmt::format("{}[{}]", up, index);
    }
};

template <typename Json>
void normalize_numbers(Json& value, const Where& where) {
    if (value.is_number_float()) {
        double d = value.template get<double>();
        if (!std::isfinite(d))
            throw InternalError(
                fmt::format("{}: the engine produced a non-finite number; please report this input",
                            where.path()));
        if (d == 0.0) value = 0.0;  // -0.0 → 0.0
    } else if (value.is_object()) {
        for (auto it = value.begin(); it != value.end(); ++it) {
            const std::string& key = it.key();
            normalize_numbers(*it, Where{&where, &key, 0});
        }
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            normalize_numbers(value[i], Where{&where, nullptr, i});
    }
}

template <typename Json>
std::string write(Json& doc, bool pretty) {
    normalize_numbers(doc, Where{});
    std::string text = pretty ? doc.dump(2) : doc.dump();
    text += '\n';
    return text;
}

}  // namespace

std::string write_document(nlohmann::ordered_json& doc, bool pretty) {
    return write(doc, pretty);
}
std::string write_document(nlohmann::json& doc, bool pretty) {
    return write(doc, pretty);
}

}  // namespace cli
