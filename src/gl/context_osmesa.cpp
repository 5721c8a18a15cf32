// glcorearb.h (through backends.h) first: osmesa.h pulls in the legacy gl.h,
// which would hide the core-profile typedefs.
#include "gl/backends.h"

#include <GL/osmesa.h>

#include <stdexcept>

namespace tg::gl {
namespace {

class OSMesaBackend final : public Context {
 public:
  OSMesaBackend() {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                           OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx_) throw std::runtime_error("createOSMesaContext: OSMesa could not create a GL 4.5 core context");
    makeCurrent();
    loadEntryPoints();
  }
  ~OSMesaBackend() override { OSMesaDestroyContext(ctx_); }

  const char* backendName() const override { return "osmesa"; }
  void makeCurrent() override {
    // All rendering goes to framebuffer objects, so the default buffer needs only one pixel.
    if (!OSMesaMakeCurrent(ctx_, pixel_, GL_UNSIGNED_BYTE, 1, 1))
      throw std::runtime_error("createOSMesaContext: OSMesaMakeCurrent failed");
  }
  void* procAddress(const char* name) const override {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
  }

 private:
  ::OSMesaContext ctx_ = nullptr;
  unsigned char pixel_[4] = {};
};

}  // namespace

std::unique_ptr<Context> createOSMesaContext() { return std::make_unique<OSMesaBackend>(); }

}  // namespace tg::gl
