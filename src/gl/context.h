#pragma once
// A GL 4.5 core context from one of the backends, with its own entry points.
#include <memory>
#include <string>

#include "gl/loader.h"

namespace tg::gl {

class Context {
 public:
  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  virtual const char* backendName() const = 0;
  virtual void makeCurrent() = 0;
  // Leaves no context current on this thread. A context is current on one
  // thread at a time (EGL refuses another's eglMakeCurrent until it is
  // released), so code that hands a context between threads releases it.
  virtual void releaseCurrent() = 0;
  virtual void* procAddress(const char* name) const = 0;

  const Api& api() const { return api_; }
  // "renderer | version" as GL reports them.
  std::string describe() const;

 protected:
  Context() = default;
  // Backends call this once their context is current.
  void loadEntryPoints();

 private:
  Api api_;
};

}  // namespace tg::gl
