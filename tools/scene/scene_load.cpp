// Reading a scene file (docs/scenes.md) into a Scene, checking every key: an unknown key, a
// value of the wrong kind or out of range is an error naming the file, the line and the key.
#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "scene/json_lines.h"
#include "scene/obj_mesh.h"
#include "scene/scene.h"
#include "text_file.h"

#include "compiler/field/field_source.h"

namespace pf::scene {

namespace {

using nlohmann::json;


// "/objects/3/params/radius" -> "objects[3].params.radius"
std::string keyName(const std::string& pointer) {
  std::string out;
  size_t i = 1;
  while (i <= pointer.size() && !pointer.empty()) {
    size_t j = pointer.find('/', i);
    if (j == std::string::npos) j = pointer.size();
    std::string token = pointer.substr(i, j - i);
    const bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + token + "]" : (out.empty() ? "" : ".") + token;
    i = j + 1;
  }
  return out.empty() ? "(the document)" : out;
}

class Reader {
 public:
  Reader(const std::string& text, const std::string& path, bool allow_files)
      : text_(text), path_(path), allow_files_(allow_files) {}

  // The lines are found only for an error: a scene of 100k spheres is read without mapping
  // its 300k values to lines.
  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    throw SceneError(path_ + ":" + std::to_string(JsonLines(text_).lineOf(pointer)) + ": error: " +
                     keyName(pointer) + ": " + message);
  }
  Origin origin(const std::string& pointer) const { return {pointer}; }
  // The scene's field names, which string parameter values may name (read before the objects).
  std::set<std::string> field_names_;
  const std::string& path() const { return path_; }

  // Fails on a key of `j` outside `known`.
  void onlyKeys(const json& j, const std::string& p, std::initializer_list<const char*> known) const {
    if (!j.is_object()) fail(p, "expected an object");
    for (const auto& [key, value] : j.items()) {
      bool ok = false;
      std::string list;
      for (const char* k : known) {
        ok |= key == k;
        list += std::string(list.empty() ? "" : ", ") + k;
      }
      if (!ok) fail(p + "/" + pointerToken(key), "unknown key '" + key + "' (expected one of: " + list + ")");
    }
  }

  double number(const json& j, const std::string& p) const {
    if (!j.is_number()) fail(p, std::string("expected a number, found ") + j.type_name());
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(p, "expected a finite number");
    return v;
  }
  double number(const json& j, const std::string& p, double lo, double hi) const {
    const double v = number(j, p);
    if (v < lo || v > hi) {
      std::ostringstream m;
      m << "expected a number in [" << lo << ", " << hi << "], found " << v;
      fail(p, m.str());
    }
    return v;
  }
  bool boolean(const json& j, const std::string& p) const {
    if (!j.is_boolean()) fail(p, std::string("expected true or false, found ") + j.type_name());
    return j.get<bool>();
  }
  std::string string(const json& j, const std::string& p) const {
    if (!j.is_string()) fail(p, std::string("expected a string, found ") + j.type_name());
    return j.get<std::string>();
  }
  std::vector<double> numbers(const json& j, const std::string& p, size_t min_count, size_t max_count) const {
    if (!j.is_array() || j.size() < min_count || j.size() > max_count)
      fail(p, "expected an array of " +
                  (min_count == max_count ? std::to_string(min_count) : std::to_string(min_count) + " to " +
                                                                             std::to_string(max_count)) +
                  " numbers");
    std::vector<double> out;
    for (size_t i = 0; i < j.size(); ++i) out.push_back(number(j[i], p + "/" + std::to_string(i)));
    return out;
  }
  glm::dvec3 vec3(const json& j, const std::string& p) const {
    const auto v = numbers(j, p, 3, 3);
    return {v[0], v[1], v[2]};
  }
  // A colour: 3 numbers (alpha 1) or 4.
  glm::dvec4 color(const json& j, const std::string& p) const {
    const auto v = numbers(j, p, 3, 4);
    return {v[0], v[1], v[2], v.size() > 3 ? v[3] : 1.0};
  }
  // A parameter value: a number or an array of 1 to 16 numbers.
  ParamValue param(const std::string& name, const json& j, const std::string& p) const {
    ParamValue v{name, {}, {}};
    if (j.is_string()) {
      v.field = j.get<std::string>();
      if (!field_names_.count(v.field))
        fail(p, "no field named '" + v.field + "' (a string value names one of the scene's \"fields\")");
      return v;
    }
    if (j.is_number()) v.values.push_back(number(j, p));
    else if (j.is_boolean()) v.values.push_back(j.get<bool>() ? 1 : 0);
    else if (j.is_array()) v.values = numbers(j, p, 1, 16);
    else fail(p, std::string("expected a number, an array of 1 to 16 numbers or a field's name, found ") + j.type_name());
    return v;
  }
  std::vector<ParamValue> params(const json& j, const std::string& p) const {
    if (!j.is_object()) fail(p, "expected an object of parameter values");
    std::vector<ParamValue> out;
    for (const auto& [key, value] : j.items()) out.push_back(param(key, value, p + "/" + pointerToken(key)));
    return out;
  }
  // A path in the scene relative to the scene file's folder.
  std::string relativePath(const std::string& file, const std::string& p) const {
    if (!allow_files_) fail(p, "files are not read here");
    const std::filesystem::path f(file);
    if (f.is_absolute()) return file;
    return (std::filesystem::path(path_).parent_path() / f).string();
  }

 private:
  const std::string& text_;
  std::string path_;
  bool allow_files_;
};

void readImage(const Reader& r, const json& j, Scene& s) {
  r.onlyKeys(j, "/image", {"size", "background"});
  if (j.contains("size")) {
    const auto v = r.numbers(j["size"], "/image/size", 2, 2);
    for (int k = 0; k < 2; ++k)
      if (v[k] < 1 || v[k] > 8192 || v[k] != std::floor(v[k]))
        r.fail("/image/size/" + std::to_string(k), "expected a whole number of pixels in [1, 8192]");
    s.width = static_cast<int>(v[0]);
    s.height = static_cast<int>(v[1]);
  }
  if (j.contains("background")) s.background = r.color(j["background"], "/image/background");
}

void readCamera(const Reader& r, const json& j, Camera& c) {
  const std::string p = "/camera";
  r.onlyKeys(j, p, {"projection", "eye", "target", "up", "fov", "height", "near", "far"});
  if (j.contains("projection")) {
    const std::string kind = r.string(j["projection"], p + "/projection");
    if (kind != "perspective" && kind != "ortho") r.fail(p + "/projection", "expected \"perspective\" or \"ortho\"");
    c.ortho = kind == "ortho";
  }
  if (j.contains("eye")) c.eye = r.vec3(j["eye"], p + "/eye");
  if (j.contains("target")) c.target = r.vec3(j["target"], p + "/target");
  if (j.contains("up")) c.up = r.vec3(j["up"], p + "/up");
  if (j.contains("fov")) c.fov_degrees = r.number(j["fov"], p + "/fov", 1e-3, 179);
  if (j.contains("height")) c.height = r.number(j["height"], p + "/height", 1e-9, 1e9);
  if (j.contains("near")) c.near = r.number(j["near"], p + "/near", 1e-9, 1e9);
  if (j.contains("far")) c.far = r.number(j["far"], p + "/far", 1e-9, 1e12);
  if (!(c.far > c.near)) r.fail(p + (j.contains("far") ? "/far" : ""), "far must be greater than near");
  if (glm::length(c.target - c.eye) == 0) r.fail(p + "/target", "the target must differ from the eye");
  if (glm::length(glm::cross(c.target - c.eye, c.up)) == 0) r.fail(p + "/up", "up must not be parallel to the view");
}

Light readLight(const Reader& r, const json& j, const std::string& p) {
  r.onlyKeys(j, p, {"type", "direction", "position", "spot_direction", "cutoff", "exponent", "ambient", "diffuse",
                    "specular", "attenuation"});
  Light l;
  const std::string type = j.contains("type") ? r.string(j["type"], p + "/type") : "directional";
  if (type == "directional") {
    l.kind = Light::Kind::Directional;
    if (!j.contains("direction")) r.fail(p, "a directional light needs \"direction\" (towards the light)");
    l.position = r.vec3(j["direction"], p + "/direction");
    if (glm::length(l.position) == 0) r.fail(p + "/direction", "expected a non-zero direction");
  } else if (type == "point" || type == "spot") {
    l.kind = type == "point" ? Light::Kind::Point : Light::Kind::Spot;
    if (!j.contains("position")) r.fail(p, "a " + type + " light needs \"position\"");
    l.position = r.vec3(j["position"], p + "/position");
  } else {
    r.fail(p + "/type", "expected \"directional\", \"point\" or \"spot\", found \"" + type + "\"");
  }
  if (l.kind == Light::Kind::Spot) {
    if (j.contains("spot_direction")) l.spot_direction = r.vec3(j["spot_direction"], p + "/spot_direction");
    l.spot_cutoff = j.contains("cutoff") ? r.number(j["cutoff"], p + "/cutoff", 0, 90) : 45;
    if (j.contains("exponent")) l.spot_exponent = r.number(j["exponent"], p + "/exponent", 0, 128);
  } else {
    for (const char* k : {"spot_direction", "cutoff", "exponent"})
      if (j.contains(k)) r.fail(p + "/" + k, "only spot lights have \"" + std::string(k) + "\"");
  }
  if (j.contains("ambient")) l.ambient = r.color(j["ambient"], p + "/ambient");
  if (j.contains("diffuse")) l.diffuse = r.color(j["diffuse"], p + "/diffuse");
  if (j.contains("specular")) l.specular = r.color(j["specular"], p + "/specular");
  if (j.contains("attenuation")) {
    l.attenuation = r.vec3(j["attenuation"], p + "/attenuation");
    if (l.attenuation.x < 0 || l.attenuation.y < 0 || l.attenuation.z < 0)
      r.fail(p + "/attenuation", "attenuation factors must not be negative");
  }
  return l;
}

void readLighting(const Reader& r, const json& j, Scene& s) {
  const std::string p = "/lighting";
  r.onlyKeys(j, p, {"ambient", "two_side", "local_viewer", "per_pixel", "lights"});
  s.lighting = true;
  if (j.contains("ambient")) s.global_ambient = r.color(j["ambient"], p + "/ambient");
  if (j.contains("two_side")) s.two_side = r.boolean(j["two_side"], p + "/two_side");
  if (j.contains("local_viewer")) s.local_viewer = r.boolean(j["local_viewer"], p + "/local_viewer");
  if (j.contains("per_pixel")) s.per_pixel = r.boolean(j["per_pixel"], p + "/per_pixel");
  if (j.contains("lights")) {
    const json& lights = j["lights"];
    if (!lights.is_array() || lights.size() > 8) r.fail(p + "/lights", "expected an array of at most 8 lights");
    for (size_t i = 0; i < lights.size(); ++i) s.lights.push_back(readLight(r, lights[i], p + "/lights/" + std::to_string(i)));
  }
}

Material readMaterial(const Reader& r, const json& j, const std::string& p) {
  r.onlyKeys(j, p, {"color", "specular", "emission", "shininess", "interpolators", "params"});
  Material m;
  m.origin = r.origin(p);
  if (j.contains("color")) m.color = r.color(j["color"], p + "/color");
  if (j.contains("specular")) m.specular = r.color(j["specular"], p + "/specular");
  if (j.contains("emission")) m.emission = r.color(j["emission"], p + "/emission");
  if (j.contains("shininess")) m.shininess = r.number(j["shininess"], p + "/shininess", 0, 128);
  if (j.contains("interpolators")) {
    const json& b = j["interpolators"];
    if (!b.is_object()) r.fail(p + "/interpolators", "expected an object: shading parameter -> interpolator name");
    for (const auto& [param, interp] : b.items())
      m.interpolators[param] = r.string(interp, p + "/interpolators/" + pointerToken(param));
  }
  if (j.contains("params")) m.params = r.params(j["params"], p + "/params");
  return m;
}

glm::dmat4 readTransform(const Reader& r, const json& j, const std::string& p) {
  if (!j.is_array()) r.fail(p, "expected an array of steps such as {\"translate\": [x, y, z]}");
  glm::dmat4 m(1.0);
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string q = p + "/" + std::to_string(i);
    const json& step = j[i];
    r.onlyKeys(step, q, {"translate", "rotate", "scale", "matrix"});
    if (step.size() != 1) r.fail(q, "expected exactly one of translate, rotate, scale, matrix");
    if (step.contains("translate")) {
      m = glm::translate(m, r.vec3(step["translate"], q + "/translate"));
    } else if (step.contains("rotate")) {
      const auto v = r.numbers(step["rotate"], q + "/rotate", 4, 4);
      const glm::dvec3 axis(v[1], v[2], v[3]);
      if (glm::length(axis) == 0) r.fail(q + "/rotate", "expected [degrees, x, y, z] with a non-zero axis");
      m = glm::rotate(m, glm::radians(v[0]), glm::normalize(axis));
    } else if (step.contains("scale")) {
      const json& v = step["scale"];
      m = glm::scale(m, v.is_number() ? glm::dvec3(r.number(v, q + "/scale")) : r.vec3(v, q + "/scale"));
    } else {
      const auto v = r.numbers(step["matrix"], q + "/matrix", 16, 16);
      glm::dmat4 n;
      for (int k = 0; k < 16; ++k) n[k / 4][k % 4] = v[k];  // column-major, as glMultMatrix
      m = m * n;
    }
  }
  return m;
}

Object readObject(const Reader& r, const json& j, const std::string& p, const Scene& s) {
  r.onlyKeys(j, p, {"primitive", "mesh", "material", "transform", "params", "instances", "vertices", "normals", "colors"});
  Object o;
  o.origin = r.origin(p);
  if (j.contains("primitive") == j.contains("mesh")) r.fail(p, "an object needs exactly one of \"primitive\" or \"mesh\"");
  if (j.contains("material")) {
    o.material = r.string(j["material"], p + "/material");
    if (!s.materials.count(o.material)) r.fail(p + "/material", "no material named '" + o.material + "'");
  }
  if (j.contains("transform")) o.transform = readTransform(r, j["transform"], p + "/transform");
  if (j.contains("params")) o.params = r.params(j["params"], p + "/params");
  if (j.contains("mesh")) {
    for (const char* k : {"instances", "vertices", "normals", "colors"})
      if (j.contains(k)) r.fail(p + "/" + k, "a mesh takes its vertices from its file");
    const std::string file = r.relativePath(r.string(j["mesh"], p + "/mesh"), p + "/mesh");
    std::string error;
    if (!loadObjMesh(file, o.vertices, o.normals, error)) r.fail(p + "/mesh", error);
    o.primitive = "triangles";
    return o;
  }
  o.primitive = r.string(j["primitive"], p + "/primitive");
  if (j.contains("vertices")) {
    if (j.contains("instances")) r.fail(p + "/instances", "vertices are the sequence points: no \"instances\" with them");
    const json& v = j["vertices"];
    if (!v.is_array() || v.empty()) r.fail(p + "/vertices", "expected a non-empty array of [x, y, z]");
    for (size_t i = 0; i < v.size(); ++i) o.vertices.push_back(r.vec3(v[i], p + "/vertices/" + std::to_string(i)));
    auto perVertex = [&](const char* key, auto read) {
      if (!j.contains(key)) return;
      const json& a = j[key];
      if (!a.is_array() || a.size() != v.size())
        r.fail(p + "/" + key, "expected one entry per vertex (" + std::to_string(v.size()) + ")");
      for (size_t i = 0; i < a.size(); ++i) read(a[i], p + "/" + key + "/" + std::to_string(i));
    };
    perVertex("normals", [&](const json& e, const std::string& q) { o.normals.push_back(r.vec3(e, q)); });
    perVertex("colors", [&](const json& e, const std::string& q) { o.colors.push_back(r.color(e, q)); });
    return o;
  }
  for (const char* k : {"normals", "colors"})
    if (j.contains(k)) r.fail(p + "/" + k, "only objects with \"vertices\" take per-vertex " + std::string(k));
  if (j.contains("instances")) {
    const json& inst = j["instances"];
    if (!inst.is_array() || inst.empty()) r.fail(p + "/instances", "expected a non-empty array of parameter objects");
    for (size_t i = 0; i < inst.size(); ++i) o.points.push_back(r.params(inst[i], p + "/instances/" + std::to_string(i)));
  } else {
    o.points.emplace_back();  // one sequence point, holding "params"
  }
  return o;
}

}  // namespace

// "fields": name -> {"file": "model.vm", "model.hf" or "model.pfl"}, or inline text as
// {"fidget": ...}, {"hyperfun": ...} or {"language": ...}; "time" (HyperFun's x[4]) and "params"
// (HyperFun's a[], a language field's parameters after its point). A language source's field is
// the unit named as the scene's field, or its only one. Each is read and checked now, so that a
// bad model is reported with its own file, line and column.
void readFields(const Reader& r, const json& j, Scene& s) {
  using field::FieldFormat;
  const char* const shape = "name -> {\"file\": ...}, {\"fidget\": ...}, {\"hyperfun\": ...} or {\"language\": ...}";
  if (!j.is_object()) r.fail("/fields", std::string("expected an object: ") + shape);
  for (const auto& [name, f] : j.items()) {
    const std::string p = "/fields/" + pointerToken(name);
    r.onlyKeys(f, p, {"file", "fidget", "hyperfun", "language", "time", "params"});
    if (f.contains("file") + f.contains("fidget") + f.contains("hyperfun") + f.contains("language") != 1)
      r.fail(p, "a field has exactly one of \"file\", \"fidget\", \"hyperfun\" or \"language\" (inline text)");
    FieldSource src{name, name, {}, r.origin(p), FieldFormat::Fidget, 0.0, {}};
    if (f.contains("file")) {
      src.file = r.relativePath(r.string(f["file"], p + "/file"), p + "/file");
      const std::optional<FieldFormat> format = field::fieldFormatOfPath(src.file);
      if (!format)
        r.fail(p + "/file",
               "'" + src.file + "': fields are read from Fidget .vm, HyperFun .hf, language .pfl or sampled .pfgrid files");
      src.format = *format;
      std::string why;
      if (!tools::readTextFile(src.file, src.text, why)) r.fail(p + "/file", "cannot read '" + src.file + "': " + why);
    } else {
      const char* key = f.contains("fidget") ? "fidget" : f.contains("hyperfun") ? "hyperfun" : "language";
      src.format = f.contains("fidget") ? FieldFormat::Fidget : f.contains("hyperfun") ? FieldFormat::HyperFun : FieldFormat::Language;
      src.text = r.string(f[key], p + "/" + key);
    }
    if ((src.format == FieldFormat::Fidget || src.format == FieldFormat::Sampled) && (f.contains("time") || f.contains("params")))
      r.fail(p, "\"time\" and \"params\" are for HyperFun and language fields; Fidget models and sampled fields have neither");
    if (src.format == FieldFormat::Language && f.contains("time"))
      r.fail(p, "\"time\" is HyperFun's x[4]: a language field takes its values through \"params\"");
    if (f.contains("time")) src.time = r.number(f["time"], p + "/time");
    if (f.contains("params")) src.params = r.numbers(f["params"], p + "/params", 1, 1000);
    DiagnosticLog log;
    // A language field is chosen by the scene's name for it, as drawing (the API) does; the
    // diagnostics name the file.
    const std::string unit = std::filesystem::path(name).stem().string();
    if (!field::compileFieldSource(src.format, src.file, src.text, src.params, src.time, log, unit))
      throw SceneError(log.format());
    s.fields.push_back(std::move(src));
  }
}

Scene parseScene(const std::string& text, const std::string& path, bool allow_files) {
  // A scene nests a few levels (objects, a mesh's arrays): far deeper is refused before parsing,
  // whose trees and error lines would take memory in proportion to the depth and more.
  constexpr int kMaxNesting = 64;
  if (const JsonNesting n = jsonNesting(text); n.depth > kMaxNesting)
    throw SceneError(path + ":" + std::to_string(n.line) + ": error: arrays and objects nest more than " +
                     std::to_string(kMaxNesting) + " deep here (a scene needs a few levels)");
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    // nlohmann reports a byte offset: turn it into a line.
    // e.byte is 1-based: the characters before the offending one are [0, byte - 1).
    const size_t before = std::min(e.byte > 0 ? static_cast<size_t>(e.byte - 1) : size_t{0}, text.size());
    const long line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(before), '\n');
    std::string what = e.what();
    const size_t colon = what.find(": ", what.find("parse error"));
    throw SceneError(path + ":" + std::to_string(line) + ": error: not valid JSON: " +
                     (colon != std::string::npos ? what.substr(colon + 2) : what));
  } catch (const json::out_of_range& e) {
    // A number past double's range ("number overflow parsing '1e999'"): nlohmann gives no
    // offset, so find the quoted token in the text for the line.
    const std::string what = e.what();
    const size_t open = what.find('\'');
    const size_t close = open == std::string::npos ? open : what.find('\'', open + 1);
    long line = 0;
    if (close != std::string::npos) {
      const size_t at = text.find(what.substr(open + 1, close - open - 1));
      if (at != std::string::npos) line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
    }
    const size_t tail = what.find("] ");
    throw SceneError(path + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                     ": error: not valid JSON: " + (tail != std::string::npos ? what.substr(tail + 2) : what));
  }
  Reader r(text, path, allow_files);
  Scene s;
  s.path = path;
  s.text = std::make_shared<const std::string>(text);
  r.onlyKeys(doc, "", {"image", "camera", "lighting", "primitives", "fields", "materials", "objects"});
  if (doc.contains("fields")) {
    readFields(r, doc["fields"], s);
    for (const FieldSource& f : s.fields) r.field_names_.insert(f.name);
  }
  if (doc.contains("image")) readImage(r, doc["image"], s);
  if (doc.contains("camera")) readCamera(r, doc["camera"], s.camera);
  if (doc.contains("lighting")) readLighting(r, doc["lighting"], s);
  if (doc.contains("primitives")) {
    const json& src = doc["primitives"];
    if (!src.is_array()) r.fail("/primitives", "expected an array of .pfl file names");
    for (size_t i = 0; i < src.size(); ++i) {
      const std::string q = "/primitives/" + std::to_string(i);
      const std::string file = r.relativePath(r.string(src[i], q), q);
      std::string body, why;
      if (!tools::readTextFile(file, body, why)) r.fail(q, "cannot read '" + file + "': " + why);
      s.sources.emplace_back(file, std::move(body));
    }
  }
  if (doc.contains("materials")) {
    const json& mats = doc["materials"];
    if (!mats.is_object()) r.fail("/materials", "expected an object: name -> material");
    for (const auto& [name, m] : mats.items()) s.materials[name] = readMaterial(r, m, "/materials/" + pointerToken(name));
  }
  if (!doc.contains("objects")) r.fail("", "a scene needs \"objects\"");
  const json& objects = doc["objects"];
  if (!objects.is_array()) r.fail("/objects", "expected an array of objects");
  for (size_t i = 0; i < objects.size(); ++i) s.objects.push_back(readObject(r, objects[i], "/objects/" + std::to_string(i), s));
  return s;
}

int lineOf(const Scene& scene, const Origin& origin) {
  return scene.text ? JsonLines(*scene.text).lineOf(origin.key) : 1;
}

Scene loadScene(const std::string& path) {
  std::string text, why;
  if (!tools::readTextFile(path, text, why)) throw SceneError(path + ": error: cannot read the scene file: " + why);
  return parseScene(text, path);
}

}  // namespace pf::scene
