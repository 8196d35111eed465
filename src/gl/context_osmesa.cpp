// OSMesa fallback: Mesa's off-screen renderer (llvmpipe), loaded with dlopen so that the binary
// does not need libOSMesa where EGL is available (e.g. on the GPU machine).
#include <dlfcn.h>

#include "gl/context.h"
#include "gl/debug.h"
// osmesa.h includes GL/gl.h, which glad's header has already stood in for (it also defines the
// GLAPI / GLAPIENTRY macros osmesa.h uses).
#include <GL/osmesa.h>

namespace tidepool::gl {
namespace {

struct OsMesaApi {
  void* lib = nullptr;
  decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

const OsMesaApi& api() {
  static const OsMesaApi a = [] {
    OsMesaApi r;
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"})
      if ((r.lib = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
    if (!r.lib) return r;
    r.createContextAttribs =
        reinterpret_cast<decltype(r.createContextAttribs)>(dlsym(r.lib, "OSMesaCreateContextAttribs"));
    r.makeCurrent = reinterpret_cast<decltype(r.makeCurrent)>(dlsym(r.lib, "OSMesaMakeCurrent"));
    r.destroyContext = reinterpret_cast<decltype(r.destroyContext)>(dlsym(r.lib, "OSMesaDestroyContext"));
    r.getProcAddress = reinterpret_cast<decltype(r.getProcAddress)>(dlsym(r.lib, "OSMesaGetProcAddress"));
    return r;
  }();
  return a;
}

GLADapiproc loadProc(const char* name) { return reinterpret_cast<GLADapiproc>(api().getProcAddress(name)); }

class OsMesaContext final : public Context {
 public:
  explicit OsMesaContext(OSMesaContext ctx) : m_ctx(ctx) {}
  ~OsMesaContext() override { api().destroyContext(m_ctx); }
  std::string description() const override { return "osmesa"; }
  void makeCurrent() override {
    // Headless rendering goes to framebuffer objects; the 1x1 default buffer only satisfies OSMesa.
    api().makeCurrent(m_ctx, m_pixel, GL_UNSIGNED_BYTE, 1, 1);
  }

 private:
  OSMesaContext m_ctx;
  unsigned char m_pixel[4] = {0, 0, 0, 0};
};

}  // namespace

std::unique_ptr<Context> createOsMesaContext(const ContextOptions& options) {
  const OsMesaApi& a = api();
  if (!a.lib || !a.createContextAttribs || !a.makeCurrent || !a.getProcAddress)
    throw Error("OSMesa: libOSMesa.so.8 could not be loaded (install libosmesa6)");
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         24,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         4,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  OSMesaContext ctx = a.createContextAttribs(attribs, nullptr);
  if (!ctx) throw Error("OSMesa: could not create an OpenGL 4.3 core context");
  auto context = std::make_unique<OsMesaContext>(ctx);
  context->makeCurrent();
  if (!gladLoadGL(loadProc)) throw Error("OSMesa: could not load OpenGL functions");
  requireGl43("osmesa");
  if (options.debug) enableDebugOutput();
  return context;
}

}  // namespace tidepool::gl
