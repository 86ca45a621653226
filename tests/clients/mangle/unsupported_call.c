/* tests/clients/mangle: a GL 1.x call primflow does not implement, through gl_mangle.h. It must
 * not compile (C and C++): "primflow does not implement glBlendFunc". */
#include <primflow/gl_mangle.h>

void draw_blended(void) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}
