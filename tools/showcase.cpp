// The built-in showcase: scenes/showcase.json, embedded at build time, read and drawn as any
// scene file is (tools/scene).
#include "showcase.h"

#include "compiler/embedded_primitives.h"
#include "scene/scene.h"

namespace pf {

extern const EmbeddedSource kShowcaseScene[];  // generated from scenes/showcase.json

void drawShowcase(int width, int height) {
  const scene::Scene scene = scene::parseScene(kShowcaseScene[0].text, "scenes/showcase.json");
  scene::drawScene(scene, width, height);
}

}  // namespace pf
