// Findings in words, for check, sweep and merge: edge and patch names, the cause of a finding or hole (from its own
// records: the LOD's per side, the tessellator's), one-line finding and hole text, the stats block and the verdict
// words. Pure functions of verify's reports.
#pragma once

#include "verify/verify.h"

#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

const char* edgeName(int e);                          // Ueq0 Veq0 Ueq1 Veq1, "?" out of range
std::string patchText(const vf::PatchRef& p);         // "ring R tile T patch P"
std::string fmtWorld(double v);                       // %.3g

// Why a finding happened, printed from its records (the LOD's per side, the tessellator's): a short, stable key (the
// grouping key of sweep summaries: the size jump, the tessellator fact and the rule the LOD applied), a longer
// explanation with the numbers of this finding and each side's LOD record (vf::lodWords), and one line a user can act
// on (fix), derived from the same facts: the change that removes the cause, naming the scene key and value where one
// exists. Each cause is one return of findingCause / holeCause with all three (a new cause is one place).
// id: the cause as a key of a fixed set (the JSON's "cause_id", docs/schema/common.schema.json "cause_id"): the branch
// of findingCause / holeCause / gpuFloatCause that named it; key and detail add the numbers and the rule that ran.
struct Cause {
  std::string key;
  std::string detail;
  std::string fix;
  std::string id;
};
Cause findingCause(const vf::Finding& f);
// The factors' source as causes name it when an edge's record says LodScheme::Shader: "the shader FILE" (the file's
// name as the scene gives it). Set once per command from its scene (attachGpuLod); "the shader" until then.
void setShaderBlame(const vf::Scene& scene);

// One line: classification, both sides, gap, cause. Off screen (Finding::onScreen false): "off screen" after the
// classification. A crack on screen whose farthest vertex is not its worst on-screen one: the on-screen gap, then the
// farthest vertex's.
// withCause false: without the cause's explanation (check's lines under their cause's header).
std::string findingLine(const vf::Finding& f, bool withCause = true);
// Where a finding is, for a line under its cause's header: both sides and a crack's gap ("ring 1 tile 10 patch 56
// Veq1 | ring 0 tile 0 patch 0 Veq0: gap 0.00252 world (0.0417 px) at (-31.4633, 5.31813, -32)").
std::string findingWhere(const vf::Finding& f);
// A hole's cause from its records: a short key (sweep grouping) and the explanation (factor bits, lod's record,
// the projection's w at the edge's midpoint, where the patch was seen).
Cause holeCause(const vf::Hole& h);
std::string holeLine(const vf::Hole& h);              // one line: "hole", the patch, the cause
// A GPU float finding (--gpu-float conformant; vf::GpuFloatFinding): key "may crack on some GPUs: ..." (the reason),
// the detail (both sides' C++ factors and what a conformant compiler may produce, the first operation that differs on
// each side) and the finding's fix.
Cause gpuFloatCause(const vf::GpuFloatFinding& g);
std::string gpuFloatWhere(const vf::GpuFloatFinding& g); // both sides, as findingWhere
// One line: "gpu float", both sides, then (withCause) the cause's detail.
std::string gpuFloatLine(const vf::GpuFloatFinding& g, bool withCause = true);
// The causes of a report with their fixes, keyed as sweep's table keys them ("hole: KEY", "undecided: ...",
// "crack: KEY", "t_junction: KEY"), each once, in the report's order: holes, undecided patches, findings (on screen
// only unless offScreenToo). For the pictures' legends.
std::vector<Cause> reportCauses(const vf::Report& r, bool offScreenToo);
// The indented stats block of check and sweep. countOffScreen (--offscreen): off-screen findings are counted (and
// said so), the worst gap is over all cracks; else the worst gap is the on-screen one and the off-screen findings
// are named apart, not counted.
std::string statsText(const vf::Stats& s, bool countOffScreen);
// The off-screen findings in words: "" when there are none; else e.g. "100 cracks off screen, not counted", and with
// explain ": the factors that made them belong to their camera, so no other camera sees them either (--offscreen
// counts them)".
std::string offScreenWords(const vf::Stats& s, bool countOffScreen, bool explain = false);
// The worst gap that counts (on screen, or with countOffScreen over all cracks): world units and pixels.
double countedGapWorld(const vf::Stats& s, bool countOffScreen);
double countedGapPixels(const vf::Stats& s, bool countOffScreen);
// The verdict line's words of a sweep (and of merged shards): cameras = the cameras asked for.
std::string verdictWords(vf::Verdict verdict, const vf::SweepResult& res, size_t crackCameras, size_t holeCameras,
                         size_t cameras, bool countOffScreen);

} // namespace fftess::cli
