// Internal to gpu_lod/: the compute shader around the LOD and the tools that build it. gpu_lod.cpp (the provider:
// the GL program, the buffers, the dispatch) calls these; docs/gpu_lod.md documents what the user's shader sees.
//   settings.cpp      the user's LodSettings (one list: the GLSL and HLSL struct and the values from the scene)
//   wrapper_glsl.cpp  the GLSL 4.50 compute source: lod/shaders/*.glsl, the interface types, the built-in scheme's
//                     evaluation (lod::glslSettings, by name) or the user's file, the buffer main
//   wrapper_hlsl.cpp  the HLSL wrapper and its front end (glslangValidator -> SPIR-V -> spirv-cross -> GLSL)
//   shader_log.cpp    reading files, the drivers' and glslang's logs as FILE:LINE messages
#pragma once

#include "gpu_lod/gpu_lod.h"

#include <string>

namespace fftess::gpulod::detail {

// Buffer layouts, in 32-bit words (docs/gpu_lod.md, "Buffers").
constexpr int kInWords = 37;  // per patch: corners 12, useHeightBounds, minHeight, maxHeight, size 4, oddU, oddV,
                              // farCorner 12, rebuiltHeight 4
constexpr int kCamWords = 39; // view 16, proj 16 (column-major), viewport 2, eye 3, depthZeroToOne, patch count
constexpr int kOutWords = 35; // per patch: 6 x (factor, metric, unclamped, exponent, fixes), cornerLevel 4, culled

// Lines of the GLSL compute source: the user's file keeps its own numbers (#line 1); fftess's prelude
// (lod/shaders/*.glsl and the interface types) is numbered from kPreludeLine, the wrapper from kWrapperLine, so a log
// line names its origin whatever the driver prints as the source-string number (Mesa "0:12(5): error: ...", NVIDIA
// "0(12) : error ...").
constexpr int kWrapperLine = 100001;
constexpr int kPreludeLine = 200001;

extern const char* const kSignatureGlsl; // the entry point the user's GLSL file defines
extern const char* const kSignatureHlsl; // the same in HLSL

// settings.cpp: the user's LodSettings struct (GLSL and HLSL spell its int, float and bool fields alike), and the
// function fftessSettings() that returns the scene's values (floats as exact bits, in the language's spelling).
std::string lodSettingsStruct();
std::string lodSettingsFunction(const verify::Lod& lod, bool hlsl);

// wrapper_glsl.cpp: the whole GLSL compute source. user: the user's file text, or "" for the built-in scheme of
// `lod` (with the tile-ring neighbour rule when sizeJumps).
std::string glslComputeSource(const verify::Lod& lod, const std::string& user, bool sizeJumps);

// wrapper_hlsl.cpp: the user's HLSL file through glslang's HLSL front end and spirv-cross into GLSL 4.50 (the
// compute source, wrapper included). False with error and kind set on failure; error names the file and line.
bool hlslToGlsl(const verify::Lod& lod, std::string& glsl, std::string& error, GpuLodError& kind);

// shader_log.cpp
bool readFile(const std::string& path, std::string& out);
bool hasEntryPoint(const std::string& source); // "lodMain(" as a word
bool isWarning(const std::string& text);
std::string trimLog(std::string s); // without trailing newlines, blanks and NULs
// The driver's log: errors only (warnings dropped), the user's lines as FILE:LINE:COLUMN. wrapper: set when an error
// lies in fftess's wrapper (the call of lodMain: a wrong signature).
std::string driverLog(const std::string& log, const std::string& file, bool& wrapper);

} // namespace fftess::gpulod::detail
