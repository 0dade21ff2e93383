#pragma once
// Real parsers for the exported files, shared by the round-trip tests: zip entries through
// minizip's unzip API, XML through tinyxml2, and lookups of a child element by name.

#include <minizip/unzip.h>
#include <tinyxml2.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace ceilplan::testing {

// Every entry of a zip archive: name -> content. Fails the test on a broken archive.
inline std::map<std::string, std::string> readZip(const std::filesystem::path& file) {
  std::map<std::string, std::string> entries;
  unzFile zip = unzOpen64(file.c_str());
  EXPECT_NE(zip, nullptr) << file;
  if (!zip) return entries;
  for (int status = unzGoToFirstFile(zip); status == UNZ_OK; status = unzGoToNextFile(zip)) {
    char name[512];
    unz_file_info64 info;
    EXPECT_EQ(unzGetCurrentFileInfo64(zip, &info, name, sizeof name, nullptr, 0, nullptr, 0), UNZ_OK);
    EXPECT_EQ(unzOpenCurrentFile(zip), UNZ_OK);
    std::string content(info.uncompressed_size, '\0');
    const int read = unzReadCurrentFile(zip, content.data(), static_cast<unsigned>(content.size()));
    EXPECT_EQ(read, static_cast<int>(content.size())) << name;
    EXPECT_EQ(unzCloseCurrentFile(zip), UNZ_OK) << name << ": CRC check";
    entries[name] = content;
  }
  unzClose(zip);
  return entries;
}

// The children of `parent` named `name`.
inline std::vector<const tinyxml2::XMLElement*> children(const tinyxml2::XMLElement* parent, const char* name) {
  std::vector<const tinyxml2::XMLElement*> found;
  if (!parent) return found;
  for (const tinyxml2::XMLElement* e = parent->FirstChildElement(name); e; e = e->NextSiblingElement(name))
    found.push_back(e);
  return found;
}

// The text of the one child `name` of `parent`; fails the test if it is missing.
inline std::string childText(const tinyxml2::XMLElement* parent, const char* name) {
  const tinyxml2::XMLElement* child = parent ? parent->FirstChildElement(name) : nullptr;
  EXPECT_NE(child, nullptr) << "missing <" << name << "> in <" << (parent ? parent->Name() : "?") << ">";
  return child && child->GetText() ? child->GetText() : "";
}

inline double childNumber(const tinyxml2::XMLElement* parent, const char* name) {
  const std::string text = childText(parent, name);
  return text.empty() ? std::nan("") : std::stod(text);
}

}  // namespace ceilplan::testing
