/* libprimflow-osmesa: the GL entry points by name, from the generated table
 * (build/generated/osmesa_gl_entry_points.c, made from primflow/gl_mangle.h at configure time:
 * api/osmesa/CMakeLists.txt). */
#ifndef PRIMFLOW_OSMESA_ENTRY_POINTS_H
#define PRIMFLOW_OSMESA_ENTRY_POINTS_H

#include <primflow/osmesa.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The function GL calls `name` (glBegin, glRastParamfEXT, ... -- implemented or a stub that
 * records GL_INVALID_OPERATION), or NULL if gl_mangle.h does not name it. */
OSMESAproc pf_osmesa_gl_entry_point(const char *name);

/* What OSMesaGetProcAddress gives for other gl* names: records GL_INVALID_OPERATION. */
void pf_osmesa_unknown_entry_point(void);

/* The stubs' one body: GL_INVALID_OPERATION and a line on stderr (api/src/frame_hook.h). */
void pf_osmesa_unsupported(const char *name);

#ifdef __cplusplus
}
#endif

#endif
