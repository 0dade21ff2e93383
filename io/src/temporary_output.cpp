#include "ceilplan/io/temporary_output.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"

#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>

namespace ceilplan::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kStagingInfix = ".tmp-ceilplan-";
constexpr std::size_t kStagingSuffixLength = 6;  // mkdtemp's XXXXXX

// The temporaries to remove on a signal. The cleanup thread takes the lock and never gives it
// back, so no commit can rename a temporary after the cleanup has looked for it.
std::mutex& registryMutex() {
  static std::mutex mutex;
  return mutex;
}

// Each registered temporary, with the final path it will take, its staging directory and the
// parent directories created for it (deepest first).
struct Registered {
  fs::path final_path;
  fs::path staging;
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
  sigaddset(&signals, SIGHUP);  // the terminal closed
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
      fs::remove_all(registered.staging, ignored);
      for (const fs::path& parent : registered.created_parents) fs::remove(parent, ignored);  // only if still empty
      left |= fs::exists(registered.staging, ignored);
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

std::string firstLineOf(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// A process's start time (clock ticks after boot, /proc/PID/stat's field 22): with the boot's id
// it tells a live owner from a later process given the same id (PID 1 in every container).
std::string startTimeOf(const std::string& pid) {
  const std::string stat = firstLineOf("/proc/" + pid + "/stat");
  const auto name_end = stat.rfind(')');
  if (name_end == std::string::npos) return {};
  std::istringstream fields(stat.substr(name_end + 1));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i) {  // fields 3 (state) to 22 (starttime)
  }
  return field;
}

std::string bootId() { return firstLineOf("/proc/sys/kernel/random/boot_id"); }

// "PID START BOOT" of this process.
std::string ownerRecord() {
  const std::string pid = std::to_string(::getpid());
  return pid + ' ' + startTimeOf(pid) + ' ' + bootId();
}

// Whether the process that wrote `record` is gone: another boot, no such process, or one that
// started at another time. A record that cannot be read counts as alive (left alone).
bool ownerGone(const std::string& record) {
  std::istringstream fields(record);
  std::string pid, start, boot;
  if (!(fields >> pid >> start >> boot) || pid.find_first_not_of("0123456789") != std::string::npos) return false;
  if (boot != bootId()) return true;
  const std::string now = startTimeOf(pid);
  return now.empty() || now != start;
}

fs::path ownerFile(const fs::path& staging, const fs::path& name) { return staging / (name.string() + ".owner"); }
fs::path previousOf(const fs::path& staging, const fs::path& name) { return staging / (name.string() + ".previous"); }

bool presentNoFollow(const fs::path& path) {
  struct stat status {};
  return ::lstat(path.c_str(), &status) == 0;
}

// Staging directories of `final_path` left by killed runs: removed, after putting back an old
// output the run had moved aside and not yet replaced. Under the registry's lock.
void removeStaleStaging(const fs::path& final_path) {
  const fs::path parent = final_path.has_parent_path() ? final_path.parent_path() : fs::path(".");
  const fs::path name = final_path.filename();
  const std::string prefix = name.string() + kStagingInfix;
  std::error_code ec;
  for (auto entry = fs::directory_iterator(parent, ec); !ec && entry != fs::directory_iterator(); entry.increment(ec)) {
    const std::string entry_name = entry->path().filename().string();
    if (entry_name.size() != prefix.size() + kStagingSuffixLength || entry_name.rfind(prefix, 0) != 0) continue;
    std::error_code kind_error;
    if (!entry->is_directory(kind_error) || entry->is_symlink(kind_error)) continue;
    if (!ownerGone(firstLineOf(ownerFile(entry->path(), name)))) continue;
    std::error_code ignored;
    const fs::path previous = previousOf(entry->path(), name);
    if (presentNoFollow(previous) && !presentNoFollow(final_path)) fs::rename(previous, final_path, ignored);
    fs::remove_all(entry->path(), ignored);
  }
}

std::string shown(const fs::path& path) { return printableText(finalPathOf(path).string(), 256); }

}  // namespace

void installSignalCleanup() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    const sigset_t signals = cleanupSignals();
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::thread(removeTemporariesOnSignal, signals).detach();
  });
}

fs::path renameablePath(const fs::path& path) {
  const fs::path name = path.filename();
  if (!name.empty() && name != "." && name != "..") return path;
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec).lexically_normal();
  if (absolute.filename().empty() && absolute.has_relative_path()) absolute = absolute.parent_path();
  return absolute;
}

fs::path finalPathOf(const fs::path& path) {
  const std::lock_guard<std::mutex> lock(registryMutex());
  fs::path mapped = path;
  // A temporary may lie inside another (a file staged inside a staged directory): map outwards.
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [temporary, registered] : registry()) {
      const fs::path inside = mapped.lexically_relative(temporary);
      if (!inside.empty() && *inside.begin() != "..") {
        mapped = inside == "." ? registered.final_path : registered.final_path / inside;
        changed = true;
        break;
      }
    }
  }
  return mapped;
}

TemporaryOutput::TemporaryOutput(fs::path final_path, bool directory) : final_(renameablePath(final_path)) {
  // Names for messages, before the lock (finalPathOf takes it).
  const std::string display = shown(final_), parent_display = shown(final_.parent_path());
  // Under the lock: once the signal cleanup has begun, nothing more is created on disk.
  const std::lock_guard<std::mutex> lock(registryMutex());
  std::error_code ec;
  for (fs::path parent = final_.parent_path(); !parent.empty() && !fs::exists(parent, ec);
       parent = parent.parent_path())
    created_parents_.push_back(parent);
  const auto fail = [&](const std::string& what, int error) {
    std::error_code ignored;
    if (!staging_.empty()) fs::remove_all(staging_, ignored);
    for (const fs::path& parent : created_parents_) fs::remove(parent, ignored);
    throw ceilplan::Error("cannot " + what + ": " + std::generic_category().message(error));
  };
  if (final_.has_parent_path()) {
    fs::create_directories(final_.parent_path(), ec);
    if (ec) fail("create directory " + parent_display, ec.value());
  }
  removeStaleStaging(final_);
  std::string name = final_.string() + kStagingInfix + std::string(kStagingSuffixLength, 'X');
  if (::mkdtemp(name.data()) == nullptr) fail("stage " + display, errno);
  staging_ = name;
  temporary_ = staging_ / final_.filename();
  {
    std::ofstream owner(ownerFile(staging_, final_.filename()));
    owner << ownerRecord() << '\n';
    if (!owner.flush()) fail("stage " + display, errno != 0 ? errno : EIO);
  }
  if (directory && !fs::create_directory(temporary_, ec)) fail("stage " + display, ec.value());
  registry().emplace(temporary_, Registered{final_, staging_, created_parents_});
}

TemporaryOutput::~TemporaryOutput() {
  const std::lock_guard<std::mutex> lock(registryMutex());
  registry().erase(temporary_);
  std::error_code ignored;
  fs::remove_all(staging_, ignored);  // after a commit, the old output moved aside
  if (!committed_)
    for (const fs::path& parent : created_parents_) fs::remove(parent, ignored);  // only if still empty
}

void TemporaryOutput::commitAll(const std::vector<TemporaryOutput*>& outputs) {
  std::unique_lock<std::mutex> lock(registryMutex());
  struct Step {
    TemporaryOutput* output;
    bool moved_aside = false;
    bool moved_in = false;
  };
  std::vector<Step> steps;
  for (TemporaryOutput* output : outputs) steps.push_back({output});
  for (Step& step : steps) {
    TemporaryOutput& o = *step.output;
    const fs::path previous = previousOf(o.staging_, o.final_.filename());
    std::error_code ec;
    if (presentNoFollow(o.final_)) {
      fs::rename(o.final_, previous, ec);
      step.moved_aside = !ec;
    }
    if (!ec) {
      fs::rename(o.temporary_, o.final_, ec);
      step.moved_in = !ec;
    }
    if (!ec) continue;
    // Back as it was, newest first; then the staging directories go with the destructors.
    std::error_code ignored;
    for (auto done = steps.rbegin(); done != steps.rend(); ++done) {
      TemporaryOutput& back = *done->output;
      if (done->moved_in) fs::rename(back.final_, back.temporary_, ignored);
      if (done->moved_aside) fs::rename(previousOf(back.staging_, back.final_.filename()), back.final_, ignored);
    }
    lock.unlock();  // finalPathOf takes it
    throw ceilplan::Error("cannot write " + shown(o.final_) + ": " + ec.message());
  }
  for (Step& step : steps) {
    step.output->committed_ = true;
    registry().erase(step.output->temporary_);
  }
  // The old outputs go only now, with their staging directories.
  std::error_code ignored;
  for (Step& step : steps) fs::remove_all(step.output->staging_, ignored);
}

}  // namespace ceilplan::io
