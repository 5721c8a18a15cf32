#pragma once
// Output written to a temporary file beside the target and renamed into place
// on commit, so a failure never leaves a partial file at the target path.
#include <string>

namespace tg::io {

class AtomicOutput {
 public:
  explicit AtomicOutput(const std::string& finalPath);
  ~AtomicOutput();  // removes the temporary file unless committed
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  // Same directory and extension as the target, so writers that pick a format
  // by extension still do.
  const std::string& tempPath() const { return temp_; }
  void commit();  // throws std::runtime_error if the rename fails

 private:
  std::string final_, temp_;
  bool committed_ = false;
};

}  // namespace tg::io
