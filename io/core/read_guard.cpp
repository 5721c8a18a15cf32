#include "io/core/read_guard.h"

#include <fcntl.h>
#include <sys/socket.h>
#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <new>
#include <optional>
#include <type_traits>

#include "io/core/guard_wire.h"
#include "io/core/read_progress.h"
#include "io/core/module_loader.h"
#include "io/core/selection.h"

namespace tg::io {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::uint32_t kWireMagic = 0x54474631;  // "TGF1"
// Every member of TensorField crosses the process boundary in writeField and
// readField; a new member changes this size and must be carried there too.
static_assert(sizeof(TensorField) == 648 + sizeof(util::MappedArray<float>) + 3 * sizeof(std::string) + sizeof(std::vector<FrameChoice>), "TensorField changed: carry the new member in writeField/readField");

void writeField(WireOut& w, const TensorField& f) {
  w.pod(kWireMagic);
  for (const std::string* s : {&f.path, &f.description, &f.arrayName, &f.space, &f.lengthUnits, &f.layout, &f.frame,
                               &f.colorArrayName, &f.pointArrays})
    w.str(*s);
  for (const auto* m : {&f.measurementFrame, &f.tensorToWC}) {
    w.pod(m->has_value());
    if (*m) w.pod(**m);
  }
  w.pod(std::uint64_t(f.otherFrames.size()));
  for (const FrameChoice& c : f.otherFrames) {
    w.str(c.name);
    w.pod(c.tensorToWC.has_value());
    if (c.tensorToWC) w.pod(*c.tensorToWC);
  }
  w.pod(f.hasConfidence);
  w.pod(std::uint64_t(f.warnings.size()));
  for (const std::string& s : f.warnings) w.str(s);
  w.array(f.positions);
  w.array(f.tensors);
  w.array(f.ids);
  w.array(f.colorValues);
  for (std::size_t n : {f.totalPoints, f.skippedNonFinite, f.skippedOverflow, f.masked, f.unselected})
    w.pod(std::uint64_t(n));
  w.pod(f.grid.has_value());
  if (f.grid) w.pod(*f.grid);
  w.pod(f.sampleSpacing);
}

TensorField readField(WireIn& r) {
  if (r.pod<std::uint32_t>() != kWireMagic) throw std::runtime_error("the reader's result is malformed");
  TensorField f;
  for (std::string* s : {&f.path, &f.description, &f.arrayName, &f.space, &f.lengthUnits, &f.layout, &f.frame,
                         &f.colorArrayName, &f.pointArrays})
    *s = r.str();
  for (auto* m : {&f.measurementFrame, &f.tensorToWC})
    if (r.pod<bool>()) *m = r.pod<std::array<double, 9>>();
  const auto frames = r.pod<std::uint64_t>();
  for (std::uint64_t k = 0; k < frames && k < 8; ++k) {
    FrameChoice c{r.str(), {}};
    if (r.pod<bool>()) c.tensorToWC = r.pod<std::array<double, 9>>();
    f.otherFrames.push_back(std::move(c));
  }
  f.hasConfidence = r.pod<bool>();
  const auto warnings = r.pod<std::uint64_t>();
  for (std::uint64_t k = 0; k < warnings && k < 1000; ++k) f.warnings.push_back(r.str());
  r.array(f.positions);
  r.array(f.tensors);
  r.array(f.ids);
  r.array(f.colorValues);
  for (std::size_t* n : {&f.totalPoints, &f.skippedNonFinite, &f.skippedOverflow, &f.masked, &f.unselected})
    *n = std::size_t(r.pod<std::uint64_t>());
  if (r.pod<bool>()) f.grid = r.pod<GridInfo>();
  f.sampleSpacing = r.pod<double>();
  return f;
}

// ---- The status pipe: one letter, then the text -------------------------
// 'P' + 8 bytes: a promise of decoded bytes; 'O': the field follows on the
// data socket; 'E' + text: the reader's InputError or ModuleError, verbatim;
// 'M' + text: out of memory; 'X' + text: any other exception, which the
// parent words with the file; 'S' + "axis index thickness size;" + text: a
// SliceOutOfRange, which the CLI reports as a command-line error.

std::string sizeText(std::uint64_t bytes) {
  return bytes >= (std::uint64_t(1) << 20) ? std::to_string(bytes >> 20) + " MiB"
         : bytes >= 1024                   ? std::to_string(bytes >> 10) + " KiB"
                                           : std::to_string(bytes) + " bytes";
}

// Room for the libraries' own thread stacks, arenas and chunk buffers.
constexpr std::uint64_t kSlackBytes = std::uint64_t(256) << 20;

std::uint64_t mappedBytes() {
  std::uint64_t pages = 0;
  std::ifstream statm("/proc/self/statm");
  statm >> pages;
  return pages * std::uint64_t(::sysconf(_SC_PAGESIZE));
}

// Lowers (never raises) the soft address-space limit to `bytes`.
void limitAddressSpace(std::uint64_t bytes) {
  rlimit as{};
  ::getrlimit(RLIMIT_AS, &as);
  if (as.rlim_cur == RLIM_INFINITY || rlim_t(bytes) < as.rlim_cur) as.rlim_cur = rlim_t(bytes);
  ::setrlimit(RLIMIT_AS, &as);
}

void sendAll(int fd, const void* p, std::size_t n) {
  const char* c = static_cast<const char*>(p);
  while (n > 0) {
    const ssize_t w = ::write(fd, c, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) _exit(3);  // the parent is gone
    c += w;
    n -= std::size_t(w);
  }
}

// A scalar volume (an underlay) on the wire: its values travel as one string.
void writeField(WireOut& w, const ScalarVolume& v) {
  w.pod(kWireMagic);
  w.pod(std::array<int, 3>{v.dims[0], v.dims[1], v.dims[2]});
  w.str(std::string(reinterpret_cast<const char*>(v.values.data()), v.values.size() * sizeof(float)));
  w.pod(v.placement.has_value());
  if (v.placement) w.pod(*v.placement);
}

void readVolume(WireIn& r, ScalarVolume& v) {
  if (r.pod<std::uint32_t>() != kWireMagic) throw std::runtime_error("the reader's result is malformed");
  const auto dims = r.pod<std::array<int, 3>>();
  const std::string bytes = r.str();
  std::uint64_t voxels = 1;
  for (int d : dims) voxels *= std::uint64_t(d >= 0 ? d : 0);
  if (bytes.size() != voxels * sizeof(float)) throw std::runtime_error("the reader's result is malformed");
  std::copy(dims.begin(), dims.end(), v.dims);
  v.values.resize(std::size_t(voxels));
  std::memcpy(v.values.data(), bytes.data(), bytes.size());
  if (r.pod<bool>()) v.placement = r.pod<GridPlacement>();
}


[[noreturn]] void childMain(int statusFd, int dataFd, const ReadLimits& limits,
                            const std::function<SendFn(const PromiseFn&)>& read) {
  // Messages of third-party libraries never reach the user; ours go through the pipe.
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) {
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::close(null);
  }
  // The parent's handlers would remove the parent's temporary files; an
  // ignored signal (nohup) stays ignored.
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXFSZ}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler != SIG_IGN) ::signal(sig, SIG_DFL);
  }
  limitAddressSpace(mappedBytes() + limits.memoryBytes + kSlackBytes);
  const rlim_t cpu = rlim_t(std::ceil(limits.cpuSeconds));
  rlimit cl{cpu, cpu + 1};  // SIGXCPU at the soft limit, SIGKILL a second later
  ::setrlimit(RLIMIT_CPU, &cl);
  int code = 0;
  std::uint64_t promised = 0;
  try {
    const SendFn send = read([statusFd, &promised](std::uint64_t bytes, std::uint64_t memory) {
      promised += memory;
      limitAddressSpace(mappedBytes() + memory + kSlackBytes);
      const char tag = 'P';
      sendAll(statusFd, &tag, 1);
      sendAll(statusFd, &bytes, sizeof bytes);
    });
    // The parent reads the field once it sees 'O'.
    sendAll(statusFd, "O", 1);
    WireOut w(dataFd);
    send(w);
    w.finish();  // with `send`'s data alive: the parent may be copying from it
    _exit(0);
  } catch (const SliceOutOfRange& e) {
    char head[128];
    const int n = std::snprintf(head, sizeof head, "S%d %lld %lld %d;", e.spec.axis, e.spec.index, e.spec.thickness,
                                e.size);
    sendAll(statusFd, head, std::size_t(n));
    sendAll(statusFd, e.what(), std::strlen(e.what()));
  } catch (const InputError& e) {
    sendAll(statusFd, "E", 1);
    sendAll(statusFd, e.what(), std::strlen(e.what()));
  } catch (const ModuleError& e) {
    // A format module that did not load: the message names it, not the file.
    sendAll(statusFd, "E", 1);
    sendAll(statusFd, e.what(), std::strlen(e.what()));
  } catch (const std::bad_alloc&) {
    const std::string what =
        promised ? "reading needed more memory than the file's header accounts for (" + sizeText(promised) +
                       "): the file is corrupt"
                 : "reading needed more memory than the " + sizeText(limits.memoryBytes) + " this load may use";
    sendAll(statusFd, "M", 1);
    sendAll(statusFd, what.data(), what.size());
  } catch (const std::exception& e) {
    sendAll(statusFd, "X", 1);  // not the reader's own message: the parent names the file
    sendAll(statusFd, e.what(), std::strlen(e.what()));
  } catch (...) {
    code = 4;
  }
  _exit(code);  // no atexit handlers or stdio flushes of the parent's state
}

std::string signalName(int sig) {
  const char* d = ::sigdescr_np(sig);
  return std::string(d ? d : "unknown signal") + ", signal " + std::to_string(sig);
}

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void sendField(WireOut& w, const TensorField& f) { writeField(w, f); }
TensorField receiveField(WireIn& r) { return readField(r); }

std::uint64_t defaultMemoryBudget() {
  const std::uint64_t phys = std::uint64_t(::sysconf(_SC_PHYS_PAGES)) * std::uint64_t(::sysconf(_SC_PAGESIZE));
  std::uint64_t budget = phys / 5 * 4;
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t mapped = mappedBytes() + kSlackBytes;
    budget = std::min<std::uint64_t>(budget, as.rlim_cur > mapped ? as.rlim_cur - mapped : 0);
  }
  return std::max<std::uint64_t>(budget, 1);  // 0 would mean no limit at all
}

ReadLimits limitsFor(std::uint64_t fileBytes, std::uint64_t memoryBudget) {
  ReadLimits l;
  l.memoryBytes = memoryBudget;
  l.headerSeconds = 3.0 + double(fileBytes) / 4e6;
  // Decoding is at least 20 MB/s of output even for bzip2 on a slow core.
  l.bytesPerSecond = 20e6;
  l.cpuSeconds = l.headerSeconds + double(memoryBudget) / l.bytesPerSecond;
  return l;
}

namespace {

// runInChild for a result that writeField puts on the wire and `receive`
// takes off: the child keeps it alive until it is sent.
template <class Result, class Receive>
Result resultInChild(const std::string& who, const std::string& path, const ReadLimits& limits,
                     const std::function<Result(const PromiseFn&)>& read, Receive receive,
                     const util::ProgressSink& progress = {}) {
  std::optional<Result> result;
  runInChild(
      who, path, limits,
      [&read](const PromiseFn& promise) -> SendFn {
        auto r = std::make_shared<const Result>(read(promise));
        return [r](WireOut& w) { writeField(w, *r); };
      },
      [&](WireIn& in) { result = receive(in); }, progress);
  return std::move(*result);
}

}  // namespace


void runInChild(const std::string& who, const std::string& path, const ReadLimits& limits,
                const std::function<SendFn(const PromiseFn&)>& read, const std::function<void(WireIn&)>& receive,
                const util::ProgressSink& progress) {
  auto fail = [&](const std::string& what) -> InputError { return InputError(who + ": " + path + ": " + what); };
  int statusFds[2], dataFds[2];
  if (::pipe2(statusFds, O_CLOEXEC) != 0) throw fail(std::string("cannot start the reader: ") + std::strerror(errno));
  Fd statusIn{statusFds[0]}, statusOut{statusFds[1]};
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, dataFds) != 0)
    throw fail(std::string("cannot start the reader: ") + std::strerror(errno));
  Fd dataIn{dataFds[0]}, dataOut{dataFds[1]};
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw fail(std::string("cannot start the reader: ") + std::strerror(errno));
  if (pid == 0) childMain(statusOut.fd, dataOut.fd, limits, read);
  ::close(statusOut.fd);
  ::close(dataOut.fd);
  statusOut.fd = dataOut.fd = -1;

  // Collect the status until the child says 'O' or ends, or the deadline passes.
  auto deadline = Clock::now() + std::chrono::duration<double>(limits.headerSeconds);
  std::string status;
  bool timedOut = false;
  auto nextReport = Clock::now();
  for (char buf[4096]; status != "O";) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      timedOut = true;
      break;
    }
    if (progress && Clock::now() >= nextReport) {
      nextReport = Clock::now() + std::chrono::milliseconds(100);
      const auto at = childReadPosition(pid);
      progress("loading", at ? double(at->offset) : 0.0, at ? double(at->size) : 0.0, "bytes");
    }
    pollfd p{statusIn.fd, POLLIN, 0};
    const int r = ::poll(&p, 1, int(std::min<long long>(left, progress ? 100 : 1000)));
    if (r < 0 && errno != EINTR) break;
    if (r <= 0) continue;
    const ssize_t n = ::read(statusIn.fd, buf, status.empty() ? 1 : sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    status.append(buf, std::size_t(n));
    // Each promise extends the deadline by the time its bytes may take.
    while (status.size() >= 9 && status[0] == 'P') {
      std::uint64_t bytes;
      std::memcpy(&bytes, status.data() + 1, 8);
      status.erase(0, 9);
      deadline += std::chrono::duration<double>(double(bytes) / limits.bytesPerSecond);
    }
  }
  bool received = false;
  std::string transferError;
  if (status == "O") {
    // Memory bandwidth, not the reader, sets this pace: 10 s and 100 MB/s.
    const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(10.0 + double(limits.memoryBytes) / 1e8));
    try {
      WireIn in(dataIn.fd, pid, until, limits.memoryBytes + (std::uint64_t(1) << 20));
      receive(in);
      in.finish();
      received = true;
    } catch (const std::runtime_error& e) {
      transferError = e.what();
    } catch (const std::bad_alloc&) {
      transferError = "the reader's result does not fit in memory";
    }
  }
  if (timedOut || !transferError.empty()) ::kill(pid, SIGKILL);
  int ws = 0;
  while (::waitpid(pid, &ws, 0) < 0 && errno == EINTR) {}
  if (timedOut)
    throw fail("reading took longer than its time limit, " + std::to_string(int(limits.headerSeconds)) +
               " s for the header and then what the promised data allows; the reader was stopped");
  if (!transferError.empty()) throw fail(transferError);
  if (received) return;
  if (WIFSIGNALED(ws)) {
    const int sig = WTERMSIG(ws);
    if (sig == SIGXCPU || sig == SIGKILL) throw fail("reading used more than its CPU time limit; the reader was stopped");
    throw fail("corrupt file: the reader crashed on it (" + signalName(sig) + ")");
  }
  if (!status.empty() && status[0] == 'E') throw InputError(status.substr(1));
  if (!status.empty() && status[0] == 'S') {
    SliceSpec s;
    int size = 0, used = 0;
    if (std::sscanf(status.c_str() + 1, "%d %lld %lld %d;%n", &s.axis, &s.index, &s.thickness, &size, &used) == 4 &&
        used > 0 && s.axis >= 0 && s.axis < 3)
      throw SliceOutOfRange(status.substr(1 + std::size_t(used)), s, size);
    throw InputError(status.substr(1));
  }
  if (!status.empty() && status[0] == 'M') throw fail(status.substr(1));
  if (!status.empty() && status[0] == 'X') throw fail("the reader failed (" + status.substr(1) + "): the file is corrupt");
  throw fail("the reader ended without a result (exit status " + std::to_string(WEXITSTATUS(ws)) + ")");
}

ScalarVolume readScalarInChild(const std::string& who, const std::string& path, const ReadLimits& limits,
                               const std::function<ScalarVolume(const PromiseFn&)>& read) {
  return resultInChild(who, path, limits, read, [](WireIn& in) {
    ScalarVolume v;
    readVolume(in, v);
    return v;
  });
}

}  // namespace tg::io
