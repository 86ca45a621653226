// libFuzzer target for scene files (tools/scene): every input is parsed as a scene (files never
// read) and, when it parses, drawn into a small primflow context; so is a generated text of a
// shape the bytes choose (adversarial.h: nesting a million deep, extreme numbers, many objects).
// Each runs on a 1 MB stack. Nothing may crash, hang, grow past -rss_limit_mb, or trip
// ASan/UBSan: a bad scene is a SceneError naming its file, line and key.
//
// Build and run locally: as fuzz_compile.cpp says, with --target fuzz_scene and the corpus
// tests/fuzz/corpus/scene.
#include <primflow/gl.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "adversarial.h"
#include "scene/scene.h"

namespace {

void parseAndDraw(const std::string& text) {
  pf::scene::Scene scene;
  try {
    scene = pf::scene::parseScene(text, "fuzz.json", false);
  } catch (const pf::scene::SceneError&) {
    return;
  }
  static PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  static std::vector<unsigned char> pixels(32 * 32 * 4);
  if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, 32, 32)) return;
  try {
    pf::scene::drawScene(scene, 32, 32);
  } catch (const pf::scene::SceneError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  pf::fuzz::onSmallStack([&] {
    if (size <= 8 * 1024) parseAndDraw(std::string(reinterpret_cast<const char*>(data), size));
    pf::fuzz::Choices in(data, size);
    parseAndDraw(pf::fuzz::sceneJson(in));
  });
  return 0;
}
