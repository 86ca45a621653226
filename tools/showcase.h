// The built-in showcase: scenes/showcase.json, embedded at build time, so pfrender and pfview
// show it with no file at hand.
#pragma once

#include "scene/scene.h"

namespace pf {
// The showcase, parsed (its messages name scenes/showcase.json).
scene::Scene showcaseScene();
// Draws it into the current context (already bound to a width x height buffer).
void drawShowcase(int width, int height);
}
