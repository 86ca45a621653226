// The built-in showcase (see showcase.h): read and drawn as any scene file is (tools/scene).
#include "showcase.h"

#include "compiler/embedded_primitives.h"

namespace pf {

extern const EmbeddedSource kShowcaseScene[];  // generated from scenes/showcase.json

scene::Scene showcaseScene() { return scene::parseScene(kShowcaseScene[0].text, "scenes/showcase.json"); }

void drawShowcase(int width, int height) { scene::drawScene(showcaseScene(), width, height); }

}  // namespace pf
