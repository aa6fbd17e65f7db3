// fftess layout: a scene's patches written as a layout.kind = "patches" file (OBJ of quads, CSV of corners), which
// reads back to the same layout (docs/cli.md, docs/verify.md "Patches"). Camera-dependent layouts: the scene camera's.
#include "commands.h"
#include "common.h"
#include "scene_options.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <set>

namespace fftess::cli {

CLI::App* addLayout(CLI::App& app, LayoutArgs& a) {
  CLI::App* sub = app.add_subcommand("layout", "Write a scene's patches as a layout.kind = \"patches\" file (OBJ, CSV)");
  sub->footer("Examples:\n"
              "  fftess layout docs/examples/terrain.toml --obj terrain.obj --csv terrain.csv\n"
              "  fftess check docs/examples/terrain.toml --set layout.kind=patches --set layout.file=$PWD/terrain.obj\n"
              "The file reads back to the same patches, in the same order, with the same corner bits; a camera-"
              "dependent layout (quadtree) is written as the scene camera (--eye/--target) sees it.\n"
              "Exit status: 0 written, 2 bad usage or scene, 3 internal error.");
  sub->add_option("scene", a.scene.scene, "Scene file (TOML, docs/verify.md)")->required();
  sub->add_option("--set", a.scene.overrides, "Override a scene key: KEY=VALUE (repeatable), validated like the file")
      ->type_name("KEY=VALUE");
  sub->add_option("--eye", a.scene.eye, "Camera eye X,Y,Z (shorthand for --set camera.eye=[X,Y,Z])");
  sub->add_option("--target", a.scene.target, "Camera target X,Y,Z (shorthand for --set camera.target=[X,Y,Z])");
  sub->add_option("--obj", a.obj, "Write the patches as an OBJ of quads (one face per patch) to FILE ('-': stdout)");
  sub->add_option("--csv", a.csv, "Write the patches as a CSV of corners (one row per patch) to FILE ('-': stdout)");
  sub->add_flag("-q,--quiet", a.scene.quiet, "Print nothing but errors");
  return sub;
}

int runLayout(const LayoutArgs& a) {
  if (a.obj.empty() && a.csv.empty()) throw UsageError("layout: nothing to write (give --obj FILE and/or --csv FILE)");
  if (a.obj == "-" && a.csv == "-") throw UsageError("--obj - and --csv -: only one of them can be stdout");
  const std::vector<FileArg> outputs{{"--obj", a.obj}, {"--csv", a.csv}};
  refuseSameFiles(outputs, sceneInputs(a.scene, nullptr));
  const vf::Terrain terrain = load(a.scene);
  refuseSameFiles(outputs, sceneInputs(a.scene, &terrain.scene())); // nor the files the scene reads
  std::unique_ptr<AtomicFile> obj, csv;
  if (!a.obj.empty()) obj = std::make_unique<AtomicFile>(a.obj);
  if (!a.csv.empty()) csv = std::make_unique<AtomicFile>(a.csv);

  const vf::Scene& s = terrain.scene();
  const vf::Terrain layout = vf::layoutFor(terrain, s.camera);
  std::vector<std::string> comments{
      "fftess layout of " + a.scene.scene + (s.name.empty() ? "" : " (" + s.name + ")") + ": " +
          std::to_string(layout.patchCount()) + " patches, layout.kind = \"" + vf::toString(s.layout.kind) + "\"",
      "v x height z (the height is ignored when read), f: one patch per face; read back with layout.kind = "
      "\"patches\" (docs/verify.md, Patches)"};
  if (terrain.cameraDependent())
    comments.push_back("as the scene camera sees it: eye " + formatFloat(s.camera.eye.x) + " " +
                       formatFloat(s.camera.eye.y) + " " + formatFloat(s.camera.eye.z) + ", target " +
                       formatFloat(s.camera.target.x) + " " + formatFloat(s.camera.target.y) + " " +
                       formatFloat(s.camera.target.z));
  AtomicFile* files[2];
  size_t n = 0;
  if (obj) obj->buffer() = vf::layoutObj(layout, comments), files[n++] = obj.get();
  if (csv) csv->buffer() = vf::layoutCsv(layout), files[n++] = csv.get();
  commitAll(files, n);

  if (!a.scene.quiet && a.obj != "-" && a.csv != "-") {
    std::set<int> levels;
    for (const vf::PatchGeometry& p : layout.patches()) levels.insert(p.ref.level);
    std::string to;
    for (const std::string* f : {&a.obj, &a.csv})
      if (!f->empty()) to += (to.empty() ? "" : " and ") + quotePath(*f);
    writeStdout("layout: " + std::to_string(layout.patchCount()) + " patches (" + std::to_string(levels.size()) +
                (levels.size() == 1 ? " level" : " levels") + ") written to " + to + "\n");
  }
  return kExitClean;
}

} // namespace fftess::cli
