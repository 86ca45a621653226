// The built-in showcase scene pfrender draws with no arguments.
#pragma once

namespace pf {
// Draws into the current context (already bound to a width x height buffer).
void drawShowcase(int width, int height);
}
