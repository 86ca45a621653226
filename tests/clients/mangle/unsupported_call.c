/* tests/clients/mangle: a GL 1.x call primflow does not implement, through gl_mangle.h. It must
 * not compile (C and C++): "primflow does not implement glFogf". */
#include <primflow/gl_mangle.h>

void draw_fogged(void) {
  glEnable(GL_FOG);
  glFogf(GL_FOG_DENSITY, 0.5f);
}
