// layout.kind = "patches": layout.file read into Layout::patchList (declared in verify/scene_reader.h).
// PLACEHOLDER (coordinator, wave 3 issue 20): the patches helper replaces this file.
#include "verify/scene_reader.h"

namespace fftess::verify::detail {

void readPatchesFile(Reader& r, const toml::table& t, Layout& L) {
  (void)L;
  r.fail("layout.file", t.get("file"), "layout.kind = \"patches\" is not implemented yet");
}

} // namespace fftess::verify::detail
