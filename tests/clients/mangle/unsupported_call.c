/* tests/clients/mangle: a GL 1.x call primflow does not implement, through gl_mangle.h. It must
 * not compile (C and C++): "primflow does not implement glRenderMode". */
#include <primflow/gl_mangle.h>

void enter_selection(void) {
  glEnable(GL_DEPTH_TEST);
  (void)glRenderMode(GL_SELECT);
}
