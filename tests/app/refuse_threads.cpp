// Preloaded (LD_PRELOAD) into `ceilplan` by test_thread_limits: pthread_create refuses with
// EAGAIN, as under a low ulimit -u or a container's pids.max, once CEILPLAN_TEST_THREADS_ALLOWED
// threads have started, and appends a byte to CEILPLAN_TEST_REFUSALS_FILE for each refusal.
// pthread.h is not included: its declaration of pthread_create would clash with this one.
#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>

namespace {

using PthreadCreate = int (*)(unsigned long*, const void*, void* (*)(void*), void*);
std::atomic<long> started{0};

}  // namespace

extern "C" int pthread_create(unsigned long* thread, const void* attributes, void* (*start)(void*), void* argument) {
  const char* allowed = std::getenv("CEILPLAN_TEST_THREADS_ALLOWED");
  if (allowed && started >= std::atol(allowed)) {
    if (const char* refusals = std::getenv("CEILPLAN_TEST_REFUSALS_FILE")) {
      const int fd = ::open(refusals, O_WRONLY | O_APPEND | O_CREAT, 0644);
      if (fd >= 0) {
        [[maybe_unused]] const ssize_t written = ::write(fd, "x", 1);
        ::close(fd);
      }
    }
    return EAGAIN;
  }
  static const auto real = reinterpret_cast<PthreadCreate>(::dlsym(RTLD_NEXT, "pthread_create"));
  const int result = real(thread, attributes, start, argument);
  if (result == 0) ++started;
  return result;
}
