#pragma once
// GLSL sources embedded at build time, and their composition by #include.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tg::gl {

struct EmbeddedFile {
  std::string_view path;  // relative to shaders/
  std::string_view text;
};

// Generated from shaders/ by shaders/embed.cmake.
const std::vector<EmbeddedFile>& embeddedShaderFiles();

struct ComposedSource {
  std::string text;
  std::vector<std::string> files;    // files[k] is GLSL source-string number k in #line
  std::vector<std::string> options;  // declared by `#pragma tg option NAME`
};

class ShaderLibrary {
 public:
  ShaderLibrary();  // the embedded files
  explicit ShaderLibrary(std::vector<EmbeddedFile> files);

  // Expands `#include "path"` (each file once) and inserts #line directives so
  // that compiler messages can be mapped back to files. Throws
  // std::runtime_error on an unknown file, an include cycle, a malformed
  // directive, or a #version outside the top-level file.
  // Each of `enable` that a composed file declares with
  // `#pragma tg option NAME` is defined (`#define NAME 1`) after #version;
  // the others are left for the caller to reject (see Program).
  ComposedSource compose(std::string_view path, std::span<const std::string_view> enable = {}) const;

  // Rewrites "K:LINE(COL)" (Mesa) and "K(LINE)" (NVIDIA) prefixes in a
  // compiler log to "file:LINE".
  static std::string mapLog(const std::string& log, const ComposedSource& src);

 private:
  std::string_view find(std::string_view path, std::string_view from) const;
  void expand(std::string_view path, ComposedSource& out, std::vector<std::string>& stack) const;
  std::vector<EmbeddedFile> files_;
};

}  // namespace tg::gl
