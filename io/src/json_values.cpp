#include "ceilplan/io/json_values.hpp"

#include "ceilplan/io/atomic_file.hpp"

namespace ceilplan::io {
namespace {

template <class Json>
void writeIndented(const std::filesystem::path& file, const Json& json) {
  writeTextAtomically(file, [&](std::ostream& out) { out << json.dump(2) << '\n'; });
}

}  // namespace

void writeJsonFile(const std::filesystem::path& file, const nlohmann::json& json) { writeIndented(file, json); }

void writeJsonFile(const std::filesystem::path& file, const nlohmann::ordered_json& json) { writeIndented(file, json); }

}  // namespace ceilplan::io
