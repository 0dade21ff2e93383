#pragma once
// Open3D reports why a read failed through its global logger (to stdout by default). This
// captures those messages for the duration of one read, so the library stays quiet and the
// error can say what Open3D found. Private to the io module.

#include <functional>
#include <mutex>
#include <optional>
#include <string>

namespace ceilplan::io::detail {

class Open3dMessages {
 public:
  Open3dMessages();   // starts capturing; one capture at a time in the process
  ~Open3dMessages();  // restores Open3D's printing
  Open3dMessages(const Open3dMessages&) = delete;
  Open3dMessages& operator=(const Open3dMessages&) = delete;

  // The captured messages joined by "; ", without Open3D's prefixes and colours.
  const std::string& text() const { return text_; }

 private:
  std::unique_lock<std::mutex> lock_;
  std::string text_;
};

// Runs one Open3D read (returning Open3D's success flag) while capturing its messages: nothing
// on success, else what Open3D said (possibly empty). Open3D errors thrown as exceptions count
// as failures too.
std::optional<std::string> failureOf(const std::function<bool()>& read);

}  // namespace ceilplan::io::detail
