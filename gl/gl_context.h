// Headless OpenGL 4.5 core context through EGL, shared by the GL test tools: the llvmpipe oracle (gl_capture.cpp),
// the NVIDIA comparison (tests/tools/nvidia_compare/nvidia_compare.cpp) and the LOD drift measurement (tests/tools/lod_gpu_drift/lod_gpu_drift.cpp).
// EGL device platform (EGL_EXT_device_enumeration) or Mesa's surfaceless platform; the context is made current
// without a surface; GL entry points come from eglGetProcAddress, so only libEGL is linked. See docs/oracle.md,
// "How a patch is captured".
//
// Users need GL/glcorearb.h on their include path (CMake: find_path(FFTESS_GLCOREARB_DIR GL/glcorearb.h)).
#pragma once

#include <GL/glcorearb.h>

#include <memory>
#include <string>

namespace fftess {
namespace gltest {

// Every GL entry point the three tools and gpu_lod/ (hull_capture.cpp, hull_bind.cpp) call (EGL 1.5's eglGetProcAddress returns core functions too).
#define FFTESS_GL_FUNCTIONS(X)                                                                                        \
  X(PFNGLGETSTRINGPROC, glGetString)                                                                                   \
  X(PFNGLGETERRORPROC, glGetError)                                                                                     \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                                                               \
  X(PFNGLENABLEPROC, glEnable)                                                                                         \
  X(PFNGLFINISHPROC, glFinish)                                                                                         \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                                                             \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                                                             \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                                                                           \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                                                               \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                                                     \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                                                             \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                                                           \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                                                             \
  X(PFNGLTRANSFORMFEEDBACKVARYINGSPROC, glTransformFeedbackVaryings)                                                   \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                                                               \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                                                             \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                                                                   \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                                                           \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                                                                 \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                                                                 \
  X(PFNGLUNIFORM1UIPROC, glUniform1ui)                                                                                 \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                                                                       \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                                                       \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                                                                 \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                                                                 \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                                                                 \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                                                                 \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                                                                           \
  X(PFNGLGETBUFFERSUBDATAPROC, glGetBufferSubData)                                                                     \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                                                                         \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                                                           \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                                                                       \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                                                       \
  X(PFNGLFRAMEBUFFERPARAMETERIPROC, glFramebufferParameteri)                                                           \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)                                                         \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                                                                 \
  X(PFNGLVIEWPORTPROC, glViewport)                                                                                     \
  X(PFNGLPATCHPARAMETERIPROC, glPatchParameteri)                                                                       \
  X(PFNGLGENQUERIESPROC, glGenQueries)                                                                                 \
  X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                                                                           \
  X(PFNGLBEGINQUERYPROC, glBeginQuery)                                                                                 \
  X(PFNGLENDQUERYPROC, glEndQuery)                                                                                     \
  X(PFNGLGETQUERYOBJECTUIVPROC, glGetQueryObjectuiv)                                                                   \
  X(PFNGLBEGINTRANSFORMFEEDBACKPROC, glBeginTransformFeedback)                                                         \
  X(PFNGLENDTRANSFORMFEEDBACKPROC, glEndTransformFeedback)                                                             \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                                                                 \
  X(PFNGLDISPATCHCOMPUTEPROC, glDispatchCompute)                                                                       \
  X(PFNGLMEMORYBARRIERPROC, glMemoryBarrier)                                                                         \
  X(PFNGLDETACHSHADERPROC, glDetachShader)                                                                             \
  X(PFNGLDISABLEPROC, glDisable)                                                                                       \
  X(PFNGLGETPROGRAMINTERFACEIVPROC, glGetProgramInterfaceiv)                                                           \
  X(PFNGLGETPROGRAMRESOURCENAMEPROC, glGetProgramResourceName)                                                         \
  X(PFNGLGETPROGRAMRESOURCEIVPROC, glGetProgramResourceiv)                                                             \
  X(PFNGLUNIFORMBLOCKBINDINGPROC, glUniformBlockBinding)                                                               \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                                                                   \
  X(PFNGLUNIFORM1FVPROC, glUniform1fv)                                                                                 \
  X(PFNGLUNIFORM2FVPROC, glUniform2fv)                                                                                 \
  X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                                                                 \
  X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                                                                 \
  X(PFNGLUNIFORM1IVPROC, glUniform1iv)                                                                                 \
  X(PFNGLUNIFORM2IVPROC, glUniform2iv)                                                                                 \
  X(PFNGLUNIFORM3IVPROC, glUniform3iv)                                                                                 \
  X(PFNGLUNIFORM4IVPROC, glUniform4iv)                                                                                 \
  X(PFNGLUNIFORM1UIVPROC, glUniform1uiv)                                                                               \
  X(PFNGLUNIFORM2UIVPROC, glUniform2uiv)                                                                               \
  X(PFNGLUNIFORM3UIVPROC, glUniform3uiv)                                                                               \
  X(PFNGLUNIFORM4UIVPROC, glUniform4uiv)                                                                               \
  X(PFNGLUNIFORMMATRIX2FVPROC, glUniformMatrix2fv)                                                                     \
  X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                                                                     \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                                                                     \
  X(PFNGLUNIFORMMATRIX2X3FVPROC, glUniformMatrix2x3fv)                                                                 \
  X(PFNGLUNIFORMMATRIX2X4FVPROC, glUniformMatrix2x4fv)                                                                 \
  X(PFNGLUNIFORMMATRIX3X2FVPROC, glUniformMatrix3x2fv)                                                                 \
  X(PFNGLUNIFORMMATRIX3X4FVPROC, glUniformMatrix3x4fv)                                                                 \
  X(PFNGLUNIFORMMATRIX4X2FVPROC, glUniformMatrix4x2fv)                                                                 \
  X(PFNGLUNIFORMMATRIX4X3FVPROC, glUniformMatrix4x3fv)                                                                 \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                                                                               \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                                                         \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                                                                               \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                                                                           \
  X(PFNGLTEXSTORAGE2DPROC, glTexStorage2D)                                                                             \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                                                                           \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                                                                           \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                                                               \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                                                               \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)

struct GlFunctions {
#define FFTESS_GL_DECLARE(type, name) type name = nullptr;
  FFTESS_GL_FUNCTIONS(FFTESS_GL_DECLARE)
#undef FFTESS_GL_DECLARE
};

// Which EGL displays are tried, in order; the first that gives a current OpenGL 4.5 core context wins.
enum class DeviceOrder {
  // The llvmpipe oracle: EGL devices with EGL_MESA_device_software first, then the other devices, then Mesa's
  // surfaceless platform.
  SoftwareFirst,
  // The hardware tools: devices without EGL_MESA_device_software only; the software devices and then the surfaceless
  // platform follow when ContextOptions::allowSoftware is set (a self-test on llvmpipe).
  HardwareFirst,
};

struct ContextOptions {
  DeviceOrder order = DeviceOrder::SoftwareFirst; // default: the oracle's choice
  bool allowSoftware = true;                      // HardwareFirst only: also try the software devices and surfaceless
};

// An OpenGL 4.5 core context, current on the creating thread, released (context destroyed, display terminated) by
// the destructor. Not thread-safe; one per thread.
class GlContext {
public:
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Tries the displays in options.order, makes the context current and loads every FFTESS_GL_FUNCTIONS entry point.
  // Returns false and sets 'error' when no display gives a context (with what each attempt said), or when an entry
  // point is missing (named). Call once.
  bool create(const ContextOptions& options, std::string& error);

  GlFunctions gl;

  // Makes the context current on the calling thread / releases it from the calling thread (a context is current on
  // one thread at a time: a caller that shares it between threads serialises and releases after each use).
  bool makeCurrent();
  void releaseCurrent();

  // GL_RENDERER, GL_VERSION, GL_VENDOR of the context; EGL_VENDOR of its display; "N EGL device(s), S software"
  // (empty when the devices could not be enumerated).
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  const std::string& vendor() const { return vendor_; }
  const std::string& eglVendor() const { return eglVendor_; }
  const std::string& deviceNote() const { return deviceNote_; }

  // The renderer is Mesa's llvmpipe ("llvmpipe (LLVM 15.0.6, 256 bits)").
  bool isLlvmpipe() const;
  // The renderer is one of Mesa's software rasterizers (llvmpipe or softpipe).
  bool isSoftware() const;

  // The renderer check of the hardware tools: false with 'error' = "the renderer is software (NAME); pass
  // --allow-llvmpipe for a self-test" when the renderer is software and allowSoftware is not set.
  bool checkHardwareRenderer(bool allowSoftware, std::string& error) const;

  struct Egl;

private:
  std::unique_ptr<Egl> egl_;
  std::string renderer_, version_, vendor_, eglVendor_, deviceNote_;
};

// True when the space-separated extension list contains 'name' as a whole word (null list: false).
bool hasExtension(const char* list, const char* name);

// After glGetError: true for GL_NO_ERROR, else false with 'error' = "GL error 0x... after WHAT".
bool checkGl(const GlFunctions& gl, const char* what, std::string& error);

// Compiles 'shader' from 'src'. On failure false, with 'error' = "GL shader compile failed: LOG\nSOURCE".
bool compileShader(const GlFunctions& gl, GLuint shader, const std::string& src, std::string& error);

// Links 'program'. On failure false, with 'error' = "GL program link failed: LOG" (the program is not deleted).
bool linkProgram(const GlFunctions& gl, GLuint program, std::string& error);

// State for capture-only draws: an attachment-less 16x16 framebuffer (draws need a complete one),
// GL_RASTERIZER_DISCARD, a vertex array, GL_PATCH_VERTICES 1. Gives back the framebuffer and vertex array names
// (the caller deletes them, or lets the context go). False with 'error' if the framebuffer is incomplete.
bool prepareCaptureDraws(const GlFunctions& gl, GLuint& framebuffer, GLuint& vertexArray, std::string& error);

} // namespace gltest
} // namespace fftess
