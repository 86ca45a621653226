/* tests/clients/mangle: taking the address of an unimplemented entry point through gl_mangle.h
 * (as a table of GL functions would) must not compile either: "primflow does not implement
 * glTexImage3D". */
#include <primflow/gl_mangle.h>

typedef void (*TexImage3D)(GLenum, GLint, GLint, GLsizei, GLsizei, GLsizei, GLint, GLenum, GLenum, const GLvoid *);
TexImage3D texture_upload = glTexImage3D;
