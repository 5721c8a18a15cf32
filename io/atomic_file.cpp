#include "io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace tg::io {

AtomicOutput::AtomicOutput(const std::string& finalPath) : final_(finalPath) {
  const std::filesystem::path p(finalPath);
  static std::atomic<unsigned> counter{0};  // unique names for several outputs in one process
  std::string name = ".";
  name.append(p.stem().string()).append(".tmp").append(std::to_string(getpid())).append("-");
  name.append(std::to_string(counter++)).append(p.extension().string());
  temp_ = (p.parent_path() / name).string();
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicOutput::commit() {
  if (std::rename(temp_.c_str(), final_.c_str()) != 0)
    throw std::runtime_error("AtomicOutput::commit: " + final_ + ": " + std::strerror(errno));
  committed_ = true;
}

}  // namespace tg::io
