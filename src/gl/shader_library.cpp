#include "gl/shader_library.h"

#include <algorithm>
#include <regex>
#include <stdexcept>

namespace tg::gl {

ShaderLibrary::ShaderLibrary() : files_(embeddedShaderFiles()) {}
ShaderLibrary::ShaderLibrary(std::vector<EmbeddedFile> files) : files_(std::move(files)) {}

std::string_view ShaderLibrary::find(std::string_view path, std::string_view from) const {
  for (const auto& f : files_)
    if (f.path == path) return f.text;
  throw std::runtime_error("ShaderLibrary::compose: " + std::string(from) + ": unknown shader file \"" +
                           std::string(path) + "\"");
}

ComposedSource ShaderLibrary::compose(std::string_view path, std::span<const std::string_view> enable) const {
  ComposedSource out;
  std::vector<std::string> stack;
  find(path, "request");
  expand(path, out, stack);
  std::string defines;
  for (std::string_view e : enable)
    if (std::find(out.options.begin(), out.options.end(), e) != out.options.end())
      defines += "#define " + std::string(e) + " 1\n";
  // After the #version line, which is the first line of the top-level file.
  const std::size_t eol = out.text.find('\n');
  out.text.insert(eol + 1, defines);
  return out;
}

void ShaderLibrary::expand(std::string_view path, ComposedSource& out, std::vector<std::string>& stack) const {
  const std::string name(path);
  if (std::find(stack.begin(), stack.end(), name) != stack.end())
    throw std::runtime_error("ShaderLibrary::compose: include cycle through " + name);
  if (std::find(out.files.begin(), out.files.end(), name) != out.files.end()) return;  // once only
  const std::string_view text = find(path, stack.empty() ? "request" : stack.back());
  const std::size_t index = out.files.size();
  out.files.push_back(name);
  stack.push_back(name);
  const bool top = stack.size() == 1;
  std::size_t pos = 0;
  int line = 0;
  bool versionSeen = false;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view l = text.substr(pos, end - pos);
    ++line;
    const std::size_t first = l.find_first_not_of(" \t");
    const std::string_view body = first == std::string_view::npos ? std::string_view() : l.substr(first);
    const std::string where = name + ":" + std::to_string(line);
    if (body.starts_with("#include")) {
      const std::size_t q0 = body.find('"'), q1 = body.rfind('"');
      if (q0 == std::string_view::npos || q1 <= q0)
        throw std::runtime_error("ShaderLibrary::compose: " + where + ": malformed #include");
      const std::string_view target = body.substr(q0 + 1, q1 - q0 - 1);
      find(target, where);
      expand(target, out, stack);
      out.text += "#line " + std::to_string(line + 1) + " " + std::to_string(index) + "\n";
    } else if (body.starts_with("#version")) {
      if (!top) throw std::runtime_error("ShaderLibrary::compose: " + where + ": #version in an included file");
      out.text.append(l).append("\n");
      out.text += "#line " + std::to_string(line + 1) + " " + std::to_string(index) + "\n";
      versionSeen = true;
    } else if (body.starts_with("#pragma tg option ")) {
      static const std::regex ident(R"([A-Za-z_][A-Za-z0-9_]*)");
      const std::string opt(body.substr(18));
      if (!std::regex_match(opt, ident))
        throw std::runtime_error("ShaderLibrary::compose: " + where + ": malformed option \"" + opt + "\"");
      out.options.push_back(opt);
      out.text += "\n";
    } else if (body.starts_with("#pragma tg")) {
      throw std::runtime_error("ShaderLibrary::compose: " + where + ": unknown tag \"" + std::string(body) + "\"");
    } else {
      if (line == 1 && !top) out.text += "#line 1 " + std::to_string(index) + "\n";
      out.text.append(l).append("\n");
    }
    if (end == text.size()) break;
    pos = end + 1;
  }
  if (top && !versionSeen) throw std::runtime_error("ShaderLibrary::compose: " + name + ": no #version line");
  stack.pop_back();
}

std::string ShaderLibrary::mapLog(const std::string& log, const ComposedSource& src) {
  static const std::regex mesa(R"((\d+):(\d+)\((\d+)\))");
  static const std::regex nv(R"((\d+)\((\d+)\))");
  auto name = [&](const std::string& k) {
    const std::size_t i = std::stoul(k);
    return i < src.files.size() ? src.files[i] : k;
  };
  std::string out;
  std::smatch m;
  std::string rest = log;
  const std::regex& re = std::regex_search(rest, mesa) ? mesa : nv;
  while (std::regex_search(rest, m, re)) {
    out += m.prefix().str() + name(m[1].str()) + ":" + m[2].str();
    rest = m.suffix().str();
  }
  return out + rest;
}

}  // namespace tg::gl
