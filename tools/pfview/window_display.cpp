// pfview's window side (see window_display.h). Legacy GL 1.x calls: the window's context is a
// compatibility one, and this is all it is asked to do.
#include "pfview/window_display.h"

#include <GLFW/glfw3.h>

#include <vector>

// stb_easy_font: a header-only bitmap font that emits quads (Debian libstb-dev).
#include <stb/stb_easy_font.h>

namespace pf::view {

WindowDisplay::WindowDisplay() { glGenTextures(1, &texture_); }

WindowDisplay::~WindowDisplay() { glDeleteTextures(1, &texture_); }

void WindowDisplay::upload(const unsigned char* rgba, int width, int height) {
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // a coarse frame stays crisp
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  has_frame_ = true;
}

void WindowDisplay::draw(int window_width, int window_height, const std::vector<std::string>& lines) {
  glViewport(0, 0, window_width, window_height);
  glClearColor(0.1f, 0.1f, 0.12f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  if (has_frame_) {
    // The frame over the whole window; its row 0 is the bottom, as GL's texture rows.
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glColor4f(1, 1, 1, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(-1, -1);
    glTexCoord2f(1, 0); glVertex2f(1, -1);
    glTexCoord2f(1, 1); glVertex2f(1, 1);
    glTexCoord2f(0, 1); glVertex2f(-1, 1);
    glEnd();
    glDisable(GL_TEXTURE_2D);
  }
  if (lines.empty()) return;
  // Text in pixels, y down, at twice the font's size, over a dark band for contrast.
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, window_width / 2.0, window_height / 2.0, 0, -1, 1);
  std::vector<char> quads(64 * 1024);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(0, 0, 0, 0.55f);
  int widest = 0;
  for (const std::string& l : lines) widest = std::max(widest, stb_easy_font_width(const_cast<char*>(l.c_str())));
  glRectf(0, 0, static_cast<float>(widest + 8), static_cast<float>(lines.size() * 11 + 6));
  glDisable(GL_BLEND);
  glColor4f(1, 1, 0.85f, 1);
  glEnableClientState(GL_VERTEX_ARRAY);
  for (size_t i = 0; i < lines.size(); ++i) {
    const int n = stb_easy_font_print(4, 4 + 11.0f * static_cast<float>(i), const_cast<char*>(lines[i].c_str()),
                                      nullptr, quads.data(), static_cast<int>(quads.size()));
    glVertexPointer(2, GL_FLOAT, 16, quads.data());
    glDrawArrays(GL_QUADS, 0, n * 4);
  }
  glDisableClientState(GL_VERTEX_ARRAY);
}

}  // namespace pf::view
