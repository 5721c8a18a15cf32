// glcorearb.h (through backends.h) first: osmesa.h pulls in the legacy gl.h,
// which would hide the core-profile typedefs.
#include "gl/backends.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace tg::gl {
namespace {

// libOSMesa is opened when the first context is made, not linked: it brings
// LLVM (about 50 MB and 40 ms to load here), which commands that draw
// nothing must not pay. It stays open until exit, as Mesa expects.
struct OSMesaLibrary {
  decltype(&::OSMesaCreateContextAttribs) createContextAttribs;
  decltype(&::OSMesaMakeCurrent) makeCurrent;
  decltype(&::OSMesaGetProcAddress) getProcAddress;
  decltype(&::OSMesaDestroyContext) destroyContext;
};

template <class F>
F symbol(void* lib, const char* name) {
  void* f = dlsym(lib, name);
  if (!f) throw std::runtime_error(std::string("createOSMesaContext: libOSMesa.so.8 has no ") + name);
  return reinterpret_cast<F>(f);
}

OSMesaLibrary openOSMesa() {
  void* lib = dlopen("libOSMesa.so.8", RTLD_LAZY | RTLD_LOCAL);
  if (!lib) throw std::runtime_error(std::string("createOSMesaContext: cannot load libOSMesa.so.8: ") + dlerror());
  return {symbol<decltype(&::OSMesaCreateContextAttribs)>(lib, "OSMesaCreateContextAttribs"),
          symbol<decltype(&::OSMesaMakeCurrent)>(lib, "OSMesaMakeCurrent"),
          symbol<decltype(&::OSMesaGetProcAddress)>(lib, "OSMesaGetProcAddress"),
          symbol<decltype(&::OSMesaDestroyContext)>(lib, "OSMesaDestroyContext")};
}

class OSMesaBackend final : public Context {
 public:
  OSMesaBackend() : lib_(openOSMesa()) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                           OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    ctx_ = lib_.createContextAttribs(attribs, nullptr);
    if (!ctx_) throw std::runtime_error("createOSMesaContext: OSMesa could not create a GL 4.5 core context");
    makeCurrent();
    loadEntryPoints();
  }
  ~OSMesaBackend() override { lib_.destroyContext(ctx_); }

  const char* backendName() const override { return "osmesa"; }
  void makeCurrent() override {
    // All rendering goes to framebuffer objects, so the default buffer needs only one pixel.
    if (!lib_.makeCurrent(ctx_, pixel_, GL_UNSIGNED_BYTE, 1, 1))
      throw std::runtime_error("createOSMesaContext: OSMesaMakeCurrent failed");
  }
  void releaseCurrent() override { lib_.makeCurrent(nullptr, nullptr, 0, 0, 0); }
  void* procAddress(const char* name) const override {
    return reinterpret_cast<void*>(lib_.getProcAddress(name));
  }

 private:
  OSMesaLibrary lib_;
  ::OSMesaContext ctx_ = nullptr;
  unsigned char pixel_[4] = {};
};

}  // namespace

std::unique_ptr<Context> createOSMesaContext() { return std::make_unique<OSMesaBackend>(); }

}  // namespace tg::gl
