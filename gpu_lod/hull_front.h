// Internal to the hull shader front end (hull_glsl.cpp, hull_hlsl.cpp, hull_diagnostics.cpp, hull_check.cpp): the
// user's files with their #includes, glslang's log as Diagnostics, the reflection shared by GLSL and HLSL.
#pragma once

#include "gpu_lod/hull.h"
#include "gpu_lod/wrapper.h"

#include <glslang/Public/ShaderLang.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fftess::gpulod::hull::detail {

// The user's files as read: [0] the main file, then every #included file once, in the order first included.
struct SourceSet {
  std::vector<std::string> files;
  std::vector<std::string> texts;
  int add(const std::string& file, const std::string& text); // index of file (added once)
  const std::string* textOf(const std::string& file) const;
};

// A diagnostic naming a file without a line (printed "file: error: message").
inline Diagnostic inFile(const std::string& file, std::string message) {
  Diagnostic d;
  d.at.file = file;
  d.message = std::move(message);
  return d;
}

using gpulod::detail::readFile;
// `name` as #include "name" in `includer` resolves: relative to the including file's folder (absolute stays).
std::string resolveInclude(const std::string& name, const std::string& includer);

// glslang's Includer: #include "x" and <x> relative to the including file; every file read lands in `sources`.
class FileIncluder : public glslang::TShader::Includer {
public:
  explicit FileIncluder(SourceSet& sources) : sources_(sources) {}
  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* r) override;

private:
  SourceSet& sources_;
  std::vector<std::unique_ptr<std::string>> kept_;
};

// `text` (file `file`) with each #include "x" line replaced by `#line 1 S`, x's text, `#line L+1 P` (S, P: indices in
// `sources`, which gains every file read), GL_GOOGLE_include_directive lines blanked and Vulkan's `set = N` blanked:
// the GLSL the driver compiles. Files not found are left to glslang's diagnostics.
std::string expandIncludes(const std::string& file, const std::string& text, SourceSet& sources, int depth);

// glslang::InitializeProcess once per process.
void initGlslang();

// The user's main file as glslang reads it (the shader keeps pointers to these until it is destroyed).
struct MainSource {
  std::string file, text;
  const char* string = nullptr;
  int length = 0;
  const char* name = nullptr;
  // Reads `file` into text and sources; false with a diagnostic.
  bool read(const std::string& path, SourceSet& sources, std::vector<Diagnostic>& errors);
  void attach(glslang::TShader& shader);
};

// Parses `shader` (its environment set by the caller) with the file includer, links it into `program`; false with
// every glslang error as a diagnostic in `errors` (warnings dropped).
bool parseAndLink(glslang::TShader& shader, glslang::TProgram& program, SourceSet& sources, EShMessages messages,
                  int defaultVersion, EProfile profile, std::vector<Diagnostic>& errors);

// glslang's info log (errors and warnings, "ERROR: FILE:LINE: 'tok' : msg") as one Diagnostic each; glslang's
// summary lines ("N compilation errors.  No code generated.") dropped. glslang 12 prints no columns: the column is
// where the quoted token first appears on that line of the file (0 when it does not).
std::vector<Diagnostic> parseGlslangLog(const std::string& log, const SourceSet& sources);

// Where `name` is declared in the user's files, read in the compiler's order (each #include replaced by the file, as
// far as `sources` holds it), comments skipped: the first line with `keyword` (if not "") and the name as a whole
// word, else its first whole-word occurrence; with `after` (a block's name) only from the first line naming that
// block on. line 0 when not found.
SourcePos findDeclaration(const SourceSet& sources, const std::string& name, const std::string& keyword,
                          const std::string& after = "");

// Uniforms, block members and samplers the linked program uses (glslang's reflection), with their declarations.
// HLSL SamplerState objects are left out (the scene binds the texture, which names the combined sampler).
void reflectResources(glslang::TProgram& program, const SourceSet& sources, bool hlsl, std::vector<Resource>& out);

// Line and column of the byte offset `at` in `text` (1-based).
SourcePos positionOf(const std::string& file, const std::string& text, size_t at);
// `text` with comments replaced by spaces (newlines kept), so offsets and lines stay.
std::string blankComments(const std::string& text);

bool compileGlsl(const std::string& file, HullProgram& out, std::vector<Diagnostic>& errors);
bool compileHlsl(const std::string& file, const std::string& entry, HullProgram& out, std::vector<Diagnostic>& errors);

} // namespace fftess::gpulod::hull::detail
