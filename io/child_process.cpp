#include "io/child_process.h"

#include <fmt/format.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace qm::io {

const char* status_name(ChildStatus status) {
  switch (status) {
    case ChildStatus::ok:
      return "ok";
    case ChildStatus::failed:
      return "failed";
    case ChildStatus::crashed:
      return "crashed";
    case ChildStatus::timeout:
      return "timeout";
  }
  return "failed";
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The child's side of fork() before it runs anything: its own process group, no
/// blocked signals, no core dumps, the address-space limit, stdin from /dev/null,
/// stdout and stderr to the log. Only async-signal-safe calls.
void prepare_child(int log_fd, const char* working_dir, std::uint64_t memory_limit) {
  setpgid(0, 0);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  if (memory_limit > 0 && address_space_limits_work()) {
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0) {
      const rlim_t wanted = static_cast<rlim_t>(memory_limit);
      if (as.rlim_max == RLIM_INFINITY || wanted < as.rlim_max) as.rlim_cur = wanted;
      else as.rlim_cur = as.rlim_max;
      setrlimit(RLIMIT_AS, &as);
    }
  }
  const int null_fd = open("/dev/null", O_RDONLY);
  if (null_fd >= 0) dup2(null_fd, STDIN_FILENO);
  const int out_fd = log_fd >= 0 ? log_fd : open("/dev/null", O_WRONLY);
  if (out_fd >= 0) {
    dup2(out_fd, STDOUT_FILENO);
    dup2(out_fd, STDERR_FILENO);
  }
  if (working_dir != nullptr && chdir(working_dir) != 0) _exit(127);
}

/// The child's side of run_child: prepare, then exec.
[[noreturn]] void become_child(char* const* argv, int log_fd, const char* working_dir,
                               std::uint64_t memory_limit, bool crash_on_purpose, pid_t die_with) {
  prepare_child(log_fd, working_dir, memory_limit);
  if (die_with > 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != die_with) _exit(1);  // the parent ended before the line above
  }
  if (crash_on_purpose) {
    signal(SIGSEGV, SIG_DFL);
    raise(SIGSEGV);
  }
  execvp(argv[0], argv);
  static const char message[] = "could not start the program\n";
  [[maybe_unused]] const auto written = write(STDERR_FILENO, message, sizeof message - 1);
  _exit(127);
}

/// The parent's side: waits for `pid` until it ends or the deadline passes (then
/// SIGKILL to its whole process group) and tells how it ended.
ChildResult wait_for_child(pid_t pid, Clock::time_point start, const ChildOptions& options) {
  ChildResult result;
  setpgid(pid, pid);  // also here, so the group exists whichever side runs first

  int raw = 0;
  bool timed_out = false;
  auto pause = std::chrono::milliseconds(2);
  // a pidfd becomes readable the moment the child ends: no polling delay (where
  // the kernel has none, sleeps growing from 2 to 32 ms between checks)
  const int pidfd = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
  for (;;) {
    const pid_t done = waitpid(pid, &raw, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      result.detail = fmt::format("lost the child process: {}", std::strerror(errno));
      result.seconds = seconds_since(start);
      return result;
    }
    if (options.timeout_seconds > 0 && seconds_since(start) >= options.timeout_seconds) {
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
      while (waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
      }
      timed_out = true;
      break;
    }
    if (pidfd >= 0) {
      int wait_ms = 1000;  // then the deadline is checked again
      if (options.timeout_seconds > 0)
        wait_ms = std::clamp(static_cast<int>(1000 * (options.timeout_seconds - seconds_since(start))) + 1, 1, 1000);
      pollfd ended{pidfd, POLLIN, 0};
      poll(&ended, 1, wait_ms);
      continue;
    }
    std::this_thread::sleep_for(pause);
    if (pause < std::chrono::milliseconds(20)) pause *= 2;
  }
  if (pidfd >= 0) close(pidfd);
  result.seconds = seconds_since(start);

  if (timed_out) {
    result.status = ChildStatus::timeout;
    result.signal = SIGKILL;
    result.detail = fmt::format("no result after {:g} s: killed", options.timeout_seconds);
  } else if (WIFSIGNALED(raw)) {
    result.status = ChildStatus::crashed;
    result.signal = WTERMSIG(raw);
    result.detail =
        fmt::format("killed by signal {} ({})", result.signal, strsignal(result.signal));
  } else if (WIFEXITED(raw)) {
    result.exit_code = WEXITSTATUS(raw);
    result.status = result.exit_code == 0 ? ChildStatus::ok : ChildStatus::failed;
    if (result.exit_code != 0) result.detail = fmt::format("exit status {}", result.exit_code);
  } else {
    result.detail = "ended in an unknown way";
  }
  return result;
}

/// The parent's side of fork(): its copy of the log closed, then the wait, or why
/// no child started.
ChildResult after_fork(pid_t pid, int log_fd, Clock::time_point start, const ChildOptions& options) {
  const int fork_error = errno;
  if (log_fd >= 0) close(log_fd);
  if (pid < 0) {
    ChildResult result;
    result.detail = fmt::format("could not start a process: {}", std::strerror(fork_error));
    return result;
  }
  return wait_for_child(pid, start, options);
}

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options) {
  if (argv.empty()) throw std::invalid_argument("run_child: empty argument list");
  // Everything the child needs is prepared before fork().
  std::vector<std::string> args = argv;
  std::vector<char*> pointers;
  for (std::string& a : args)
    pointers.push_back(a.data());
  pointers.push_back(nullptr);
  int log_fd = -1;
  if (!options.log_path.empty())
    log_fd = open(options.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const char* working_dir = options.working_dir.empty() ? nullptr : options.working_dir.c_str();

  const pid_t die_with = options.die_with_parent ? getpid() : 0;
  const Clock::time_point start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0)
    become_child(pointers.data(), log_fd, working_dir, options.memory_limit_bytes,
                 options.crash_on_purpose, die_with);
  return after_fork(pid, log_fd, start, options);
}

ChildResult run_in_child(const std::function<int()>& body, const ChildOptions& options) {
  int log_fd = -1;
  if (!options.log_path.empty())
    log_fd = open(options.log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const char* working_dir = options.working_dir.empty() ? nullptr : options.working_dir.c_str();
  const pid_t parent = getpid();
  std::fflush(nullptr);  // or the child's exit would print our buffered output again

  const Clock::time_point start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    prepare_child(log_fd, working_dir, options.memory_limit_bytes);
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // no orphan left running if we are killed
    if (getppid() != parent) _exit(1);
    // a fault in the body ends the child by its signal, which the parent reports,
    // whatever handlers this process had (a sanitizer's or a fuzzer's would
    // otherwise turn it into an exit status, or write its own reports)
    for (const int fatal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) signal(fatal, SIG_DFL);
    if (options.crash_on_purpose) raise(SIGSEGV);
    int status = 1;
    try {
      status = body();
    } catch (...) {
    }
    _exit(status);
  }
  return after_fork(pid, log_fd, start, options);
}

std::string own_executable() {
  std::vector<char> buffer(4096);
  const ssize_t n = readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
  if (n <= 0) throw std::runtime_error("cannot find the program's own path (/proc/self/exe)");
  return std::string(buffer.data(), static_cast<std::size_t>(n));
}

}  // namespace qm::io
