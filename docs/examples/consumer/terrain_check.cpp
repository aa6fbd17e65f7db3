// A terrain team's CI test with the installed verifier (fftess::verify, which links fftess::lod and
// fftess::tessellator): load a scene, check its camera ([camera]) for cracks and holes, fail unless watertight.
#include <cstdio>

#include <fftess/verify/verify.h>

int main(int argc, char** argv) {
  namespace fv = fftess::verify;
  if (argc != 2) {
    std::fprintf(stderr, "usage: terrain_check SCENE.toml\n");
    return 2;
  }
  const fv::SceneResult scene = fv::loadScene(argv[1]);
  if (!scene) {
    std::fprintf(stderr, "%s\n", scene.error.c_str());
    return 2;
  }
  const fv::TerrainResult terrain = fv::prepareTerrain(scene.scene);
  if (!terrain) {
    std::fprintf(stderr, "%s\n", terrain.error.c_str());
    return 2;
  }
  const fv::Report report = fv::checkScene(terrain.terrain, scene.scene.camera);
  if (!report.error.empty()) {
    std::fprintf(stderr, "%s\n", report.error.c_str());
    return 2;
  }
  const fv::Verdict verdict = fv::verdictOf(report.stats); // findings proven off screen do not count
  std::printf("%s: %s (%lld patches, %lld shared edges checked, %lld cracks, %lld holes)\n", argv[1],
              fv::toString(verdict), (long long)report.stats.patches, (long long)report.stats.edgesChecked,
              (long long)report.stats.cracksOnScreen(), (long long)report.stats.holes);
  return verdict == fv::Verdict::Watertight ? 0 : 1;
}
