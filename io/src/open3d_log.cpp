#include "open3d_log.hpp"

#include <open3d/utility/Logging.h>

#include <unistd.h>

#include <cstdio>
#include <mutex>
#include <regex>

namespace ceilplan::io::detail {
namespace {

std::mutex read_mutex;

// Sends file descriptor 2 to a temporary file until text() restores it.
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    saved_ = file_ ? ::dup(STDERR_FILENO) : -1;
    if (saved_ >= 0) ::dup2(::fileno(file_), STDERR_FILENO);
  }
  ~StderrCapture() { restore(); }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  std::string text() {
    restore();
    std::string captured;
    if (!file_) return captured;
    std::rewind(file_);
    char buffer[512];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file_)) > 0) captured.append(buffer, n);
    std::fclose(file_);
    file_ = nullptr;
    return captured;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

// "\x1b[1;33m[Open3D WARNING] Read PCD failed: ...\x1b[0;m\n" -> "Read PCD failed: ..."
void append(std::string& messages, const std::string& message) {
  static const std::regex decoration("\x1b\\[[0-9;]*m|\\[Open3D [A-Z]+\\] ?");
  std::string line;
  for (std::size_t start = 0; start <= message.size();) {
    const std::size_t end = std::min(message.find('\n', start), message.size());
    line = std::regex_replace(message.substr(start, end - start), decoration, "");
    if (!line.empty()) messages += (messages.empty() ? "" : "; ") + line;
    start = end + 1;
  }
}

}  // namespace

std::optional<std::string> failureOf(const std::function<bool()>& read) {
  const std::lock_guard<std::mutex> lock(read_mutex);
  auto& logger = open3d::utility::Logger::GetInstance();
  logger.SetVerbosityLevel(open3d::utility::VerbosityLevel::Warning);
  std::string logged;
  logger.SetPrintFunction([&logged](const std::string& message) { append(logged, message); });
  bool succeeded = false;
  std::string thrown;
  StderrCapture capture;
  try {
    succeeded = read();
  } catch (const std::exception& e) {  // Open3D's LogError throws
    thrown = e.what();
  }
  const std::string printed = capture.text();
  logger.ResetPrintFunction();
  if (succeeded) return std::nullopt;
  std::string messages;
  append(messages, printed);
  append(messages, logged);
  append(messages, thrown);
  return messages;
}

}  // namespace ceilplan::io::detail
