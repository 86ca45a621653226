// Scene files (tools/scene, docs/scenes.md): where JSON values start; that every kind of bad
// scene is refused with the file, the line and the key; and that a scene draws what it says --
// a sphere seen through the scene's camera and transform, checked against a ray cast in double
// through matrices built here from the same numbers, and an OBJ mesh's coverage.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "gl_context.h"
#include "scene/json_lines.h"
#include "scene/scene.h"

namespace {

using pf::scene::parseScene;
using pf::scene::SceneError;

TEST(JsonLines, ValuesAreFoundByPointer) {
  const std::string text =
      "{\n"
      "  \"a\": 1,\n"
      "  \"list\": [\n"
      "    {\"x\": \"s,t]\"},\n"
      "    [2, 3],\n"
      "    true\n"
      "  ],\n"
      "  \"we/ird\": {\"k\": null}\n"
      "}\n";
  const pf::scene::JsonLines lines(text);
  EXPECT_EQ(lines.lineOf(""), 1);
  EXPECT_EQ(lines.lineOf("/a"), 2);
  EXPECT_EQ(lines.lineOf("/list"), 3);
  EXPECT_EQ(lines.lineOf("/list/0/x"), 4);
  EXPECT_EQ(lines.lineOf("/list/1/1"), 5);
  EXPECT_EQ(lines.lineOf("/list/2"), 6);
  EXPECT_EQ(lines.lineOf("/we~1ird/k"), 8);
  EXPECT_EQ(lines.lineOf("/list/0/nothing"), 4);  // its nearest known ancestor
}

// Deep nesting: the scan keeps one frame a level and no path but the one asked for (a map of
// every value's path, as it once built, is quadratic in the depth: 60 GB here).
TEST(JsonLines, DeepNestingIsScannedInLinearMemory) {
  const int depth = 200000;
  const std::string text = std::string(depth, '[') + "\n1" + std::string(depth, ']');
  const pf::scene::JsonLines lines(text);
  std::string pointer;
  for (int i = 0; i < depth; ++i) pointer += "/0";
  EXPECT_EQ(lines.lineOf(pointer), 2);
  EXPECT_EQ(lines.lineOf("/0/0/1"), 1);  // not there: its longest prefix, /0/0
  EXPECT_EQ(pf::scene::jsonNesting(text).depth, depth);
}

// The message a scene gets, or "" if it loads.
std::string errorOf(const std::string& text) {
  try {
    parseScene(text, "t.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

struct BadScene {
  const char* text;
  const char* expected;  // a part of the message: file, line and key
};

TEST(SceneErrors, NameTheFileLineAndKey) {
  const BadScene cases[] = {
      {"{\n\"objects\": [\n", "t.json:3: error: not valid JSON"},
      // found by fuzz_scene: a number past double's range threw an exception nobody caught
      {"{\"objects\": [],\n \"camera\": {\"fov\": -0.5e4444446}}",
       "t.json:2: error: not valid JSON: number overflow parsing '-0.5e4444446'"},
      {"{\"objects\": []}\n", ""},
      // nesting far past a scene's: refused before parsing, at the line where it gets too deep
      {"{\"objects\": [],\n\"x\": [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[",
       "t.json:2: error: arrays and objects nest more than 64 deep here"},
      {"{}", "t.json:1: error: (the document): a scene needs \"objects\""},
      {"{\"objects\": [],\n \"camra\": {}}", "t.json:2: error: camra: unknown key 'camra'"},
      {"{\"objects\": [\n {\"primitive\": \"sphere\",\n  \"params\": {\"radius\": \"big\"}}]}",
       "t.json:3: error: objects[0].params.radius: no field named 'big'"},
      {"{\"objects\": [\n {\"primitive\": \"sphere\",\n  \"params\": {\"radius\": null}}]}",
       "t.json:3: error: objects[0].params.radius: expected a number, an array of 1 to 16 numbers or a field's name, "
       "found null"},
      {"{\"fields\": {\"f\": {\"fidget\": \"x var-x\\ny sqrt x x\\n\"}}, \"objects\": []}",
       "f:2:10: error: 'sqrt' takes 1 argument, found 2"},
      {"{\"fields\": {\"f\": {\"fidget\": \"x var-x\", \"file\": \"f.vm\"}}, \"objects\": []}",
       "t.json:1: error: fields.f: a field has exactly one of \"file\", \"fidget\", \"hyperfun\" or \"language\""},
      {"{\"fields\": {\"f\": {\"file\": \"f.obj\"}}, \"objects\": []}",
       "t.json:1: error: fields.f.file: 'f.obj': fields are read from Fidget .vm, HyperFun .hf, language .pfl or sampled .pfgrid files"},
      {"{\"fields\": {\"f\": {\"hyperfun\": \"my_model(x[3], a[1]) {\\n my_model = hfFoo(x);\\n}\"}}, \"objects\": []}",
       "f:2:13: error: unknown function 'hffoo'"},
      {"{\"fields\": {\"f\": {\"fidget\": \"x var-x\", \"time\": 1}}, \"objects\": []}",
       "t.json:1: error: fields.f: \"time\" and \"params\" are for HyperFun and language fields"},
      {"{\"fields\": {\"ball\": {\"language\": \"field float ball(point p, float r) {\\n  return r - length(p);\\n}\", \"time\": 1}},"
       " \"objects\": []}",
       "t.json:1: error: fields.ball: \"time\" is HyperFun's x[4]: a language field takes its values through \"params\""},
      {"{\"fields\": {\"ball\": {\"language\": \"field float ball(point p, float r) {\\n  return r - X;\\n}\", \"params\": [1]}},"
       " \"objects\": []}",
       "ball:2:14: error: 'X' is a pixel's built-in, which a field does not see"},
      {"{\"fields\": {\"f\": {\"hyperfun\": \"my_model(x[3], a[1]) { my_model = a[1]; }\", \"params\": [1, 2]}},"
       " \"objects\": []}",
       "f:1:16: error: 2 parameters given, but 'my_model' has a[1]"},
      {"{\"fields\": {\"f\": {\"file\": \"missing.vm\"}}, \"objects\": []}",
       "t.json:1: error: fields.f.file: cannot read 'missing.vm'"},
      {"{\"objects\": [{\"primitive\": \"sphere\", \"mesh\": \"a.obj\"}]}",
       "t.json:1: error: objects[0]: an object needs exactly one of \"primitive\" or \"mesh\""},
      {"{\"objects\": [\n{\"primitive\": \"sphere\",\n \"material\": \"gold\"}]}",
       "t.json:3: error: objects[0].material: no material named 'gold'"},
      {"{\"camera\": {\n\"near\": 2,\n\"far\": 1},\n\"objects\": []}",
       "t.json:3: error: camera.far: far must be greater than near"},
      {"{\"camera\": {\"eye\": [0, 0, 1],\n \"target\": [0, 0, 1]}, \"objects\": []}",
       "t.json:2: error: camera.target: the target must differ from the eye"},
      {"{\"lighting\": {\"lights\": [\n{\"type\": \"lamp\"}]}, \"objects\": []}",
       "t.json:2: error: lighting.lights[0].type: expected \"directional\", \"point\" or \"spot\""},
      {"{\"lighting\": {\"lights\": [{\"type\": \"point\",\n \"cutoff\": 10, \"position\": [0, 0, 0]}]}, \"objects\": []}",
       "t.json:2: error: lighting.lights[0].cutoff: only spot lights"},
      {"{\"image\": {\"size\": [640,\n 0]}, \"objects\": []}", "t.json:2: error: image.size[1]: expected a whole number"},
      {"{\"objects\": [{\"primitive\": \"sphere\", \"transform\": [\n{\"rotate\": [30, 0, 0, 0]}]}]}",
       "t.json:2: error: objects[0].transform[0].rotate: expected [degrees, x, y, z] with a non-zero axis"},
      {"{\"objects\": [{\"primitive\": \"triangles\", \"vertices\": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],\n"
       " \"colors\": [[1, 0, 0]]}]}",
       "t.json:2: error: objects[0].colors: expected one entry per vertex (3)"},
      {"{\"objects\": [{\"mesh\": \"no_such_file.obj\"}]}", "t.json:1: error: objects[0].mesh: cannot read OBJ file"},
      {"{\"primitives\": [\"missing.pfl\"], \"objects\": []}", "t.json:1: error: primitives[0]: cannot read"},
      {"{\"materials\": {\"m\": {\"shininess\": 500}}, \"objects\": []}",
       "t.json:1: error: materials.m.shininess: expected a number in [0, 128], found 500"},
      {"{\"objects\": [{\"primitive\": \"sphere\", \"params\": {\"v\": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, "
       "14, 15, 16, 17]}}]}",
       "t.json:1: error: objects[0].params.v: expected an array of 1 to 16 numbers"},
  };
  for (const BadScene& c : cases) {
    const std::string message = errorOf(c.text);
    if (std::string(c.expected).empty()) {
      EXPECT_EQ(message, "") << c.text;
    } else {
      EXPECT_NE(message.find(c.expected), std::string::npos) << "got: " << message << "\nwanted: " << c.expected;
    }
  }
}

constexpr int kW = 120, kH = 90;

// A sphere of radius 0.8 at world (0.3, 0.2, -0.5) (centre (0.1, 0, 0) in object coordinates,
// translated by (0.2, 0.2, -0.5)), camera at (0.5, 1, 4) looking at the origin, fov 40.
const char* kSphereScene = R"({
  "image": {"size": [120, 90], "background": [0, 0, 0, 0]},
  "camera": {"eye": [0.5, 1, 4], "target": [0, 0, 0], "fov": 40, "near": 1, "far": 20},
  "materials": {"red": {"color": [1, 0, 0]}},
  "objects": [
    {"primitive": "sphere", "material": "red", "transform": [{"translate": [0.2, 0.2, -0.5]}],
     "params": {"center": [0.1, 0, 0], "radius": 0.8}}
  ]
})";

TEST(SceneDrawing, ASphereThroughTheCameraMatchesARayCastInDouble) {
  const pf::scene::Scene scene = parseScene(kSphereScene, "sphere.json");
  ASSERT_EQ(scene.width, kW);
  pf::test::GlContext c(kW, kH);
  pf::scene::drawScene(scene, kW, kH);
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));

  const glm::dmat4 view = glm::lookAt(glm::dvec3(0.5, 1, 4), glm::dvec3(0), glm::dvec3(0, 1, 0));
  const glm::dmat4 proj = glm::perspective(glm::radians(40.0), double(kW) / kH, 1.0, 20.0);
  const glm::dmat4 inv = glm::inverse(proj * view);
  const glm::dvec3 centre(0.3, 0.2, -0.5);
  int inside = 0, judged = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double nx = (x + 0.5) / kW * 2 - 1, ny = (y + 0.5) / kH * 2 - 1;
      const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
      const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::normalize(glm::dvec3(b) / b.w - o);
      const double along = glm::dot(centre - o, d);
      const double miss = glm::length(o + d * along - centre);  // the ray's distance from the centre
      if (std::abs(miss - 0.8) < 0.01) continue;               // the rim: either answer
      ++judged;
      const bool hit = miss < 0.8;
      inside += hit;
      EXPECT_EQ(c.at(x, y)[0], hit ? 255 : 0) << "(" << x << ", " << y << ")";
      EXPECT_EQ(c.at(x, y)[1], 0);
    }
  EXPECT_GT(inside, 500);
  EXPECT_GT(judged, kW * kH - 300);
}

TEST(SceneDrawing, AnObjMeshCoversWhatItsTrianglesCover) {
  // A unit square in z = 0 as two triangles, without normals (they are computed), seen from
  // straight ahead by an orthographic camera 4 units tall: it covers the middle quarter.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "pf_scene_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream obj(dir / "square.obj");
    obj << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
    std::ofstream json(dir / "square.json");
    json << R"({"image": {"size": [80, 80], "background": [0, 0, 0, 0]},
                "camera": {"projection": "ortho", "eye": [0, 0, 5], "target": [0, 0, 0], "height": 4, "near": 1, "far": 10},
                "objects": [{"mesh": "square.obj", "material": "white"}],
                "materials": {"white": {"color": [1, 1, 1]}}})";
  }
  const pf::scene::Scene scene = pf::scene::loadScene((dir / "square.json").string());
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].vertices.size(), 6u);
  EXPECT_NEAR(scene.objects[0].normals[0].z, 1.0, 1e-12);
  pf::test::GlContext c(80, 80);
  pf::scene::drawScene(scene, 80, 80);
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 80; ++x) {
      const bool in = x >= 20 && x < 60 && y >= 20 && y < 60;
      EXPECT_EQ(c.at(x, y)[0], in ? 255 : 0) << "(" << x << ", " << y << ")";
    }
  std::filesystem::remove_all(dir);
}

TEST(SceneDrawing, AnUnknownPrimitiveIsReportedWithItsLine) {
  const pf::scene::Scene scene = parseScene("{\"objects\": [\n{\"primitive\": \"dodecahedron\"}]}", "s.json");
  pf::test::GlContext c(16, 16);
  try {
    pf::scene::drawScene(scene, 16, 16);
    FAIL() << "drew an unknown primitive";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json:2: error: no primitive named 'dodecahedron'"), std::string::npos)
        << e.what();
  }
}

TEST(SceneDrawing, AMissingParameterIsReportedWithItsLine) {
  const pf::scene::Scene scene =
      parseScene("{\"objects\": [\n{\"primitive\": \"sphere\",\n \"params\": {\"radius\": 1}}]}", "s.json");
  pf::test::GlContext c(16, 16);
  try {
    pf::scene::drawScene(scene, 16, 16);
    FAIL() << "drew a sphere without a centre";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json:2: error: 'sphere' refused"), std::string::npos) << e.what();
  }
}

}  // namespace
