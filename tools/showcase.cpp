// The built-in showcase, drawn through primflow: tools/showcase_scene.inc compiled against
// <primflow/gl_mangle.h>.
#include "showcase.h"

#include <primflow/gl_mangle.h>

#include <cmath>

#include "showcase_scene.inc"

namespace pf {

void drawShowcase(int width, int height) { drawShowcaseScene(width, height); }

}  // namespace pf
