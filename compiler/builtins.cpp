// Typing of built-in function calls (see builtins.h). Their expansion into instructions is in
// lower_expressions.cpp (Lowerer::call()); docs/language.md lists them.
#include "compiler/builtins.h"

#include <set>

namespace pf {

namespace {

bool isNumericScalar(const Type& t) {
  return t.dims.empty() && (t.base == BaseType::Float || t.base == BaseType::Int);
}
bool isAggregate(const Type& t) { return t.isAggregate() && t.base != BaseType::InterpData; }
// Types with an (x, y, z): points use their first three components.
bool isSpatial(const Type& t) {
  return t.dims.empty() && (t.base == BaseType::Point || t.base == BaseType::Vector || t.base == BaseType::Normal);
}

}  // namespace

int componentwiseArity(const std::string& f) {
  static const std::set<std::string> one = {"abs", "floor", "ceil", "fract", "sqrt", "sign", "sin",
                                            "cos", "tan", "asin", "acos", "atan", "exp", "log"};
  static const std::set<std::string> two = {"min", "max", "pow", "atan2", "mod", "step"};
  static const std::set<std::string> three = {"clamp", "mix", "smoothstep"};
  if (one.count(f)) return 1;
  if (two.count(f)) return 2;
  if (three.count(f)) return 3;
  return 0;
}

void typeBuiltinCall(Expr& e, UnitKind unit, const std::function<void(SourceLoc, const std::string&)>& err) {
  bool any_void = false;
  for (ExprPtr& a : e.args) {
    e.varying = e.varying || a->varying;
    any_void = any_void || a->type.base == BaseType::Void;
  }
  const std::string& f = e.name;
  size_t n = e.args.size();
  auto arity = [&](size_t lo, size_t hi) {
    if (n < lo || n > hi) {
      err(e.loc, f + "() takes " + (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) +
                     " argument" + (hi == 1 ? "" : "s") + ", not " + std::to_string(n));
      return false;
    }
    return true;
  };
  auto needScalars = [&]() {
    for (ExprPtr& a : e.args)
      if (a->type.base != BaseType::Void && !isNumericScalar(a->type)) {
        err(a->loc, f + "() takes float arguments, not " + typeName(a->type));
        return false;
      }
    return true;
  };
  auto needSpatial = [&](size_t i) {
    if (isSpatial(e.args[i]->type)) return true;
    err(e.args[i]->loc, f + "() takes a point, vector or normal here, not " + typeName(e.args[i]->type));
    return false;
  };

  if (int k = componentwiseArity(f)) {
    // Scalars, or aggregates of one type with scalars broadcast to every component.
    if (!arity(k, k) || any_void) return;
    Type agg;
    bool all_int = true;
    for (ExprPtr& a : e.args) {
      const Type& t = a->type;
      if (isNumericScalar(t)) {
        all_int = all_int && t.base == BaseType::Int;
        continue;
      }
      if (!isAggregate(t) || (agg.base != BaseType::Void && t != agg)) {
        err(a->loc, f + "() takes floats, or " + (agg.base != BaseType::Void ? typeName(agg) + "s" : std::string("vectors of one type")) +
                        " with floats, not " + typeName(t));
        return;
      }
      agg = t;
      all_int = false;
    }
    bool int_ok = f == "min" || f == "max" || f == "abs";
    e.type = agg.base != BaseType::Void ? agg : Type::of(all_int && int_ok ? BaseType::Int : BaseType::Float);
  } else if (f == "cross_sign") {
    if (!arity(4, 4) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "dot" || f == "distance") {
    if (!arity(2, 2) || any_void || !needSpatial(0) || !needSpatial(1)) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "cross") {
    if (!arity(2, 2) || any_void || !needSpatial(0) || !needSpatial(1)) return;
    e.type = Type::of(BaseType::Vector);
  } else if (f == "length") {
    if (!arity(1, 1) || any_void || !needSpatial(0)) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "normalize") {
    if (!arity(1, 1) || any_void || !needSpatial(0)) return;
    e.type = e.args[0]->type.base == BaseType::Normal ? Type::of(BaseType::Normal) : Type::of(BaseType::Vector);
  } else if (f == "reflect") {
    if (!arity(2, 2) || any_void || !needSpatial(0) || !needSpatial(1)) return;
    e.type = Type::of(BaseType::Vector);
  } else if (f == "refract") {
    if (!arity(3, 3) || any_void || !needSpatial(0) || !needSpatial(1)) return;
    if (!isNumericScalar(e.args[2]->type)) {
      err(e.args[2]->loc, "refract()'s third argument is the ratio of refractive indices, a float");
      return;
    }
    e.type = Type::of(BaseType::Vector);
  } else if (f == "faceforward") {
    if (!arity(3, 3) || any_void || !needSpatial(0) || !needSpatial(1) || !needSpatial(2)) return;
    e.type = e.args[0]->type.base == BaseType::Normal ? Type::of(BaseType::Normal) : Type::of(BaseType::Vector);
  } else if (f == "noise" || f == "snoise") {
    if (!arity(1, 1) || any_void) return;
    if (!isNumericScalar(e.args[0]->type) && !isSpatial(e.args[0]->type)) {
      err(e.args[0]->loc, f + "() takes a float, point, vector or normal, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(BaseType::Float);
  } else if (f == "screen") {
    if (!arity(1, 1) || any_void) return;
    if (e.args[0]->type != Type::of(BaseType::Point)) {
      err(e.args[0]->loc, "screen() maps a point from clip space to homogeneous screen space; it takes a point, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(BaseType::Point);
  } else if (f == "depth_range") {
    if (!arity(0, 0)) return;
    e.type = Type::of(BaseType::Vector);
  } else if (f == "culled") {
    // GL's face culling for a polygon of this window-space orientation (> 0: counter-clockwise).
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Bool);
  } else if (f == "facing") {
    // The instance's facing for two-sided lighting, from its window-space orientation: a
    // statement (uniform; sema checks).
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Void);
  } else if (f == "depth_bound") {
    // depth_bound(zmin, zmax): a promise that every pixel the instance draws passed ztest(z)
    // with z in [zmin, zmax] (window Z), so the renderer may skip blocks where none can pass: a
    // statement (uniform; sema checks; codegen refuses it in a primitive without ztest()).
    if (!arity(2, 2) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Void);
  } else if (f == "unscreen") {
    // The inverse of screen(): homogeneous window coordinates back to clip coordinates.
    if (!arity(1, 1) || any_void) return;
    if (e.args[0]->type != Type::of(BaseType::Point)) {
      err(e.args[0]->loc, "unscreen() maps a point from window to clip coordinates; it takes a point, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(BaseType::Point);
  } else if (f == "clip" || f == "object" || f == "eye_from_object") {
    // Eye to clip coordinates (the projection), eye to object coordinates (the inverse modelview),
    // object to eye coordinates (the modelview).
    if (!arity(1, 1) || any_void) return;
    if (e.args[0]->type != Type::of(BaseType::Point)) {
      err(e.args[0]->loc, f + "() maps a point between spaces; it takes a point, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(BaseType::Point);
  } else if (f == "object_matrix" || f == "eye_from_object_matrix" || f == "eye_matrix" || f == "clip_matrix" ||
             f == "screen_matrix") {
    // The matrix of the space transform of the same name: m * p == object(p), and so on.
    if (!arity(0, 0)) return;
    e.type = Type::of(BaseType::Matrix);
  } else if (f == "transpose" || f == "inverse" || f == "determinant") {
    // inverse(): by cofactors; a singular matrix gives infinities or NaNs, as a division by 0.
    if (!arity(1, 1) || any_void) return;
    if (e.args[0]->type != Type::of(BaseType::Matrix)) {
      err(e.args[0]->loc, f + "() takes a matrix, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(f == "determinant" ? BaseType::Float : BaseType::Matrix);
  } else if (f == "matrix") {
    // matrix(s): s on the diagonal, 0 elsewhere; matrix(m00, m01, ..., m33): 16 numbers, row by row.
    if (n != 1 && n != 16) {
      err(e.loc, "matrix() takes 1 number (the diagonal) or 16 (row by row), not " + std::to_string(n));
      return;
    }
    if (any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Matrix);
  } else if (f == "eye_normal") {
    // An object-space normal to eye space: the inverse transpose of the modelview.
    if (!arity(1, 1) || any_void) return;
    if (!isSpatial(e.args[0]->type) || e.args[0]->type.base == BaseType::Point) {
      err(e.args[0]->loc, "eye_normal() takes a normal or vector, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(BaseType::Normal);
  } else if (f == "eye") {
    // Clip to eye coordinates: the inverse projection applied to a point (P for shared
    // interpolators is in eye space).
    if (!arity(1, 1) || any_void) return;
    if (e.args[0]->type != Type::of(BaseType::Point)) {
      err(e.args[0]->loc, "eye() maps a point from clip to eye coordinates; it takes a point, not " + typeName(e.args[0]->type));
      return;
    }
    e.type = Type::of(BaseType::Point);
  } else if (f == "polygon_mode") {
    // glPolygonMode for a polygon of this window-space orientation (> 0: counter-clockwise):
    // 0 GL_FILL, 1 GL_LINE, 2 GL_POINT.
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "polygon_offset" || f == "polygon_offset_modes") {
    // glPolygonOffset: vector(factor, units r, 0); its enables: vector(fill, line, point), 1 or 0.
    if (!arity(0, 0)) return;
    e.type = Type::of(BaseType::Vector);
  } else if (f == "line_stipple") {
    // glLineStipple: vector(pattern, factor, 1 where GL_LINE_STIPPLE is enabled, else 0).
    if (!arity(0, 0)) return;
    e.type = Type::of(BaseType::Vector);
  } else if (f == "line_width" || f == "point_size") {
    // glLineWidth / glPointSize as rasterized: whole pixels, rounded and clamped as the API says.
    if (!arity(0, 0)) return;
    e.type = Type::of(BaseType::Float);
  } else if (f == "flat_shading" || f == "polygon_stipple") {
    // glShadeModel(GL_FLAT): per-vertex parameters take the provoking vertex's value.
    // glEnable(GL_POLYGON_STIPPLE): polygon_ztest() applies the stipple.
    if (!arity(0, 0)) return;
    e.type = Type::of(BaseType::Bool);
  } else if (f == "ztest" || f == "polygon_ztest") {
    // polygon_ztest(): ztest() for a fragment of a filled polygon, which the polygon stipple
    // (glPolygonStipple under GL_POLYGON_STIPPLE) may also fail.
    if (unit != UnitKind::Primitive) {
      err(e.loc, f + "() is only available in a primitive");
      return;
    }
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(BaseType::Bool);
    e.varying = true;
  } else if (f == "field_hit") {
    // field_hit(field, box_min, box_max, method, parameter): the t of the pixel's ray (from
    // object_ray_near(), t = 0, to object_ray_far(), t = 1) where it first meets the surface of
    // the context's field `field` inside the box; +inf where it does not.
    if (unit != UnitKind::Primitive) {
      err(e.loc, "field_hit() is only available in a primitive");
      return;
    }
    if (!arity(5, 5) || any_void) return;
    static const char* const roles[5] = {"field", "box minimum", "box maximum", "method", "method parameter"};
    for (size_t k = 0; k < 5; ++k) {
      const bool spatial = k == 1 || k == 2;
      if (spatial ? !isSpatial(e.args[k]->type) : !isNumericScalar(e.args[k]->type)) {
        err(e.args[k]->loc, std::string("field_hit()'s ") + roles[k] + " is " + (spatial ? "a point or vector" : "a float") +
                                ", not " + typeName(e.args[k]->type));
        return;
      }
      if (e.args[k]->varying) {
        err(e.args[k]->loc, std::string("field_hit()'s ") + roles[k] +
                                " must be uniform (one value per instance): the search culls whole blocks of pixels with it");
        return;
      }
    }
    e.type = Type::of(BaseType::Float);
    e.varying = true;
  } else if (f == "field_gradient" || f == "field_gradient_fd") {
    // The gradient of a context's field at a point: by the derived (automatic differentiation)
    // form, or by central differences (_fd) for comparison.
    if (unit != UnitKind::Primitive) {
      err(e.loc, f + "() is only available in a primitive");
      return;
    }
    if (!arity(2, 2) || any_void) return;
    if (!isNumericScalar(e.args[0]->type)) {
      err(e.args[0]->loc, f + "()'s field is a float, not " + typeName(e.args[0]->type));
      return;
    }
    if (!needSpatial(1)) return;
    e.type = Type::of(BaseType::Vector);
    e.varying = true;
  } else if (f == "field_color") {
    // The colour a context's field defines at a point (its attributes, HyperFun's s[1..3]; seed
    // 000's procedural colour), for a primitive's or a shared interpolator's shading parameters.
    if (unit != UnitKind::Primitive && unit != UnitKind::Interpolator) {
      err(e.loc, "field_color() is only available in a primitive or an interpolator");
      return;
    }
    if (!arity(2, 2) || any_void) return;
    if (!isNumericScalar(e.args[0]->type)) {
      err(e.args[0]->loc, "field_color()'s field is a float, not " + typeName(e.args[0]->type));
      return;
    }
    if (!needSpatial(1)) return;
    e.type = Type::of(BaseType::Color);
    e.varying = true;
  } else if (f == "float" || f == "int") {
    if (!arity(1, 1) || any_void || !needScalars()) return;
    e.type = Type::of(f == "float" ? BaseType::Float : BaseType::Int);
  } else if (f == "point" || f == "vector" || f == "normal" || f == "color") {
    BaseType b = f == "point" ? BaseType::Point : f == "vector" ? BaseType::Vector
                 : f == "normal" ? BaseType::Normal : BaseType::Color;
    size_t comps = Type::componentsOf(b);
    // point(x, y, z) has w = 1; color(r, g, b) has a = 1; one float fills a vector or colour.
    size_t lo = (b == BaseType::Point || b == BaseType::Color) ? 3 : comps;
    if (n == 1 && b != BaseType::Point) lo = 1;
    if (!arity(lo, comps) || any_void || !needScalars()) return;
    e.type = Type::of(b);
  } else {
    err(e.loc, "'" + f + "' is not a built-in function (nor a function defined in this source)");
  }
}

}  // namespace pf
