#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace unimap::cli {

// run.json's objects (nlohmann-json), keys in insertion order.
using Json = nlohmann::ordered_json;

// Two-space indented text: non-finite numbers are written as null, invalid
// UTF-8 in strings (a path, a message) is replaced instead of throwing.
inline std::string JsonText(const Json& json) { return json.dump(2, ' ', false, Json::error_handler_t::replace); }

}  // namespace unimap::cli
