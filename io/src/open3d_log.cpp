#include "open3d_log.hpp"

#include <open3d/utility/Logging.h>

#include <regex>

namespace ceilplan::io::detail {
namespace {

std::mutex capture_mutex;

}  // namespace

Open3dMessages::Open3dMessages() : lock_(capture_mutex) {
  auto& logger = open3d::utility::Logger::GetInstance();
  logger.SetVerbosityLevel(open3d::utility::VerbosityLevel::Warning);
  logger.SetPrintFunction([this](const std::string& message) {
    // "\x1b[1;33m[Open3D WARNING] Read PCD failed: ...\x1b[0;m" -> "Read PCD failed: ..."
    static const std::regex decoration("\x1b\\[[0-9;]*m|\\[Open3D [A-Z]+\\] ?|\n");
    const std::string plain = std::regex_replace(message, decoration, "");
    if (plain.empty()) return;
    text_ += (text_.empty() ? "" : "; ") + plain;
  });
}

Open3dMessages::~Open3dMessages() { open3d::utility::Logger::GetInstance().ResetPrintFunction(); }

std::optional<std::string> failureOf(const std::function<bool()>& read) {
  Open3dMessages capture;
  try {
    if (read()) return std::nullopt;
  } catch (const std::exception& e) {  // Open3D's LogError throws
    return std::string(e.what());
  }
  return capture.text();
}

}  // namespace ceilplan::io::detail
