// The GL 1.x state primflow holds constant, for glGet* (query.h): a program asking about
// evaluators, selection and the rest gets GL's answer for a context that has
// never changed them (which in primflow cannot change), never GL_INVALID_ENUM; the absent
// buffers have 0 bits. The conformance case state_queries_all compares these with OSMesa's in a
// new context; the implementation limits at the end are primflow's own (docs/api.md).


#include "api/src/query.h"

namespace {

// A value; a colour-like one (normalised when read as an integer); a capability (glIsEnabled
// answers for it, and glEnable cannot turn it on).
enum Kind { kValue, kNormalized, kCapability };

struct Constant {
  GLenum pname;
  int count;
  double v[4];
  Kind kind = kValue;
};

constexpr double kTrue = 1.0, kFalse = 0.0;

constexpr Constant kConstants[] = {
    // Current values and the raster position (no glRasterPos: its initial state).
    {GL_CURRENT_INDEX, 1, {1}},
    {GL_CURRENT_RASTER_INDEX, 1, {1}},
    {GL_CURRENT_FOG_COORD, 1, {0}},
    {GL_CURRENT_SECONDARY_COLOR, 4, {0, 0, 0, 1}, kNormalized},
    // Vertex arrays primflow does not have.
    {GL_INDEX_ARRAY, 1, {kFalse}, kCapability},
    {GL_INDEX_ARRAY_TYPE, 1, {GL_FLOAT}},
    {GL_INDEX_ARRAY_STRIDE, 1, {0}},
    {GL_FOG_COORD_ARRAY, 1, {kFalse}, kCapability},
    {GL_SECONDARY_COLOR_ARRAY, 1, {kFalse}, kCapability},
    {GL_CLIENT_ACTIVE_TEXTURE, 1, {GL_TEXTURE0}},
    {GL_ARRAY_BUFFER_BINDING, 1, {0}},
    {GL_ELEMENT_ARRAY_BUFFER_BINDING, 1, {0}},
    {GL_VERTEX_ARRAY_BUFFER_BINDING, 1, {0}},
    {GL_NORMAL_ARRAY_BUFFER_BINDING, 1, {0}},
    {GL_COLOR_ARRAY_BUFFER_BINDING, 1, {0}},
    {GL_INDEX_ARRAY_BUFFER_BINDING, 1, {0}},
    {GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 1, {0}},
    {GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 1, {0}},
    // Fog coordinates (GL 1.4: the fragment depth is the one source) and the secondary colour.
    {GL_FOG_COORD_SRC, 1, {GL_FRAGMENT_DEPTH}},
    {GL_COLOR_SUM, 1, {kFalse}, kCapability},
    {GL_LIGHT_MODEL_COLOR_CONTROL, 1, {GL_SINGLE_COLOR}},
    // Points, lines, polygons: no smoothing.
    {GL_POINT_SMOOTH, 1, {kFalse}, kCapability},
    {GL_POINT_SIZE_MIN, 1, {0}},
    {GL_POINT_FADE_THRESHOLD_SIZE, 1, {1}},
    {GL_POINT_DISTANCE_ATTENUATION, 3, {1, 0, 0}},
    {GL_LINE_SMOOTH, 1, {kFalse}, kCapability},
    {GL_POLYGON_SMOOTH, 1, {kFalse}, kCapability},
    {GL_MULTISAMPLE, 1, {kTrue}, kCapability},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, 1, {kFalse}, kCapability},
    {GL_SAMPLE_ALPHA_TO_ONE, 1, {kFalse}, kCapability},
    {GL_SAMPLE_COVERAGE, 1, {kFalse}, kCapability},
    {GL_SAMPLE_COVERAGE_VALUE, 1, {1}},
    {GL_SAMPLE_COVERAGE_INVERT, 1, {kFalse}},
    // Texturing.
    {GL_TEXTURE_3D, 1, {kFalse}, kCapability},
    {GL_TEXTURE_CUBE_MAP, 1, {kFalse}, kCapability},
    {GL_TEXTURE_BINDING_3D, 1, {0}},
    {GL_TEXTURE_BINDING_CUBE_MAP, 1, {0}},
    {GL_ACTIVE_TEXTURE, 1, {GL_TEXTURE0}},
    // Fragment operations (those primflow has: state_queries.cpp).
    {GL_INDEX_LOGIC_OP, 1, {kFalse}, kCapability},
    // Framebuffer: one front buffer, no index buffer (the accumulation buffer: state_queries.cpp).
    {GL_DRAW_BUFFER, 1, {GL_FRONT}},
    {GL_READ_BUFFER, 1, {GL_FRONT}},
    {GL_INDEX_WRITEMASK, 1, {-1}},
    {GL_INDEX_CLEAR_VALUE, 1, {0}},
    {GL_RGBA_MODE, 1, {kTrue}},
    {GL_INDEX_MODE, 1, {kFalse}},
    {GL_DOUBLEBUFFER, 1, {kFalse}},
    {GL_STEREO, 1, {kFalse}},
    {GL_AUX_BUFFERS, 1, {0}},
    {GL_INDEX_BITS, 1, {0}},
    {GL_SAMPLE_BUFFERS, 1, {0}},
    {GL_SAMPLES, 1, {0}},
    // Evaluators.
    {GL_AUTO_NORMAL, 1, {kFalse}, kCapability},
    {GL_MAP1_COLOR_4, 1, {kFalse}, kCapability},
    {GL_MAP1_INDEX, 1, {kFalse}, kCapability},
    {GL_MAP1_NORMAL, 1, {kFalse}, kCapability},
    {GL_MAP1_TEXTURE_COORD_1, 1, {kFalse}, kCapability},
    {GL_MAP1_TEXTURE_COORD_2, 1, {kFalse}, kCapability},
    {GL_MAP1_TEXTURE_COORD_3, 1, {kFalse}, kCapability},
    {GL_MAP1_TEXTURE_COORD_4, 1, {kFalse}, kCapability},
    {GL_MAP1_VERTEX_3, 1, {kFalse}, kCapability},
    {GL_MAP1_VERTEX_4, 1, {kFalse}, kCapability},
    {GL_MAP2_COLOR_4, 1, {kFalse}, kCapability},
    {GL_MAP2_INDEX, 1, {kFalse}, kCapability},
    {GL_MAP2_NORMAL, 1, {kFalse}, kCapability},
    {GL_MAP2_TEXTURE_COORD_1, 1, {kFalse}, kCapability},
    {GL_MAP2_TEXTURE_COORD_2, 1, {kFalse}, kCapability},
    {GL_MAP2_TEXTURE_COORD_3, 1, {kFalse}, kCapability},
    {GL_MAP2_TEXTURE_COORD_4, 1, {kFalse}, kCapability},
    {GL_MAP2_VERTEX_3, 1, {kFalse}, kCapability},
    {GL_MAP2_VERTEX_4, 1, {kFalse}, kCapability},
    {GL_MAP1_GRID_DOMAIN, 2, {0, 1}},
    {GL_MAP2_GRID_DOMAIN, 4, {0, 1, 0, 1}},
    {GL_MAP1_GRID_SEGMENTS, 1, {1}},
    {GL_MAP2_GRID_SEGMENTS, 2, {1, 1}},
    // Selection and feedback.
    {GL_RENDER_MODE, 1, {GL_RENDER}},
    {GL_NAME_STACK_DEPTH, 1, {0}},
    {GL_SELECTION_BUFFER_SIZE, 1, {0}},
    {GL_FEEDBACK_BUFFER_SIZE, 1, {0}},
    {GL_FEEDBACK_BUFFER_TYPE, 1, {GL_2D}},
    // primflow's limits for what it does not have (not OSMesa's): no 3D or cube map textures,
    // evaluators or selection names.
    {GL_MAX_3D_TEXTURE_SIZE, 1, {0}},
    {GL_MAX_CUBE_MAP_TEXTURE_SIZE, 1, {0}},
    {GL_MAX_TEXTURE_UNITS, 1, {1}},
    {GL_MAX_TEXTURE_LOD_BIAS, 1, {0}},
    {GL_NUM_COMPRESSED_TEXTURE_FORMATS, 1, {0}},
    {GL_COMPRESSED_TEXTURE_FORMATS, 0, {}},
    {GL_MAX_NAME_STACK_DEPTH, 1, {0}},
    {GL_MAX_EVAL_ORDER, 1, {0}},
    {GL_POINT_SIZE_MAX, 1, {1}},
    // (no limit on a glDrawElements: the recommendation is the largest count)
    {GL_MAX_ELEMENTS_INDICES, 1, {2147483647}},
    {GL_MAX_ELEMENTS_VERTICES, 1, {2147483647}},
};

}  // namespace

bool pf::constantQuery(GLenum pname, Query& q) {
  for (const Constant& c : kConstants) {
    if (c.pname != pname) continue;
    q.count = c.count;
    for (int k = 0; k < c.count; ++k) q.v[k] = c.v[k];
    q.normalized = c.kind == kNormalized;
    return true;
  }
  return false;
}

bool pf::constantCapability(GLenum cap, bool& enabled) {
  for (const Constant& c : kConstants)
    if (c.pname == cap && c.kind == kCapability) {
      enabled = c.v[0] != 0.0;
      return true;
    }
  return false;
}
