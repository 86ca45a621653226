// libFuzzer target for scene files (tools/scene): every input is parsed as a scene (files never
// read) and, when it parses, drawn into a small primflow context. Nothing may crash, hang, or
// trip ASan/UBSan: a bad scene is a SceneError naming its file, line and key.
//
// Build and run locally: as fuzz_compile.cpp says, with --target fuzz_scene and the corpus
// tests/fuzz/corpus/scene.
#include <primflow/gl.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 8 * 1024) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  pf::scene::Scene scene;
  try {
    scene = pf::scene::parseScene(text, "fuzz.json", false);
  } catch (const pf::scene::SceneError&) {
    return 0;
  }
  static PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  static std::vector<unsigned char> pixels(32 * 32 * 4);
  if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, 32, 32)) return 0;
  try {
    pf::scene::drawScene(scene, 32, 32);
  } catch (const pf::scene::SceneError&) {
  }
  return 0;
}
