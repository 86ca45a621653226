// pfview: primflow's scenes in a window (GLFW), to look at rather than read.
//   pfview [SCENE.json | MODEL.vm|.hf|.pfl|.pfgrid] [--size WxH] [--threads N] [--frames N [--orbit DEG]] [--screenshot FILE]
//          [--window-shot FILE] [--keys KEYS]
// primflow renders every frame into a buffer; the window's own GL context only shows it (a
// texture over the window) with a text overlay. Mouse: left-drag orbits, right-drag (or
// shift + left) pans, the wheel zooms. Keys: R reload the scene file, S save a screenshot,
// T cycle the thread count, L switch GL polygons between per-vertex and per-pixel lighting,
// M cycle the root-finding method of implicit surfaces and [ ] halve or double its steps (the
// overlay shows the method, the field evaluations per ray and, for a model, its accuracy against
// the double-precision reference on a grid of pixels), Home reset the camera, H help,
// Q or Esc quit. A model (.vm, .hf, .pfl, .pfgrid) opens as a scene of one implicit surface.
// While the camera moves the frame is rendered at a quarter of the window's size, and at full
// size once it rests (progressive refinement). With --frames N it renders N full-size frames
// (turning the camera --orbit degrees about the target before each after the first), saves
// --screenshot (primflow's last frame, as pfrender would write it) and exits: the headless test.
// --window-shot writes what the window shows at exit, overlay included (read back from it).
// --keys presses keys before the first frame (e.g. "MM]": two methods on, steps doubled), and in
// scripted mode the overlay's implicit-surface lines are printed on stdout at exit: that is how
// the tests drive the method keys and read the accuracy figure without a person at the window.
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "model/model_file.h"
#include "raster/field/implicit_field.h"
#include "pfview/accuracy_probe.h"
#include "pfview/frame_renderer.h"
#include "pfview/orbit_camera.h"
#include "pfview/window_display.h"
#include "png_image.h"
#include "scene/scene.h"
#include "showcase.h"

namespace {

using Clock = std::chrono::steady_clock;

// Everything the window's callbacks change.
struct Viewer {
  std::string scene_path;  // empty: the built-in showcase
  pf::scene::Scene scene;
  bool scene_ok = false;
  int generation = 0;
  std::optional<pf::view::OrbitCamera> camera;
  std::vector<std::string> errors;  // shown in the window until the next successful frame
  std::string status;               // the last message of a key (screenshot saved, ...)

  // Mouse state.
  bool orbiting = false, panning = false;
  double last_x = 0, last_y = 0;
  Clock::time_point last_motion = Clock::now() - std::chrono::seconds(10);
  bool dirty = true;       // the camera or the scene changed since the last full-size frame
  bool show_help = false;
  int screenshots = 0;
  std::vector<int> keys;  // pressed since the last frame; handled in the loop (they need the renderer)
  // A model's accuracy against the double-precision reference, measured after each full frame.
  std::optional<pf::view::AccuracyProbe> probe;
  std::string accuracy;
};

// Splits a message into lines for the overlay (and echoes it on stderr).
void reportError(Viewer& v, const std::string& message) {
  std::cerr << message << "\n";
  v.errors.clear();
  std::istringstream in(message);
  for (std::string line; std::getline(in, line);) v.errors.push_back(line);
}

// (Re)reads the scene; on failure the error shows and the last good scene stays.
void loadScene(Viewer& v) {
  try {
    pf::scene::Scene next;
    if (v.scene_path.empty()) {
      next = pf::showcaseScene();
    } else if (pf::model::isModelPath(v.scene_path)) {
      // A model opens as a scene of one implicit instance (tools/model/model_file.h).
      const pf::model::Model m = pf::model::loadModel(v.scene_path);
      pf::model::ModelView view;
      view.box_min = m.default_box_min;
      view.box_max = m.default_box_max;
      next = pf::model::sceneOfModel(m, view);
      v.probe.emplace(m, view);
    } else {
      next = pf::scene::loadScene(v.scene_path);
    }
    const bool first = !v.scene_ok;
    v.scene = std::move(next);
    v.scene_ok = true;
    ++v.generation;
    if (first || !v.camera) v.camera.emplace(v.scene.camera);
    v.errors.clear();
    v.dirty = true;
  } catch (const pf::scene::SceneError& e) {
    reportError(v, e.what());
  } catch (const pf::model::ModelError& e) {
    reportError(v, e.what());
  }
}

// The implicit objects' "method" and "steps" parameters (models, and scenes with fields).
std::vector<pf::scene::ParamValue*> implicitParams(pf::scene::Scene& s, const std::string& name) {
  std::vector<pf::scene::ParamValue*> out;
  for (pf::scene::Object& o : s.objects)
    if (o.primitive == "implicit")
      for (pf::scene::ParamValue& p : o.params)
        if (p.name == name && !p.values.empty()) out.push_back(&p);
  return out;
}

// A parameter value as a small whole number (0 where it is not one), without converting a float
// out of int's range.
int wholeValue(double v) { return v >= 0.0 && v < 1e9 ? static_cast<int>(v) : 0; }

// "implicit: interval, steps 64" for the first implicit object, or "".
std::string implicitStatus(pf::scene::Scene& s) {
  const auto methods = implicitParams(s, "method");
  if (methods.empty()) return "";
  const auto steps = implicitParams(s, "steps");
  std::string text = "implicit: " +
                     std::string(pf::field::rootMethodName(pf::field::RootMethod(wholeValue(methods[0]->values[0]))));
  if (!steps.empty()) text += ", steps " + std::to_string(wholeValue(steps[0]->values[0]));
  return text;
}

// M: the next root-finding method; [ and ]: halve or double march's steps (from 64).
std::string changeImplicitMethod(pf::scene::Scene& s, int key) {
  const auto methods = implicitParams(s, "method");
  const auto steps = implicitParams(s, "steps");
  if (methods.empty()) return "the scene has no implicit surfaces";
  if (key == GLFW_KEY_M) {
    const int next = (wholeValue(methods[0]->values[0]) + 1) % pf::field::kRootMethodCount;
    for (auto* p : methods) p->values[0] = next;
  } else {
    for (auto* p : steps) {
      const double cur = p->values[0] >= 1 ? p->values[0] : 64;
      p->values[0] = std::clamp(key == GLFW_KEY_RIGHT_BRACKET ? cur * 2 : cur / 2, 1.0, 65536.0);
    }
  }
  return implicitStatus(s);
}

Viewer& viewerOf(GLFWwindow* w) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }

void onMouseButton(GLFWwindow* w, int button, int action, int mods) {
  Viewer& v = viewerOf(w);
  const bool press = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) {
    v.orbiting = press && !(mods & GLFW_MOD_SHIFT);
    v.panning = press && (mods & GLFW_MOD_SHIFT);
  } else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
    v.panning = press;
  }
  glfwGetCursorPos(w, &v.last_x, &v.last_y);
}

void onCursor(GLFWwindow* w, double x, double y) {
  Viewer& v = viewerOf(w);
  const double dx = x - v.last_x, dy = y - v.last_y;
  v.last_x = x;
  v.last_y = y;
  if (!v.camera || (!v.orbiting && !v.panning)) return;
  int width, height;
  glfwGetWindowSize(w, &width, &height);
  if (v.orbiting) v.camera->orbit(-dx * 0.4, dy * 0.4);
  else v.camera->pan(dx, dy, height);
  v.last_motion = Clock::now();
  v.dirty = true;
}

void onScroll(GLFWwindow* w, double, double dy) {
  Viewer& v = viewerOf(w);
  if (!v.camera) return;
  v.camera->zoom(std::pow(0.9, dy));
  v.last_motion = Clock::now();
  v.dirty = true;
}

void onResize(GLFWwindow* w, int, int) { viewerOf(w).dirty = true; }

void onKey(GLFWwindow* w, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) glfwSetWindowShouldClose(w, GLFW_TRUE);
  viewerOf(w).keys.push_back(key);
}

bool saveFrame(const pf::view::FrameRenderer& r, const std::string& path, std::string& error) {
  return pf::writePngBottomUp(path, r.pixels().data(), r.width(), r.height(), &error);
}

std::vector<std::string> overlay(const Viewer& v, const pf::view::FrameRenderer& r, bool coarse) {
  std::vector<std::string> lines;
  std::ostringstream head;
  head << (v.scene_path.empty() ? "showcase" : std::filesystem::path(v.scene_path).filename().string()) << "  "
       << r.width() << "x" << r.height() << (coarse ? " (1/4 while moving)" : "") << "  ";
  head.precision(1);
  head << std::fixed << r.milliseconds() << " ms";
  lines.push_back(head.str());
  const std::string threads = std::to_string(r.threads()) + (r.threads() == 1 ? " thread" : " threads");
  if (v.show_help) {
    lines.push_back(threads);
    lines.push_back("left drag: orbit   right drag / shift+left: pan   wheel: zoom");
    lines.push_back("R: reload   S: screenshot   T: threads   L: per-pixel/per-vertex lighting");
    lines.push_back("M: root-finding method of implicit surfaces   [ ]: its steps");
    lines.push_back("Home: reset view   Q/Esc: quit");
  } else {
    lines.push_back(threads + "   H: help");
  }
  if (r.fieldEvaluationsPerRay() > 0) {
    std::ostringstream f;
    f.precision(1);
    f << std::fixed << implicitStatus(const_cast<pf::scene::Scene&>(v.scene)) << "   " << r.fieldEvaluationsPerRay()
      << " field evaluations per ray";
    lines.push_back(f.str());
  }
  if (!v.accuracy.empty() && !coarse) lines.push_back(v.accuracy);
  if (!v.status.empty()) lines.push_back(v.status);
  for (const std::string& e : v.errors) lines.push_back(e);
  return lines;
}

// The GLFW key of one character of --keys: a letter, '[' or ']' (the keys pfview handles by name;
// Home and Esc have no character and are of no use before the first frame).
std::optional<int> scriptedKey(char c) {
  if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  if (c >= 'A' && c <= 'Z') return GLFW_KEY_A + (c - 'A');
  if (c == '[') return GLFW_KEY_LEFT_BRACKET;
  if (c == ']') return GLFW_KEY_RIGHT_BRACKET;
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pfview: primflow's scenes in a window"};
  Viewer v;
  std::string size, screenshot, window_shot, keys;
  int threads = 0, frames = 0;
  double orbit = 0;
  app.add_option("scene", v.scene_path, "scene file (.json) or model (.vm, .hf, .pfl, .pfgrid); none: the built-in showcase");
  app.add_option("--size", size, "window size WxH (default: the scene's)");
  app.add_option("--threads", threads, "rasterizer threads (0: PF_NUM_THREADS or all cores)")->check(CLI::Range(0, 256));
  app.add_option("--frames", frames, "render this many frames, then exit (scripted mode)")->check(CLI::Range(0, 100000));
  app.add_option("--orbit", orbit, "scripted mode: degrees to orbit before each frame after the first");
  app.add_option("--screenshot", screenshot, "write primflow's last frame to this PNG (scripted mode: at exit)");
  app.add_option("--window-shot", window_shot, "write the window's content (overlay included) to this PNG at exit");
  app.add_option("--keys", keys, "press these keys before the first frame (letters, '[' and ']'; e.g. MM] )");
  PF_PARSE_COMMAND_LINE(app, argc, argv);
  if (!v.scene_path.empty() && std::filesystem::path(v.scene_path).extension() != ".json" &&
      !pf::model::isModelPath(v.scene_path)) {
    std::cerr << "pfview: " << v.scene_path << ": error: unknown scene type (pfview opens .json scene files and .vm models)\n";
    return 1;
  }
  for (char c : keys) {
    const std::optional<int> key = scriptedKey(c);
    if (!key) {
      std::cerr << "pfview: --keys takes letters, '[' and ']', not '" << c << "'\n";
      return 2;
    }
    if (*key == GLFW_KEY_Q) {
      std::cerr << "pfview: --keys: Q would quit before the first frame\n";
      return 2;
    }
    v.keys.push_back(*key);
  }
  loadScene(v);
  int width = v.scene_ok ? v.scene.width : 960, height = v.scene_ok ? v.scene.height : 640;
  char tail = 0;
  if (!size.empty() &&
      (std::sscanf(size.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width < 1 || height < 1 ||
       width > 8192 || height > 8192)) {
    std::cerr << "pfview: --size must be WxH with each side in 1..8192, not '" << size << "'\n";
    return 2;
  }

  if (!glfwInit()) {
    std::cerr << "pfview: cannot open a window (no display? try xvfb-run)\n";
    return 1;
  }
  // The frame is shown 1:1 in scripted mode, so the window must not be resized by the system.
  if (frames > 0) glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(width, height, "pfview", nullptr, nullptr);
  if (!window) {
    std::cerr << "pfview: cannot create a " << width << "x" << height << " window\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  glfwSetWindowUserPointer(window, &v);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetScrollCallback(window, onScroll);
  glfwSetKeyCallback(window, onKey);
  glfwSetFramebufferSizeCallback(window, onResize);

  int status = 0;
  {
    pf::view::FrameRenderer renderer(threads);
    pf::view::WindowDisplay display;
    bool coarse_shown = false;
    int rendered = 0;
    std::vector<unsigned char> window_pixels;
    int window_w = 0, window_h = 0;
    const auto render = [&](int w, int h) {
      std::string error;
      if (!v.scene_ok || !v.camera) return false;
      if (!renderer.render(v.scene, v.generation, v.camera->camera(), w, h, error)) {
        reportError(v, error);
        return false;
      }
      display.upload(renderer.pixels().data(), renderer.width(), renderer.height());
      return true;
    };
    while (!glfwWindowShouldClose(window)) {
      int fb_w, fb_h;
      glfwGetFramebufferSize(window, &fb_w, &fb_h);
      if (fb_w < 1 || fb_h < 1) {  // minimised
        glfwWaitEvents();
        continue;
      }
      for (int key : v.keys) {
        if (key == GLFW_KEY_R) {
          loadScene(v);
          if (v.errors.empty()) v.status = "reloaded";
        } else if (key == GLFW_KEY_L && v.scene_ok) {
          v.scene.per_pixel = !v.scene.per_pixel;
          v.status = v.scene.lighting ? (v.scene.per_pixel ? "polygons lit per pixel" : "polygons lit per vertex")
                                      : "the scene has no lighting";
          v.dirty = true;
        } else if ((key == GLFW_KEY_M || key == GLFW_KEY_LEFT_BRACKET || key == GLFW_KEY_RIGHT_BRACKET) && v.scene_ok) {
          v.status = changeImplicitMethod(v.scene, key);
          v.dirty = true;
        } else if (key == GLFW_KEY_H) {
          v.show_help = !v.show_help;
        } else if (key == GLFW_KEY_HOME && v.scene_ok) {
          v.camera.emplace(v.scene.camera);
          v.dirty = true;
        } else if (key == GLFW_KEY_T) {
          const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
          const int next = renderer.threads() >= hw ? 1 : renderer.threads() == 1 ? std::min(2, hw) : hw;
          if (renderer.setThreads(next)) v.dirty = true;
          v.status = "threads: " + std::to_string(renderer.threads());
        } else if (key == GLFW_KEY_S) {
          if (coarse_shown && render(fb_w, fb_h)) coarse_shown = false;  // save the full frame
          const std::string path = "pfview-" + std::to_string(++v.screenshots) + ".png";
          std::string error;
          v.status = saveFrame(renderer, path, error) ? "saved " + path : error;
          std::cerr << "pfview: " << v.status << "\n";
        }
      }
      v.keys.clear();

      // Progressive refinement: a quarter-size frame while the camera moves, the full one once
      // it has rested for 0.2 s (and never a coarse one in scripted mode).
      const bool moving = frames == 0 && Clock::now() - v.last_motion < std::chrono::milliseconds(200);
      bool drew = false;
      if (v.dirty && moving) {
        if (render(std::max(1, fb_w / 4), std::max(1, fb_h / 4))) v.errors.clear();
        coarse_shown = true;
        drew = true;
      } else if (v.dirty || coarse_shown) {
        if (render(fb_w, fb_h)) {
          v.errors.clear();
          // The accuracy figure of a model's full frame (the probe's rays follow the same camera).
          if (v.probe && renderer.depth())
            v.accuracy = v.probe->measure(v.camera->camera(), renderer.width(), renderer.height(), renderer.depth()).text();
        }
        v.dirty = coarse_shown = false;
        drew = true;
      }
      display.draw(fb_w, fb_h, overlay(v, renderer, coarse_shown));
      if (!window_shot.empty()) {  // the back buffer just drawn: kept for the exit
        window_pixels.resize(static_cast<size_t>(fb_w) * fb_h * 4);
        glReadPixels(0, 0, fb_w, fb_h, GL_RGBA, GL_UNSIGNED_BYTE, window_pixels.data());
        window_w = fb_w;
        window_h = fb_h;
      }
      glfwSwapBuffers(window);
      if (drew) {
        char title[256];
        std::snprintf(title, sizeof title, "pfview - %.1f ms", renderer.milliseconds());
        glfwSetWindowTitle(window, title);
      }

      if (frames > 0) {
        if (drew || !v.scene_ok) ++rendered;
        if (rendered >= frames) break;
        if (orbit != 0 && v.camera) v.camera->orbit(orbit, 0);
        v.dirty = true;
        glfwPollEvents();
      } else if (moving || v.dirty || coarse_shown) {
        glfwPollEvents();
      } else {
        glfwWaitEventsTimeout(0.25);
      }
    }
    if (!screenshot.empty()) {
      std::string error;
      if (renderer.width() == 0 || !saveFrame(renderer, screenshot, error)) {
        std::cerr << "pfview: no screenshot: " << (error.empty() ? "nothing was rendered" : error) << "\n";
        status = 1;
      }
    }
    if (!window_shot.empty()) {
      std::string error;
      if (window_w == 0 || !pf::writePngBottomUp(window_shot, window_pixels.data(), window_w, window_h, &error)) {
        std::cerr << "pfview: no window shot: " << (error.empty() ? "nothing was shown" : error) << "\n";
        status = 1;
      }
    }
    if (frames > 0 && !v.errors.empty()) status = 1;
    if (frames > 0) {  // what the overlay said of the implicit surfaces, for scripts
      const std::string implicit = implicitStatus(v.scene);
      if (!implicit.empty()) std::cout << implicit << "\n";
      if (!v.accuracy.empty()) std::cout << v.accuracy << "\n";
    }
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
