/* osmesa_calls.c -- client suite (tests/clients): OSMesa's entry points with good and bad
 * arguments, one observation a line on stdout. `osmesa_calls` prints what OSMesa and
 * libprimflow-osmesa must agree on: ctest runs it on the system OSMesa and on primflow
 * (LD_LIBRARY_PATH) and compares the two outputs line for line. `osmesa_calls crashers` makes the
 * calls that crash Mesa 22.3's OSMesa (NULL context or attribute list, no current context,
 * OSMesaGetProcAddress(NULL)), run on primflow only: it must answer them without crashing.
 * What differs on purpose (docs/api.md, "Porting from OSMesa") is left out of the first list. */
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>

static unsigned char buffer[64 * 64 * 16];

static const char *ok(const void *p) { return p ? "context" : "NULL"; }

static void formats(void) {
  static const GLenum fmts[] = {OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR, OSMESA_RGB_565,
                                OSMESA_COLOR_INDEX, 0x1234};
  static const GLenum types[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT, GL_UNSIGNED_SHORT_5_6_5, GL_INT};
  unsigned f, t;
  for (f = 0; f < sizeof fmts / sizeof fmts[0]; ++f) {
    OSMesaContext c = OSMesaCreateContextExt(fmts[f], 16, 0, 0, NULL);
    printf("OSMesaCreateContextExt(format 0x%x) -> %s\n", fmts[f], ok(c));
    if (!c) continue;
    for (t = 0; t < sizeof types / sizeof types[0]; ++t) {
      GLint v = -1;
      GLboolean made = OSMesaMakeCurrent(c, buffer, types[t], 4, 4);
      printf("  OSMesaMakeCurrent(type 0x%x) -> %d", types[t], made);
      if (made) {
        OSMesaGetIntegerv(OSMESA_TYPE, &v);
        printf(", OSMESA_TYPE 0x%x", v);
        OSMesaGetIntegerv(OSMESA_FORMAT, &v);
        printf(", OSMESA_FORMAT 0x%x", v);
      }
      printf("\n");
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(c);
  }
}

static void attributes(void) {
  static const int lists[][7] = {
      {0x9999, 1, 0}, {OSMESA_FORMAT, 0x1234, 0}, {OSMESA_DEPTH_BITS, -1, 0}, {OSMESA_STENCIL_BITS, -1, 0},
      {OSMESA_ACCUM_BITS, -1, 0}, {OSMESA_PROFILE, 5, 0}, {OSMESA_PROFILE, OSMESA_CORE_PROFILE, 0},
      {OSMESA_CONTEXT_MAJOR_VERSION, 0, 0}, {OSMESA_CONTEXT_MAJOR_VERSION, 5, 0},
      {OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0},
      {OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0},
      {OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 6, 0},
      {OSMESA_CONTEXT_MINOR_VERSION, -1, 0}, {OSMESA_TYPE, GL_FLOAT, 0}, {0, 5, OSMESA_DEPTH_BITS, -1, 0},
      {OSMESA_DEPTH_BITS, 16, OSMESA_DEPTH_BITS, 0, 0}};
  unsigned i;
  for (i = 0; i < sizeof lists / sizeof lists[0]; ++i) {
    OSMesaContext c = OSMesaCreateContextAttribs(lists[i], NULL);
    printf("OSMesaCreateContextAttribs(list %u) -> %s\n", i, ok(c));
    OSMesaDestroyContext(c);
  }
  printf("OSMesaCreateContextExt(depth -1) -> %s\n", ok(OSMesaCreateContextExt(GL_RGBA, -1, 0, 0, NULL)));
  printf("OSMesaCreateContextExt(stencil -1) -> %s\n", ok(OSMesaCreateContextExt(GL_RGBA, 16, -1, 0, NULL)));
  printf("OSMesaCreateContextExt(accum -1) -> %s\n", ok(OSMesaCreateContextExt(GL_RGBA, 16, 0, -1, NULL)));
}

static void binding(void) {
  OSMesaContext a = OSMesaCreateContext(OSMESA_RGBA, NULL), b = OSMesaCreateContext(OSMESA_RGBA, NULL);
  GLint w = -1, h = -1, f = -1, v = -7, vp[4];
  void *p = NULL;
  printf("OSMesaGetColorBuffer(never bound) -> %d", OSMesaGetColorBuffer(a, &w, &h, &f, &p));
  printf(" %d %d %d %s\n", w, h, f, p ? "buffer" : "NULL");
  printf("OSMesaMakeCurrent(NULL buffer) -> %d\n", OSMesaMakeCurrent(a, NULL, GL_UNSIGNED_BYTE, 4, 4));
  printf("OSMesaMakeCurrent(width 0) -> %d\n", OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 0, 4));
  printf("OSMesaMakeCurrent(height -1) -> %d\n", OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 4, -1));
  printf("OSMesaMakeCurrent(NULL context, a buffer) -> %d\n", OSMesaMakeCurrent(NULL, buffer, GL_UNSIGNED_BYTE, 4, 4));
  printf("OSMesaMakeCurrent(NULL, NULL) -> %d, current %s\n", OSMesaMakeCurrent(NULL, NULL, 0, 0, 0),
         ok(OSMesaGetCurrentContext()));
  OSMesaGetIntegerv(OSMESA_WIDTH, &v);
  printf("OSMESA_WIDTH with no context -> %d\n", v);
  printf("OSMesaMakeCurrent(a, 5x3) -> %d", OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 5, 3));
  printf(", current is a: %d\n", OSMesaGetCurrentContext() == a);
  OSMesaGetIntegerv(OSMESA_WIDTH, &v);
  printf("OSMESA_WIDTH %d", v);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &v);
  printf(" OSMESA_HEIGHT %d", v);
  OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &v);
  printf(" OSMESA_ROW_LENGTH %d", v);
  OSMesaGetIntegerv(OSMESA_Y_UP, &v);
  printf(" OSMESA_Y_UP %d\n", v);
  v = -7;
  OSMesaGetIntegerv(0x9999, &v);
  printf("OSMesaGetIntegerv(bad name) leaves %d\n", v);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, -3);
  OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &v);
  printf("OSMESA_ROW_LENGTH after -3: %d\n", v);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
  OSMesaPixelStore(OSMESA_Y_UP, 5);
  OSMesaGetIntegerv(OSMESA_Y_UP, &v);
  printf("OSMESA_Y_UP after 5: %d\n", v);
  OSMesaPixelStore(OSMESA_Y_UP, 1);
  OSMesaPixelStore(0x9999, 1);
  printf("glGetError after the OSMesa calls: 0x%x\n", glGetError());
  glGetIntegerv(GL_VIEWPORT, vp);
  printf("viewport after the first binding: %d %d %d %d\n", vp[0], vp[1], vp[2], vp[3]);
  OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 2, 2);
  glGetIntegerv(GL_VIEWPORT, vp);
  printf("viewport after binding 2x2: %d %d %d %d\n", vp[0], vp[1], vp[2], vp[3]);
  printf("OSMesaGetColorBuffer -> %d", OSMesaGetColorBuffer(a, &w, &h, &f, &p));
  printf(" %d %d 0x%x %s\n", w, h, f, p == buffer ? "the buffer" : "another");

  /* When the caller's buffer is written: glFinish, release, another context made current; not
   * glReadPixels, not a binding of the same context to another buffer. */
  memset(buffer, 0x11, 16);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buffer + 1024);
  printf("after glClear and glReadPixels: %02x\n", buffer[0]);
  glFinish();
  printf("after glFinish: %02x\n", buffer[0]);
  memset(buffer, 0x11, 16);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  printf("after release: %02x %02x\n", buffer[0], buffer[1]);
  OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 2, 2);
  memset(buffer, 0x11, 16);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  OSMesaMakeCurrent(b, buffer + 64, GL_UNSIGNED_BYTE, 2, 2);
  printf("after making another context current: %02x %02x %02x\n", buffer[0], buffer[1], buffer[2]);
  OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 2, 2);
  memset(buffer, 0x11, 32);
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  OSMesaMakeCurrent(a, buffer + 16, GL_UNSIGNED_BYTE, 2, 2);
  printf("after binding to another buffer: old %02x, new %02x\n", buffer[0], buffer[16]);
  glFinish();
  printf("then glFinish: new %02x%02x%02x\n", buffer[16], buffer[17], buffer[18]);
  memset(buffer + 16, 0x11, 16);
  glFinish();
  printf("glFinish with nothing drawn since: %02x\n", buffer[16]);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  printf("glFinish after a glClear: %02x\n", buffer[16]);
  OSMesaDestroyContext(a);
  printf("current after destroying it: %s\n", ok(OSMesaGetCurrentContext()));
  OSMesaDestroyContext(b);
  OSMesaDestroyContext(NULL);
  glClear(GL_COLOR_BUFFER_BIT);
  printf("glGetError with no context: 0x%x\n", glGetError());
}

static void depth(void) {
  static const int bits[][2] = {{0, 0}, {8, 0}, {15, 0}, {16, 0}, {17, 0}, {24, 0}, {32, 0}, {16, 8}, {24, 8}, {0, 8}};
  unsigned i;
  for (i = 0; i < sizeof bits / sizeof bits[0]; ++i) {
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, bits[i][0], bits[i][1], 0, NULL);
    GLint w = -1, h = -1, bytes = -1;
    void *p = (void *)1;
    GLboolean got;
    OSMesaMakeCurrent(c, buffer, GL_UNSIGNED_BYTE, 4, 4);
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT);
    got = OSMesaGetDepthBuffer(c, &w, &h, &bytes, &p);
    printf("depth %d stencil %d: OSMesaGetDepthBuffer -> %d, %dx%d, %d bytes", bits[i][0], bits[i][1], got, w, h, bytes);
    if (got) {
      const unsigned z = bytes == 2 ? *(unsigned short *)p : *(unsigned *)p & 0xffffffu;
      void *again = NULL;
      printf(", cleared to 0.5: 0x%x", z);
      glClearDepth(0.25);
      glClear(GL_DEPTH_BUFFER_BIT);
      printf(", 0.25 before glFinish: 0x%x", bytes == 2 ? *(unsigned short *)p : *(unsigned *)p & 0xffffffu);
      glFinish();
      printf(", after: 0x%x", bytes == 2 ? *(unsigned short *)p : *(unsigned *)p & 0xffffffu);
      OSMesaGetDepthBuffer(c, &w, &h, &bytes, &again);
      printf(", same memory: %d", again == p);
    } else {
      printf(" %s", p ? "buffer" : "NULL");
    }
    printf("\n");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(c);
  }
}

static void procs(void) {
  OSMesaContext c = OSMesaCreateContext(OSMESA_RGBA, NULL);
  OSMesaMakeCurrent(c, buffer, GL_UNSIGNED_BYTE, 4, 4);
  printf("OSMesaGetProcAddress: glBegin %s, glRastParamfEXT %s, glFooBar %s, foo %s, OSMesaMakeCurrent is it: %d\n",
         OSMesaGetProcAddress("glBegin") ? "a function" : "NULL",
         OSMesaGetProcAddress("glRastParamfEXT") ? "a function" : "NULL",
         OSMesaGetProcAddress("glFooBar") ? "a function" : "NULL", OSMesaGetProcAddress("foo") ? "a function" : "NULL",
         OSMesaGetProcAddress("OSMesaMakeCurrent") == (OSMESAproc)(void (*)(void))OSMesaMakeCurrent);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(c);
}

/* Display lists shared through `sharelist`: defined in one context, called in another. */
static void sharing(void) {
  OSMesaContext a = OSMesaCreateContext(OSMESA_RGBA, NULL);
  OSMesaContext b = OSMesaCreateContext(OSMESA_RGBA, a);
  OSMesaContext c = OSMesaCreateContext(OSMESA_RGBA, NULL);
  OSMesaContext d = OSMesaCreateContextExt(OSMESA_BGRA, 16, 0, 0, b);
  GLuint first;
  OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 2, 2);
  first = glGenLists(2);
  glNewList(first, GL_COMPILE);
  glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEndList();
  OSMesaMakeCurrent(b, buffer, GL_UNSIGNED_BYTE, 2, 2);
  printf("shared: glIsList %d", glIsList(first));
  printf(" %d", glIsList(first + 1));
  memset(buffer, 0x11, 16);
  glCallList(first);
  glFinish();
  printf(", glCallList draws %02x%02x%02x", buffer[0], buffer[1], buffer[2]);
  printf(", next glGenLists %u\n", glGenLists(1) - first);
  OSMesaMakeCurrent(c, buffer, GL_UNSIGNED_BYTE, 2, 2);
  printf("not shared: glIsList %d", glIsList(first));
  printf(", glGenLists %u\n", glGenLists(1));
  OSMesaMakeCurrent(d, buffer, GL_UNSIGNED_BYTE, 2, 2);
  printf("shared through a sharer, another format: glIsList %d\n", glIsList(first));
  glDeleteLists(first, 1);
  OSMesaMakeCurrent(a, buffer, GL_UNSIGNED_BYTE, 2, 2);
  printf("deleted in one, seen in the other: glIsList %d\n", glIsList(first));
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(a);
  OSMesaMakeCurrent(b, buffer, GL_UNSIGNED_BYTE, 2, 2);
  printf("after destroying the first: glIsList %d\n", glIsList(first + 2));
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(b);
  OSMesaDestroyContext(c);
  OSMesaDestroyContext(d);
}

/* What crashes Mesa 22.3's OSMesa; primflow must answer. */
static int crashers(void) {
  GLint w = -1, h = -1, bytes = -1, v = -7;
  void *p = (void *)1;
  OSMesaContext c = OSMesaCreateContext(OSMESA_RGBA, NULL);
  int fine = 1;
  fine &= !OSMesaGetDepthBuffer(NULL, &w, &h, &bytes, &p) && w == 0 && p == NULL;
  fine &= !OSMesaGetDepthBuffer(c, &w, &h, &bytes, &p);  /* never bound */
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 4);                  /* no current context */
  OSMesaGetIntegerv(OSMESA_FORMAT, &v);
  fine &= v == 0;
  OSMesaGetIntegerv(OSMESA_WIDTH, NULL);
  fine &= OSMesaGetProcAddress(NULL) == NULL;
  fine &= !OSMesaGetColorBuffer(NULL, NULL, NULL, NULL, NULL);
  OSMesaDestroyContext(OSMesaCreateContextAttribs(NULL, NULL));
  /* a size OSMesa accepts and then draws out of the buffer with: refused */
  fine &= !OSMesaMakeCurrent(c, buffer, GL_UNSIGNED_BYTE, 20000, 20000);
  fine &= OSMesaMakeCurrent(c, buffer, GL_UNSIGNED_BYTE, 4, 4);
  /* a negative row length: kept, rows packed (OSMesa writes before the buffer) */
  OSMesaPixelStore(OSMESA_ROW_LENGTH, -3);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
  /* an entry point primflow lacks, by name and through OSMesaGetProcAddress */
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, buffer);
  fine &= glGetError() == GL_INVALID_OPERATION;
  ((void (*)(void))OSMesaGetProcAddress("glFooBar"))();
  fine &= glGetError() == GL_INVALID_OPERATION;
  OSMesaDestroyContext(c);
  printf("crashers: %s\n", fine ? "answered" : "answered wrongly");
  return fine ? 0 : 1;
}

int main(int argc, char *argv[]) {
  setvbuf(stdout, NULL, _IONBF, 0);
  if (argc > 1 && strcmp(argv[1], "crashers") == 0) return crashers();
  formats();
  attributes();
  binding();
  depth();
  procs();
  sharing();
  return 0;
}
