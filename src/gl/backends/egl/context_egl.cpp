#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/backends.h"

namespace tg::gl {
namespace {

struct EglEntry {
  PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC platformDisplay = nullptr;
};

EglEntry eglEntry() {
  EglEntry e;
  e.queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  e.queryDeviceString =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  e.platformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  return e;
}

bool isSoftware(const EglEntry& e, EGLDeviceEXT dev) {
  const char* ext = e.queryDeviceString ? e.queryDeviceString(dev, EGL_EXTENSIONS) : nullptr;
  return ext && std::strstr(ext, "EGL_MESA_device_software");
}

// Hardware devices first (a GPU server), then Mesa surfaceless (llvmpipe).
std::vector<EGLDisplay> candidateDisplays(const EglEntry& e, bool allowSoftware) {
  std::vector<EGLDisplay> out;
  if (!e.platformDisplay) return out;
  if (e.queryDevices) {
    EGLDeviceEXT devs[16];
    EGLint n = 0;
    if (e.queryDevices(16, devs, &n))
      for (EGLint i = 0; i < n; ++i)
        if (!isSoftware(e, devs[i]))
          out.push_back(e.platformDisplay(EGL_PLATFORM_DEVICE_EXT, devs[i], nullptr));
  }
  if (allowSoftware) out.push_back(e.platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
  return out;
}

class EglBackend final : public Context {
 public:
  explicit EglBackend(const EglOptions& opt) {
    const EglEntry e = eglEntry();
    for (EGLDisplay d : candidateDisplays(e, opt.allowSoftware)) {
      if (d == EGL_NO_DISPLAY) continue;
      EGLint major = 0, minor = 0;
      if (!eglInitialize(d, &major, &minor)) continue;
      if (tryContext(d)) {
        dpy_ = d;
        break;
      }
      eglTerminate(d);
    }
    if (dpy_ == EGL_NO_DISPLAY)
      throw std::runtime_error(opt.allowSoftware
                                   ? "createEglContext: no EGL display offers a GL 4.5 core context"
                                   : "createEglContext: no GPU EGL device offers a GL 4.5 core context "
                                     "(software renderers refused)");
    makeCurrent();
    loadEntryPoints();
  }
  ~EglBackend() override {
    eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy_, ctx_);
    eglTerminate(dpy_);
  }
  const char* backendName() const override { return "egl"; }
  void makeCurrent() override {
    // Surfaceless: all rendering goes to framebuffer objects.
    if (!eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_))
      throw std::runtime_error("createEglContext: eglMakeCurrent failed");
  }
  void releaseCurrent() override { eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }
  void* procAddress(const char* name) const override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

 private:
  bool tryContext(EGLDisplay d) {
    if (!eglBindAPI(EGL_OPENGL_API)) return false;
    const EGLint cfgAttr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig cfg = nullptr;
    EGLint n = 0;
    if (!eglChooseConfig(d, cfgAttr, &cfg, 1, &n) || n == 0) cfg = nullptr;  // EGL_KHR_no_config_context
    const EGLint ctxAttr[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    ctx_ = eglCreateContext(d, cfg, EGL_NO_CONTEXT, ctxAttr);
    return ctx_ != EGL_NO_CONTEXT;
  }
  EGLDisplay dpy_ = EGL_NO_DISPLAY;
  EGLContext ctx_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> createEglContext(const EglOptions& opt) { return std::make_unique<EglBackend>(opt); }

bool eglHasHardwareDevice() {
  const EglEntry e = eglEntry();
  return !candidateDisplays(e, false).empty();
}

}  // namespace tg::gl
