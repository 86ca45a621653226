// One value glGet* reads (state_queries.cpp), and the GL 1.x state primflow holds constant
// (constant_queries.cpp).
#pragma once

#include <initializer_list>

#include <GL/gl.h>

namespace pf {

// Up to 16 numbers, and whether GL maps them to integers as normalised values (colours,
// depths, normals: 1.0 -> 2^31 - 1, GL 1.5 section 6.1.2).
struct Query {
  double v[16];
  int count = 0;
  bool normalized = false;
  void set(std::initializer_list<double> values, bool is_normalized = false) {
    count = 0;
    for (double d : values) v[count++] = d;
    normalized = is_normalized;
  }
};

// The GL 1.x state of what primflow does not have -- evaluators, selection, ... -- which no command changes: GL's initial values (those
// OSMesa reports in a new context); and primflow's implementation limits for them. False for a
// token that is not GL 1.x state.
bool constantQuery(GLenum pname, Query& q);
// The same for glIsEnabled: whether `cap` is one of those capabilities, and its (fixed) value.
bool constantCapability(GLenum cap, bool& enabled);

}  // namespace pf
