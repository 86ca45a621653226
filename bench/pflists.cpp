// pflists: a display list replayed against the same commands issued directly (docs/performance.md,
// "Display lists").
//   pflists [--scene torus,triangles,begin_end,attributes] [--frames 1000] [--warmup 20] [--size 256]
//           [--threads 1] [--csv FILE]
// Each scene's drawing commands are compiled once into a list; then every frame draws them
// twice -- issued directly, and by one glCallList -- in alternating order, each time from
// glClear to glFinish. Per way it prints the median over the frames after the warm-up of the
// time to issue the commands (glClear to the last command: what the API costs, glEnd's setup
// included) and of the whole frame (to glFinish). The two images must be identical (exit 1
// otherwise).
#include <CLI/CLI.hpp>

#include "tools/command_line.h"

#include <primflow/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Scene {
  std::string name;
  std::function<void()> setup;  // state outside the list: matrices, lights
  std::function<long()> draw;   // the commands compiled into the list; returns how many
};

// A lit torus of quad strips, a normal and a vertex per corner; the material and a rotation
// under glPushMatrix are among the commands.
long drawTorus() {
  const int rings = 48, sides = 32;
  const double pi = 3.14159265358979323846, major = 1.0, minor = 0.4;
  const GLfloat gold[4] = {0.8f, 0.6f, 0.2f, 1.0f}, white[4] = {1, 1, 1, 1};
  long commands = 5;
  pfglMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, gold);
  pfglMaterialfv(GL_FRONT, GL_SPECULAR, white);
  pfglMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
  pfglPushMatrix();
  pfglRotatef(35.0f, 1.0f, 0.2f, 0.0f);
  for (int i = 0; i < rings; ++i) {
    pfglBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= sides; ++j) {
      for (int k = 1; k >= 0; --k) {
        const double u = 2 * pi * (i + k) / rings, v = 2 * pi * j / sides;
        const double nx = std::cos(v) * std::cos(u), ny = std::cos(v) * std::sin(u), nz = std::sin(v);
        pfglNormal3f(static_cast<float>(nx), static_cast<float>(ny), static_cast<float>(nz));
        pfglVertex3f(static_cast<float>((major + minor * std::cos(v)) * std::cos(u)),
                     static_cast<float>((major + minor * std::cos(v)) * std::sin(u)), static_cast<float>(minor * nz));
        commands += 2;
      }
    }
    pfglEnd();
    commands += 2;
  }
  pfglPopMatrix();
  return commands + 1;
}

// Small Gouraud triangles in window coordinates: 10,000 in one glBegin, a colour per vertex.
long drawTriangles() {
  long commands = 2;
  pfglBegin(GL_TRIANGLES);
  for (int t = 0; t < 10000; ++t) {
    const float x = static_cast<float>((t * 37) % 240), y = static_cast<float>((t * 53) % 240);
    for (int k = 0; k < 3; ++k) {
      pfglColor3f(static_cast<float>(k == 0), static_cast<float>(k == 1), static_cast<float>((t % 7) / 7.0));
      pfglVertex2f(x + (k == 1 ? 9.0f : 0.0f), y + (k == 2 ? 9.0f : 0.0f));
      commands += 2;
    }
  }
  pfglEnd();
  return commands;
}

// 2,000 triangles, each its own glBegin / glEnd: the most calls per triangle GL has.
long drawBeginEnd() {
  long commands = 0;
  for (int t = 0; t < 2000; ++t) {
    const float x = static_cast<float>((t * 37) % 240), y = static_cast<float>((t * 53) % 240);
    pfglBegin(GL_TRIANGLES);
    pfglColor3f(0.2f, static_cast<float>(t % 5) / 5.0f, 0.8f);
    pfglVertex2f(x, y);
    pfglVertex2f(x + 9.0f, y);
    pfglVertex2f(x, y + 9.0f);
    pfglEnd();
    commands += 6;
  }
  return commands;
}

// 30,000 state commands and no drawing: glColor, glNormal, glTexCoord, glMaterial and a matrix
// change -- what a list costs per command, against a call through the API.
long drawAttributes() {
  long commands = 0;
  for (int i = 0; i < 6000; ++i) {
    const float f = static_cast<float>(i % 100) / 100.0f;
    pfglColor3f(f, 0.5f, 1.0f - f);
    pfglNormal3f(0.0f, f, 1.0f);
    pfglTexCoord2f(f, f);
    pfglMaterialf(GL_FRONT, GL_SHININESS, 10.0f + f);
    pfglTranslatef(0.0f, 0.0f, 0.0f);
    commands += 5;
  }
  return commands;
}

void windowCoordinates(int size) {
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglOrtho(0, size, 0, size, -1, 1);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglDisable(GL_LIGHTING);
  pfglDisable(GL_DEPTH_TEST);
}

void litPerspective() {
  const GLfloat light[4] = {1.0f, 1.0f, 2.0f, 0.0f};
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglTranslatef(0.0f, 0.0f, -3.5f);
  pfglLightfv(GL_LIGHT0, GL_POSITION, light);
  pfglEnable(GL_LIGHTING);
  pfglEnable(GL_LIGHT0);
  pfglEnable(GL_DEPTH_TEST);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pflists: a display list replayed against its commands issued directly"};
  std::string scenes_arg = "torus,triangles,begin_end,attributes", csv;
  int frames = 1000, warmup = 20, size = 256, threads = 1;
  app.add_option("--scene", scenes_arg, "comma-separated: torus, triangles, begin_end, attributes");
  app.add_option("--frames", frames, "timed frames per way (each a replay of the list)")->check(CLI::Range(1, 100000));
  app.add_option("--warmup", warmup, "untimed frames first")->check(CLI::Range(0, 10000));
  app.add_option("--size", size, "image size (square)")->check(CLI::Range(16, 4096));
  app.add_option("--threads", threads, "rasterizer threads")->check(CLI::Range(1, 256));
  app.add_option("--csv", csv, "append scene,commands,size,threads,frames,direct_issue_ms,list_issue_ms,"
                               "direct_frame_ms,list_frame_ms,compile_ms to FILE");
  PF_PARSE_COMMAND_LINE(app, argc, argv);

  const std::vector<Scene> all = {{"torus", litPerspective, drawTorus},
                                  {"triangles", [size] { windowCoordinates(size); }, drawTriangles},
                                  {"begin_end", [size] { windowCoordinates(size); }, drawBeginEnd},
                                  {"attributes", [size] { windowCoordinates(size); }, drawAttributes}};
  std::vector<unsigned char> pixels(static_cast<size_t>(size) * size * 4), first(pixels.size());
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx || !pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, size, size)) {
    std::fprintf(stderr, "pflists: no context\n");
    return 1;
  }
  std::FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "a");
  std::printf("%-10s %9s %16s %16s %7s %16s %16s %7s %11s\n", "scene", "commands", "direct issue ms", "list issue ms",
              "ratio", "direct frame ms", "list frame ms", "ratio", "compile ms");
  int status = 0;
  std::stringstream names(scenes_arg);
  for (std::string name; std::getline(names, name, ',');) {
    auto scene = std::find_if(all.begin(), all.end(), [&](const Scene& s) { return s.name == name; });
    if (scene == all.end()) {
      std::fprintf(stderr, "pflists: no scene '%s'\n", name.c_str());
      return 1;
    }
    scene->setup();
    const GLuint list = pfglGenLists(1);
    const auto c0 = Clock::now();
    pfglNewList(list, GL_COMPILE);
    const long commands = scene->draw();
    pfglEndList();
    const double compile_ms = ms(c0, Clock::now());
    std::vector<double> issue[2], frame[2];  // [0] direct, [1] list
    for (int f = 0; f < warmup + frames; ++f) {
      for (int k = 0; k < 2; ++k) {
        const int way = (f + k) % 2;  // alternate which way goes first
        const auto t0 = Clock::now();
        pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (way == 0) scene->draw();
        else pfglCallList(list);
        const auto t1 = Clock::now();
        pfglFinish();
        const auto t2 = Clock::now();
        if (f >= warmup) {
          issue[way].push_back(ms(t0, t1));
          frame[way].push_back(ms(t0, t2));
        }
        if (f == 0 && way == 0) first = pixels;
        if (f == 0 && way == 1 && std::memcmp(first.data(), pixels.data(), pixels.size()) != 0) {
          std::fprintf(stderr, "pflists: %s: the list draws another image than its commands\n", name.c_str());
          status = 1;
        }
      }
    }
    if (pfglGetError() != GL_NO_ERROR) {
      std::fprintf(stderr, "pflists: %s: a GL error\n", name.c_str());
      status = 1;
    }
    const double di = median(issue[0]), li = median(issue[1]), df = median(frame[0]), lf = median(frame[1]);
    std::printf("%-10s %9ld %16.3f %16.3f %7.2f %16.3f %16.3f %7.2f %11.3f\n", name.c_str(), commands, di, li, li / di,
                df, lf, lf / df, compile_ms);
    if (out)
      std::fprintf(out, "%s,%ld,%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f\n", name.c_str(), commands, size, threads, frames, di,
                   li, df, lf, compile_ms);
    pfglDeleteLists(list, 1);
  }
  if (out) std::fclose(out);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return status;
}
