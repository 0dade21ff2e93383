#include "ceilplan/io/provenance.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/version.hpp"

#include <openssl/evp.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>

namespace ceilplan::io {
namespace {

// A command line or file name may hold line breaks; a provenance field is one line.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

Provenance Provenance::of(std::string command_line) {
  Provenance provenance;
  provenance.version = std::string(kVersion) + " (git " + gitRevision() + ")";
  provenance.command_line = std::move(command_line);
  return provenance;
}

Provenance& Provenance::input(const std::string& role, const std::filesystem::path& path) {
  if (!path.empty()) inputs.push_back({role, path, sha256File(path)});
  return *this;
}

nlohmann::json Provenance::json() const {
  nlohmann::json files = nlohmann::json::array();
  for (const InputFile& file : inputs)
    files.push_back({{"role", file.role}, {"path", file.path.string()}, {"sha256", file.sha256}});
  nlohmann::json out = {{"ceilplan", version}, {"command", command_line}, {"inputs", files}};
  out["seed"] = seed ? nlohmann::json(*seed) : nlohmann::json(nullptr);
  return out;
}

std::vector<std::pair<std::string, std::string>> Provenance::fields() const {
  std::vector<std::pair<std::string, std::string>> out{{"ceilplan", version}, {"command", command_line}};
  if (seed) out.emplace_back("seed", std::to_string(*seed));
  for (const InputFile& file : inputs) {
    out.emplace_back(file.role, file.path.string());
    out.emplace_back(file.role + "_sha256", file.sha256);
  }
  for (auto& field : out) field.second = oneLine(field.second);
  return out;
}

std::string Provenance::csvComment() const { return "# " + line(); }

std::string Provenance::line() const {
  std::string line = "ceilplan " + version + " | " + command_line;
  if (seed) line += " | seed " + std::to_string(*seed);
  for (const InputFile& file : inputs) line += " | " + file.role + " " + file.path.string() + " sha256 " + file.sha256;
  return oneLine(line);
}

nlohmann::json withProvenance(nlohmann::json json, const Provenance& provenance) {
  json["provenance"] = provenance.json();
  return json;
}

nlohmann::ordered_json withProvenance(nlohmann::ordered_json json, const Provenance& provenance) {
  json["provenance"] = nlohmann::ordered_json(provenance.json());
  return json;
}

std::string commandLine(int argc, const char* const* argv) {
  std::string line;
  for (int k = 0; k < argc; ++k) {
    const std::string argument = argv[k];
    const bool plain = !argument.empty() && argument.find_first_of(" \t\n'\"\\$`*?;&|<>(){}") == std::string::npos;
    std::string quoted = "'";
    for (char c : argument) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    quoted += "'";
    line += (k ? " " : "") + (plain ? argument : quoted);
  }
  return line;
}

std::string sha256File(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot be read");
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1) throw Error("SHA-256 is not available");
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    if (in.gcount() > 0) EVP_DigestUpdate(context.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(file.string() + ": cannot be read");
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  EVP_DigestFinal_ex(context.get(), digest.data(), &length);
  std::string hex;
  char byte[3];
  for (unsigned int k = 0; k < length; ++k) {
    std::snprintf(byte, sizeof byte, "%02x", digest[k]);
    hex += byte;
  }
  return hex;
}

}  // namespace ceilplan::io
