// The shading channels of a glBegin: the shading parameters its instances carry (seed 003
// section 3.1; 4 floats each, in every sequence point's row and in the G-buffer) and where each
// goes (planShading), and each sequence point's values of them (rowChannels) -- the colour GL's
// lit colour where lighting applies, lit a batch at a time (flushVertexLighting,
// vertex_lighting.h), the texture coordinates generated and transformed where a texture is on,
// the fog coordinate where fog is on.
#pragma once

#include <GL/gl.h>

struct PFcontextRec;

namespace pf {

struct CompiledPrimitive;

// Plans the shading channels of a glBegin of `mode` drawing `prim`, into ctx.shading,
// ctx.begin_layout and the colour / texture-coordinate channel indices.
void planShading(PFcontextRec& ctx, GLenum mode, const CompiledPrimitive& prim);
// Appends the current sequence point's row of shading channels to ctx.row_shading.
void rowChannels(PFcontextRec& ctx);
// Lights the vertices waiting in ctx.vertex_lighting, into their rows' colour channels.
void flushVertexLighting(PFcontextRec& ctx);

}  // namespace pf
