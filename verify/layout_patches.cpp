// layout.kind = "patches" (verify/internal.h). PLACEHOLDER: the patches helper replaces this file.
#include "verify/internal.h"

namespace fftess::verify::detail {

bool buildPatchesLayout(const Scene& s, TerrainData& t, std::string& error) {
  (void)s;
  (void)t;
  error = "layout.kind = \"patches\" is not implemented yet";
  return false;
}

} // namespace fftess::verify::detail
