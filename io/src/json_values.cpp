#include "ceilplan/io/json_values.hpp"

#include "ceilplan/io/atomic_file.hpp"

namespace ceilplan::io {
namespace {

template <class Json>
std::string dumped(const Json& json, int indent) {
  return json.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

template <class Json>
void writeIndented(const std::filesystem::path& file, const Json& json) {
  const std::string text = dumped(json, 2);
  writeTextAtomically(file, [&](std::ostream& out) { out << text << '\n'; });
}

}  // namespace

std::string jsonText(const nlohmann::json& json, int indent) { return dumped(json, indent); }

std::string jsonText(const nlohmann::ordered_json& json, int indent) { return dumped(json, indent); }

void writeJsonFile(const std::filesystem::path& file, const nlohmann::json& json) { writeIndented(file, json); }

void writeJsonFile(const std::filesystem::path& file, const nlohmann::ordered_json& json) { writeIndented(file, json); }

}  // namespace ceilplan::io
