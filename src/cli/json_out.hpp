// Writing output documents (docs/cli.md): compact or indented, numbers that read back to
// the same double, -0 written as 0, and never a NaN or an infinity (an engine bug, exit 1).
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "physics/vec.hpp"

namespace cli {

/// An output document whose number was not finite: an internal error, not bad input.
class InternalError : public std::logic_error {
  public:
    using std::logic_error::logic_error;
};

/// [x, y] and [x, y, z].
nlohmann::ordered_json to_json(physics::Vec2 v);
nlohmann::ordered_json to_json(physics::Vec3 v);

/// Serializes a document (one line, or indented by 2 when `pretty`), with a final newline.
/// Rewrites -0.0 as 0.0 in place so that output is byte-stable; throws InternalError naming
/// the JSON path of a NaN or infinite number.
std::string write_document(nlohmann::ordered_json& doc, bool pretty);
std::string write_document(nlohmann::json& doc, bool pretty);

}  // namespace cli
