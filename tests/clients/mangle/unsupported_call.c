/* tests/clients/mangle: a GL 1.x call primflow does not implement, through gl_mangle.h. It must
 * not compile (C and C++): "primflow does not implement glLineStipple". */
#include <primflow/gl_mangle.h>

void draw_stippled(void) {
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x0f0f);
}
