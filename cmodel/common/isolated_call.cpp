#include "common/isolated_call.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

// A sanitizer's (or libFuzzer's) death callback: present only in sanitized builds (weak).
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace cig {

namespace {

// A sanitizer's shadow memory takes terabytes of address space, so an address-space limit would
// fail every allocation; under ASan the time limit and the result cap still hold.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressLimit = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
constexpr bool kAddressLimit = false;
#else
constexpr bool kAddressLimit = true;
#endif
#else
constexpr bool kAddressLimit = true;
#endif

// Bytes of address space this process has mapped (/proc/self/statm's first field, in pages).
unsigned long long mapped_bytes() {
  FILE* f = std::fopen("/proc/self/statm", "r");
  unsigned long long pages = 0;
  if (f) {
    if (std::fscanf(f, "%llu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return pages * static_cast<unsigned long long>(sysconf(_SC_PAGESIZE));
}

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= std::size_t(w);
  }
  return true;
}

// The child: default signal dispositions (a crash ends it instead of running the parent's
// handlers, libFuzzer's among them), no death callback, the limits, the work, and a status byte
// before the result.
[[noreturn]] void child(int fd, const std::function<std::string()>& work, const IsolationLimits& limits,
                        unsigned long long address_limit) {
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM, SIGTERM, SIGPIPE}) std::signal(sig, SIG_DFL);
  // Under libFuzzer a sanitizer report in the child would run the fuzzer's death callback there,
  // which writes the input as a crash of the fuzz target; the parent reports the child's end instead.
  if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
  const rlim_t cpu = rlim_t(limits.seconds) + 1;
  const rlimit cpu_limit{cpu, cpu};
  setrlimit(RLIMIT_CPU, &cpu_limit);
  if (address_limit > 0) {
    const rlimit as_limit{rlim_t(address_limit), rlim_t(address_limit)};
    setrlimit(RLIMIT_AS, &as_limit);
  }
  char status = 'E';
  std::string out;
  try {
    out = work();
    status = 'K';
  } catch (const std::bad_alloc&) {
    out = "ran out of memory";
    status = 'M';
  } catch (const std::exception& e) { out = e.what(); } catch (...) {
    out = "unknown exception";
  }
  const bool done = write_all(fd, &status, 1) && write_all(fd, out.data(), out.size());
  ::_exit(done ? 0 : 3);  // no atexit handlers or destructors of the parent's objects
}

std::string signal_words(int sig) {
  const char* name = sigabbrev_np(sig);
  return "crashed (signal " + std::to_string(sig) + (name ? std::string(", SIG") + name : std::string()) + ")";
}

// Reads the child's output until it closes the pipe or the deadline passes; false on timeout.
bool read_until(int fd, std::chrono::steady_clock::time_point deadline, std::size_t cap, std::string& bytes,
                bool& too_big) {
  char buf[1 << 16];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int r = ::poll(&p, 1, int(std::min<long long>(left.count(), 1 << 30)));
    if (r < 0 && errno == EINTR) continue;
    if (r == 0) return false;
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    if (bytes.size() + std::size_t(n) > cap) {
      too_big = true;
      return true;
    }
    bytes.append(buf, std::size_t(n));
  }
}

}  // namespace

bool address_space_limited() { return kAddressLimit; }

IsolatedResult run_isolated(const std::function<std::string()>& work, const IsolationLimits& limits) {
  IsolatedResult res;
  int fds[2];
  if (::pipe(fds) != 0) {
    res.reason = std::string("could not make a pipe: ") + std::strerror(errno);
    return res;
  }
  const unsigned long long address_limit = kAddressLimit ? mapped_bytes() + limits.extra_address_bytes : 0;
  std::fflush(nullptr);  // no buffered output written twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    res.reason = std::string("could not start a process: ") + std::strerror(errno);
    return res;
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], work, limits, address_limit);
  }
  ::close(fds[1]);
  const auto deadline =
      std::chrono::steady_clock::now() +
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(limits.seconds));
  std::string bytes;
  bool too_big = false;
  const bool finished = read_until(fds[0], deadline, limits.max_result_bytes + 1, bytes, too_big);
  ::close(fds[0]);
  if (!finished || too_big) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if (!finished) {
    char secs[32];
    std::snprintf(secs, sizeof secs, "%g", limits.seconds);
    res.reason = std::string("took more than ") + secs + " s and was stopped";
  } else if (too_big) {
    res.reason = "gave a result larger than " + std::to_string(limits.max_result_bytes >> 20) + " MiB";
  } else if (WIFSIGNALED(status)) {
    res.reason = WTERMSIG(status) == SIGXCPU ? "used more than its CPU time" : signal_words(WTERMSIG(status));
    if (WTERMSIG(status) == SIGKILL) res.reason += " (likely out of memory)";
  } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty()) {
    res.reason = "ended without a result (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  } else if (bytes[0] != 'K') {
    res.reason = bytes[0] == 'M' ? "ran out of memory (limit " + std::to_string(limits.extra_address_bytes >> 20) +
                                       " MiB more than the parent's)"
                                 : "threw";
    res.bytes = bytes.substr(1);
  } else {
    res.ok = true;
    res.bytes = bytes.substr(1);
  }
  return res;
}

}  // namespace cig
