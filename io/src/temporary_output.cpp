#include "ceilplan/io/temporary_output.hpp"

#include "ceilplan/core/error.hpp"

#include <pthread.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <mutex>
#include <map>
#include <string>
#include <system_error>
#include <thread>

namespace ceilplan::io {
namespace {

namespace fs = std::filesystem;

// The temporaries to remove on a signal. The cleanup thread takes the lock and never gives it
// back, so no commit can rename a temporary after the cleanup has looked for it.
std::mutex& registryMutex() {
  static std::mutex mutex;
  return mutex;
}

// Each registered temporary, with the final path it will take and the parent directories
// created for it (deepest first).
struct Registered {
  fs::path final_path;
  std::vector<fs::path> created_parents;
};

std::map<fs::path, Registered>& registry() {
  static std::map<fs::path, Registered> paths;
  return paths;
}

sigset_t cleanupSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  return signals;
}

[[noreturn]] void removeTemporariesOnSignal(sigset_t signals) {
  int signal_number = 0;
  while (sigwait(&signals, &signal_number) != 0) {
  }
  registryMutex().lock();
  std::error_code ignored;
  // Other threads run on: no new temporary can start (its constructor waits for the lock), but a
  // file of a registered one may be opened while remove_all walks its directory. Walk again.
  for (int pass = 0; pass < 20; ++pass) {
    bool left = false;
    for (const auto& [temporary, registered] : registry()) {
      fs::remove_all(temporary, ignored);
      for (const fs::path& parent : registered.created_parents) fs::remove(parent, ignored);  // only if still empty
      left |= fs::exists(temporary, ignored);
    }
    if (!left) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // End the process the way the signal would have, so the caller sees "killed by SIGINT".
  std::signal(signal_number, SIG_DFL);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, signal_number);
  pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
  std::raise(signal_number);
  _exit(128 + signal_number);  // not reached
}

}  // namespace

void installSignalCleanup() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    const sigset_t signals = cleanupSignals();
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::thread(removeTemporariesOnSignal, signals).detach();
  });
}

fs::path finalPathOf(const fs::path& path) {
  const std::lock_guard<std::mutex> lock(registryMutex());
  for (const auto& [temporary, registered] : registry()) {
    const fs::path inside = path.lexically_relative(temporary);
    if (!inside.empty() && *inside.begin() != "..")
      return inside == "." ? registered.final_path : registered.final_path / inside;
  }
  return path;
}

TemporaryOutput::TemporaryOutput(fs::path final_path, bool directory) : final_(std::move(final_path)) {
  temporary_ = final_;
  temporary_ += ".tmp" + std::to_string(::getpid());
  // Under the lock: once the signal cleanup has begun, nothing more is created on disk.
  const std::lock_guard<std::mutex> lock(registryMutex());
  std::error_code ec;
  for (fs::path parent = final_.parent_path(); !parent.empty() && !fs::exists(parent, ec); parent = parent.parent_path())
    created_parents_.push_back(parent);
  if (final_.has_parent_path()) {
    fs::create_directories(final_.parent_path(), ec);
    if (ec)
      throw ceilplan::Error("cannot create directory " + final_.parent_path().string() + ": " + ec.message());
  }
  if (directory) {
    fs::create_directory(temporary_, ec);
    if (ec) {
      std::error_code ignored;
      for (const fs::path& parent : created_parents_) fs::remove(parent, ignored);
      throw ceilplan::Error("cannot create " + temporary_.string() + ": " + ec.message());
    }
  }
  registry().emplace(temporary_, Registered{final_, created_parents_});
}

TemporaryOutput::~TemporaryOutput() {
  const std::lock_guard<std::mutex> lock(registryMutex());
  registry().erase(temporary_);
  if (!committed_) {
    std::error_code ignored;
    fs::remove_all(temporary_, ignored);
    for (const fs::path& parent : created_parents_) fs::remove(parent, ignored);  // only if still empty
  }
}

void TemporaryOutput::commit() {
  const std::lock_guard<std::mutex> lock(registryMutex());
  std::error_code ec;
  fs::rename(temporary_, final_, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove_all(temporary_, ignored);
    throw ceilplan::Error("cannot write " + final_.string() + ": " + ec.message());
  }
  committed_ = true;
  registry().erase(temporary_);
}

void TemporaryOutput::commitMerging() {
  const std::lock_guard<std::mutex> lock(registryMutex());
  std::error_code ec;
  fs::create_directories(final_, ec);
  for (auto entry = fs::recursive_directory_iterator(temporary_, ec); !ec && entry != fs::recursive_directory_iterator();
       entry.increment(ec)) {
    const fs::path target = final_ / fs::relative(entry->path(), temporary_);
    if (entry->is_directory()) {
      fs::create_directories(target, ec);
    } else {
      fs::rename(entry->path(), target, ec);
    }
    if (ec) break;
  }
  if (ec) {
    std::error_code ignored;
    fs::remove_all(temporary_, ignored);
    throw ceilplan::Error("cannot write into " + final_.string() + ": " + ec.message());
  }
  fs::remove_all(temporary_, ec);
  committed_ = true;
  registry().erase(temporary_);
}

}  // namespace ceilplan::io
