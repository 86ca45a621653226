// pfview's window side: shows a primflow frame in the window (a texture of the window's own GL
// context, drawn over the whole window -- that GL only displays; primflow does the rendering)
// and an overlay of text lines (stb_easy_font).
#pragma once

#include <string>
#include <vector>

namespace pf::view {

class WindowDisplay {
 public:
  WindowDisplay();
  ~WindowDisplay();
  WindowDisplay(const WindowDisplay&) = delete;
  WindowDisplay& operator=(const WindowDisplay&) = delete;

  // Uploads an RGBA frame (bottom row first), of any size: it is stretched over the window.
  void upload(const unsigned char* rgba, int width, int height);
  // Draws the last frame and `lines` of text at the top left over a window of the given
  // framebuffer size.
  void draw(int window_width, int window_height, const std::vector<std::string>& lines);

 private:
  unsigned int texture_ = 0;
  bool has_frame_ = false;
};

}  // namespace pf::view
