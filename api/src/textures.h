// The texturing state of a context (GL 1.5 section 3.8, tables 6.15-6.19): texture objects and
// their images, the bindings and enables, the texture environment and texture coordinate
// generation; and the snapshot a draw takes of it (raster/texture.h's TextureUnit), rebuilt only
// when something it depends on has changed.
//
// Images live in shared, immutable levels: a draw's snapshot holds the levels it samples, so a
// level re-specified before the frame is drawn (glTexImage, glTexSubImage, glCopyTexImage,
// glDeleteTextures) leaves the earlier draws their old image -- a changed level is a new one,
// copied first when a draw still holds it.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <vector>

#include <GL/gl.h>

#include "raster/texture.h"

struct PFcontextRec;

namespace pf {

// GL_MAX_TEXTURE_SIZE and the levels it allows (llvmpipe's: 16384, 15 levels).
constexpr int kMaxTextureLevels = 15;
constexpr int kMaxTextureSize = 1 << (kMaxTextureLevels - 1);

// One image of a texture object: its level's texels (null: the level has no image) and what
// glGetTexLevelParameter reports of it.
struct TextureImage {
  std::shared_ptr<const TextureLevel> level;
  GLint internal_format = 1;  // as given (1..4 or a GL enum)
  TextureBase base = TextureBase::Rgba;
  int width = 0, height = 0;  // (also kept for proxy images, which have no texels)
};

struct TextureObject {
  GLenum target = 0;  // GL_TEXTURE_1D or GL_TEXTURE_2D once bound; 0: a name never bound
  TextureImage images[kMaxTextureLevels];
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR, mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT;
  float border[4] = {0, 0, 0, 0};
  float priority = 1.0f;
  float min_lod = -1000.0f, max_lod = 1000.0f;
  int base_level = 0, max_level = 1000;
};

// Texture coordinate generation for one of s, t, r, q (GL 1.5 section 2.11.4).
struct TexGen {
  bool enabled = false;
  GLenum mode = GL_EYE_LINEAR;
  float object_plane[4] = {0, 0, 0, 0};
  float eye_plane[4] = {0, 0, 0, 0};  // as stored: the plane given times the inverse modelview
};

// What glPushAttrib(GL_TEXTURE_BIT) keeps besides the enables (GL_ENABLE_BIT): the bindings, the
// environment and the generation state.
struct TextureAttribs {
  bool enabled_1d = false, enabled_2d = false;
  GLuint binding_1d = 0, binding_2d = 0;
  GLenum env_mode = GL_MODULATE;
  float env_color[4] = {0, 0, 0, 0};
  TexGen gen[4];  // s, t, r, q
};

struct TextureState {
  TextureAttribs a;
  // Named objects (glGenTextures reserves a name with an object whose target is 0), and the two
  // default textures of name 0.
  std::map<GLuint, TextureObject> objects;
  TextureObject default_1d{GL_TEXTURE_1D, {}}, default_2d{GL_TEXTURE_2D, {}};
  // The proxies' images (GL_PROXY_TEXTURE_1D / 2D): sizes and formats, no texels.
  TextureImage proxy_1d[kMaxTextureLevels], proxy_2d[kMaxTextureLevels];
  // The snapshot of the texture that draws sample now (null: none -- texturing off, or the bound
  // texture incomplete), valid while `dirty` is false.
  std::shared_ptr<const TextureUnit> unit;
  bool dirty = true;

  TextureObject& bound(GLenum target);
  TextureObject* object(GLuint name);
  // The snapshot for the next draw (rebuilt if dirty). Throws std::bad_alloc.
  const std::shared_ptr<const TextureUnit>& current();
  // Whether any texture coordinate generation is enabled.
  bool generating() const {
    return a.gen[0].enabled || a.gen[1].enabled || a.gen[2].enabled || a.gen[3].enabled;
  }
};

// The texture coordinates of a vertex as a draw's texturing uses them: generated where enabled
// (from the object-space vertex, the eye-space vertex and normal), then transformed by the
// texture matrix.
glm::vec4 textureCoordinates(const TextureState& t, const glm::mat4& texture_matrix, const glm::vec4& current,
                             const glm::vec4& object_vertex, const glm::vec4& eye_vertex, const glm::vec3& eye_normal);

// A textured draw under glShadeModel(GL_FLAT) (flat_texturing.cpp): gives the glEnd's rows the
// colours of their parts' provoking vertices, as the independent mode where parts share
// vertices, so that it can be drawn smooth -- texture coordinates interpolated, colours flat.
// False (nothing changed) where that is not needed or not possible.
bool flattenForTexturing(PFcontextRec& ctx);

}  // namespace pf
