// Headless OpenGL 4.5 core context through EGL. See gl_context.h.
#include "gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <sstream>
#include <utility>
#include <vector>

namespace fftess {
namespace gltest {

namespace {

std::string eglErrorString(EGLint e) {
  std::ostringstream s;
  s << "EGL error 0x" << std::hex << e;
  return s.str();
}

} // namespace

struct GlContext::Egl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

GlContext::GlContext() : egl_(new Egl) {}

GlContext::~GlContext() {
  if (egl_->context != EGL_NO_CONTEXT) {
    eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(egl_->display, egl_->context);
  }
  if (egl_->display != EGL_NO_DISPLAY) eglTerminate(egl_->display);
}

bool GlContext::create(const ContextOptions& options, std::string& error) {
  std::string log;
  const bool hardwareOnly = options.order == DeviceOrder::HardwareFirst && !options.allowSoftware;

  // Candidate displays, in the order of options.order.
  const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  std::vector<std::pair<EGLenum, void*>> software, hardware;
  if (hasExtension(clientExt, "EGL_EXT_device_enumeration") || hasExtension(clientExt, "EGL_EXT_device_base")) {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLDeviceEXT devices[16];
    EGLint n = 0;
    if (queryDevices && queryDevices(16, devices, &n)) {
      for (EGLint i = 0; i < n; ++i) {
        const char* ext = queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
        (hasExtension(ext, "EGL_MESA_device_software") ? software : hardware)
            .emplace_back(EGL_PLATFORM_DEVICE_EXT, devices[i]);
      }
      deviceNote_ = std::to_string(n) + " EGL device(s), " + std::to_string(software.size()) + " software";
    } else {
      log += "eglQueryDevicesEXT failed; ";
    }
  } else {
    log += "no EGL_EXT_device_enumeration; ";
  }
  std::vector<std::pair<EGLenum, void*>> candidates;
  if (options.order == DeviceOrder::SoftwareFirst) {
    candidates = software;
    candidates.insert(candidates.end(), hardware.begin(), hardware.end());
  } else {
    candidates = hardware;
    if (options.allowSoftware) candidates.insert(candidates.end(), software.begin(), software.end());
  }
  if (!hardwareOnly && hasExtension(clientExt, "EGL_MESA_platform_surfaceless"))
    candidates.emplace_back(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
  if (!getPlatformDisplay) candidates.clear(), log += "no eglGetPlatformDisplayEXT; ";

  for (auto& cand : candidates) {
    EGLDisplay dpy = getPlatformDisplay(cand.first, cand.second, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) {
      log += "display init: " + eglErrorString(eglGetError()) + "; ";
      continue;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      log += "eglBindAPI(OpenGL): " + eglErrorString(eglGetError()) + "; ";
      eglTerminate(dpy);
      continue;
    }
    // Without EGL_KHR_no_config_context: an OpenGL config, preferably one that also supports pbuffers.
    EGLConfig config = nullptr;
    if (!hasExtension(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
      const EGLint surfaceTypes[] = {EGL_PBUFFER_BIT, 0};
      EGLint count = 0;
      for (EGLint st : surfaceTypes) {
        const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, st, EGL_NONE};
        if (eglChooseConfig(dpy, attribs, &config, 1, &count) && count > 0) break;
      }
      if (count < 1) {
        log += "no OpenGL EGLConfig; ";
        eglTerminate(dpy);
        continue;
      }
    }
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx == EGL_NO_CONTEXT) {
      log += "OpenGL 4.5 core context: " + eglErrorString(eglGetError()) + "; ";
      eglTerminate(dpy);
      continue;
    }
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      log += "eglMakeCurrent without surface: " + eglErrorString(eglGetError()) + "; ";
      eglDestroyContext(dpy, ctx);
      eglTerminate(dpy);
      continue;
    }
    egl_->display = dpy;
    egl_->context = ctx;
    const char* v = eglQueryString(dpy, EGL_VENDOR);
    eglVendor_ = v ? v : "?";
    break;
  }
  if (egl_->context == EGL_NO_CONTEXT) {
    if (options.order == DeviceOrder::SoftwareFirst)
      error = "cannot create a headless OpenGL 4.5 core context through EGL (" + log + "tried " +
              std::to_string(candidates.size()) + " display(s))";
    else
      error = "no headless OpenGL 4.5 context on a " + std::string(hardwareOnly ? "hardware " : "") + "EGL device (" +
              deviceNote_ + "; " + log + std::to_string(candidates.size()) + " candidate(s))";
    return false;
  }

  bool loaded = true;
  std::string missing;
#define FFTESS_GL_LOAD(type, name)                                                                                    \
  gl.name = reinterpret_cast<type>(eglGetProcAddress(#name));                                                        \
  if (!gl.name) loaded = false, missing += " " #name;
  FFTESS_GL_FUNCTIONS(FFTESS_GL_LOAD)
#undef FFTESS_GL_LOAD
  if (!loaded) {
    error = "OpenGL entry points missing:" + missing;
    return false;
  }
  auto str = [this](GLenum name) {
    const GLubyte* s = gl.glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  renderer_ = str(GL_RENDERER);
  version_ = str(GL_VERSION);
  vendor_ = str(GL_VENDOR);
  return true;
}

bool GlContext::makeCurrent() {
  return egl_->context != EGL_NO_CONTEXT &&
         eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context) == EGL_TRUE;
}

void GlContext::releaseCurrent() {
  if (egl_->display != EGL_NO_DISPLAY) eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

bool GlContext::isLlvmpipe() const { return renderer_.find("llvmpipe") != std::string::npos; }

bool GlContext::isSoftware() const { return isLlvmpipe() || renderer_.find("softpipe") != std::string::npos; }

bool GlContext::checkHardwareRenderer(bool allowSoftware, std::string& error) const {
  if (allowSoftware || !isSoftware()) return true;
  error = "the renderer is software (" + renderer_ + "); pass --allow-llvmpipe for a self-test";
  return false;
}

bool checkGl(const GlFunctions& gl, const char* what, std::string& error) {
  const GLenum e = gl.glGetError();
  if (e == GL_NO_ERROR) return true;
  std::ostringstream s;
  s << "GL error 0x" << std::hex << e << " after " << what;
  error = s.str();
  return false;
}

bool compileShader(const GlFunctions& gl, GLuint shader, const std::string& src, std::string& error) {
  const char* p = src.c_str();
  gl.glShaderSource(shader, 1, &p, nullptr);
  gl.glCompileShader(shader);
  GLint ok = 0;
  gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok) return true;
  char log[4096] = {};
  gl.glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  error = "GL shader compile failed: " + std::string(log) + "\n" + src;
  return false;
}

bool linkProgram(const GlFunctions& gl, GLuint program, std::string& error) {
  gl.glLinkProgram(program);
  GLint linked = 0;
  gl.glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (linked) return true;
  char log[4096] = {};
  gl.glGetProgramInfoLog(program, sizeof log, nullptr, log);
  error = "GL program link failed: " + std::string(log);
  return false;
}

bool prepareCaptureDraws(const GlFunctions& gl, GLuint& framebuffer, GLuint& vertexArray, std::string& error) {
  gl.glGenFramebuffers(1, &framebuffer);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  gl.glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, 16);
  gl.glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, 16);
  if (gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "attachment-less framebuffer incomplete";
    return false;
  }
  gl.glViewport(0, 0, 16, 16);
  gl.glEnable(GL_RASTERIZER_DISCARD);
  gl.glGenVertexArrays(1, &vertexArray);
  gl.glBindVertexArray(vertexArray);
  gl.glPatchParameteri(GL_PATCH_VERTICES, 1);
  return true;
}

} // namespace gltest
} // namespace fftess
