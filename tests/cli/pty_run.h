#pragma once
// Runs a command with stderr on a pseudo-terminal (isatty true) and stdout
// on /dev/null, and returns what it wrote to the terminal.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

namespace tg::test {

struct PtyResult {
  int code = -1;
  std::string err;
};

inline PtyResult runOnPty(const std::string& command) {
  PtyResult r;
  int master = -1, slave = -1;
  if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    ADD_FAILURE() << "openpty failed";
    return r;
  }
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(master);
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(slave, 2);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  ::close(slave);
  // The master reads EIO once the last holder of the slave has gone.
  for (char buf[4096];;) {
    const ssize_t n = ::read(master, buf, sizeof buf);
    if (n <= 0) break;
    r.err.append(buf, std::size_t(n));
  }
  ::close(master);
  int status = 0;
  ::waitpid(pid, &status, 0);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace tg::test
