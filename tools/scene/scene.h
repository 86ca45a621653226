// A scene read from a JSON file (docs/scenes.md): camera, lights, materials and the objects to
// draw -- instances of any primitive with their parameters, vertex lists for the GL modes, and
// triangle meshes from OBJ files. Loading checks everything it can without a context; drawing
// (scene_draw.cpp) issues the GL and extension calls, the same ones an application would.
#pragma once

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/field/field_source.h"

namespace pf::scene {

// A bad scene: the message names the file, the line and the key ("FILE:LINE: error: KEY: ...").
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Where a value came from, for errors found while drawing: its JSON pointer (the line is
// found from the scene's text only when an error needs it).
struct Origin {
  std::string key;
};

struct Camera {
  bool ortho = false;
  glm::dvec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  double fov_degrees = 45;  // vertical, perspective
  double height = 4;        // of the view at the target, orthographic
  double near = 0.1, far = 100;
};

struct Light {
  enum class Kind { Directional, Point, Spot } kind = Kind::Directional;
  glm::dvec3 position{0, 0, 1};  // directional: the direction *towards* the light
  glm::dvec3 spot_direction{0, 0, -1};
  double spot_cutoff = 180, spot_exponent = 0;
  glm::dvec4 ambient{0, 0, 0, 1}, diffuse{1, 1, 1, 1}, specular{1, 1, 1, 1};
  glm::dvec3 attenuation{1, 0, 0};  // constant, linear, quadratic
};

// A named parameter's current value (pfglRastParamfvEXT), 1 to 16 numbers -- or the name of one
// of the scene's fields (`field`), whose id the parameter then takes (the implicit primitive's
// "field").
struct ParamValue {
  std::string name;
  std::vector<double> values;
  std::string field;
};

// A field of the scene ("fields"): a model for implicit surfaces, read from a file or given
// inline, compiled with pfglCompileFieldEXT under its name.
struct FieldSource {
  std::string name;
  std::string file;  // as named in messages (the file, or the scene's key for inline text)
  std::string text;
  Origin origin;
  field::FieldFormat format = field::FieldFormat::Fidget;
  double time = 0.0;           // HyperFun: x[4]
  std::vector<double> params;  // HyperFun: a[1], a[2], ...; a language field's parameters after p
};

struct Material {
  glm::dvec4 color{0.8, 0.8, 0.8, 1};  // ambient and diffuse (through GL_COLOR_MATERIAL)
  glm::dvec4 specular{0, 0, 0, 1}, emission{0, 0, 0, 1};
  double shininess = 0;
  // Shading parameter -> "perspective_linear", "linear" or a shared interpolator's name.
  std::map<std::string, std::string> interpolators;
  std::vector<ParamValue> params;  // the interpolators' parameters
  Origin origin;
};

struct Transform {
  glm::dmat4 matrix{1.0};
};

// One glBegin ... glEnd: a primitive (any registered mode, built-in or compiled from the
// scene's sources) with one sequence point per instance, or a triangle mesh.
struct Object {
  std::string primitive;                       // glBegin mode's name ("sphere", "triangles", ...)
  std::string material;                        // empty: the default material
  glm::dmat4 transform{1.0};                   // object -> world
  std::vector<ParamValue> params;              // set once, before the sequence points
  std::vector<std::vector<ParamValue>> points; // per sequence point
  // Vertex lists (GL modes, meshes): one sequence point per vertex.
  std::vector<glm::dvec3> vertices, normals;
  std::vector<glm::dvec4> colors;
  Origin origin;
};

struct Scene {
  std::string path;         // the file, for messages
  std::shared_ptr<const std::string> text;  // its text, for the line numbers of errors
  int width = 960, height = 640;
  glm::dvec4 background{0.06, 0.07, 0.10, 1};
  Camera camera;
  bool lighting = false;
  glm::dvec4 global_ambient{0.2, 0.2, 0.2, 1};
  bool two_side = false, local_viewer = false;
  bool per_pixel = false;  // GL polygons lit per pixel (GL_PER_PIXEL_LIGHTING_EXT)
  std::vector<Light> lights;
  std::vector<std::pair<std::string, std::string>> sources;  // (path, text) of .pfl files
  std::vector<FieldSource> fields;
  std::map<std::string, Material> materials;
  std::vector<Object> objects;
};

// The 1-based line of the scene's text where `origin`'s value starts.
int lineOf(const Scene& scene, const Origin& origin);

// Reads a scene file; throws SceneError.
Scene loadScene(const std::string& path);
// Parses scene text (`path` names it in messages and resolves relative file names). With
// allow_files false, a scene naming a file (an OBJ mesh, a primitive source) is refused instead
// of read (the fuzzer's setting).
Scene parseScene(const std::string& text, const std::string& path, bool allow_files = true);

// Compiles the scene's primitive sources (pfglCompilePrimitivesEXT) and fields
// (pfglCompileFieldEXT) into the current context; throws SceneError with the diagnostics.
void compileSceneSources(const Scene& scene);

// Draws the scene into the current context at width x height: compiles its sources (unless
// they already are, compile_sources = false), sets the camera, lights and materials, and draws
// every object, then glFinish. Throws SceneError naming the object's line when the context
// rejects something (unknown primitive, a parameter missing or of the wrong size).
void drawScene(const Scene& scene, int width, int height, bool compile_sources = true);

// drawScene in pieces, for a renderer that draws only some of the objects (pfrender-mpi):
// beginScene compiles the sources (unless compile_sources is false), clears, and sets the
// camera and lights; drawObject draws one object as drawScene would (throws SceneError).
// drawScene is beginScene, drawObject for each object in order, then glFinish.
void beginScene(const Scene& scene, int width, int height, bool compile_sources = true);
void drawObject(const Scene& scene, const Object& object);

}  // namespace pf::scene
