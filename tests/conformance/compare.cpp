// Judging a GL case: the two renderings compared pixel by pixel, by ID colours or by colour
// with the case's tolerance, then the depth buffers, the error codes and the numbers.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "conformance.h"

namespace pfconf {

namespace {

const uint8_t* pixel(const Image& img, int i) { return &img.rgba[static_cast<size_t>(i) * 4]; }

bool isClear(const uint8_t* p) {
  return p[0] == kClear[0] && p[1] == kClear[1] && p[2] == kClear[2] && p[3] == kClear[3];
}

std::string rgba(const uint8_t* p) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "(%d, %d, %d, %d)", p[0], p[1], p[2], p[3]);
  return buf;
}

// The triangle whose ID colour the pixel has (cases.inc: idColor): -1 for the clear colour, -2
// for a colour that is no ID.
int idOf(const uint8_t* p, int ids) {
  if (isClear(p)) return -1;
  const int id = p[0] + 256 * p[1] - 1;
  if (id < 0 || id >= ids || p[2] != ((id * 37) & 255) || p[3] != 255) return -2;
  return id;
}

int channelDifference(const uint8_t* a, const uint8_t* b) {
  int d = 0;
  for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
  return d;
}

}  // namespace

Result compareGl(const GlCase& c, const Rendering& reference, const Rendering& actual) {
  Result r;
  r.reference = reference.image;
  r.actual = actual.image;
  const Image& ref = reference.image;
  const Image& got = actual.image;
  std::ostringstream why;
  bool pass = true;
  if (!ref.ok || !got.ok || ref.rgba.size() != got.rgba.size()) {
    r.detail = !ref.ok ? "OSMesa could not render it" : "primflow could not render it";
    if (const char* reason = expectedDeviation(c.name)) {
      r.status = Result::Status::ExpectedDeviation;
      r.detail += std::string("; expected: ") + reason;
    }
    return r;
  }
  const int n = ref.width * ref.height;
  const Tolerance& t = c.tolerance;
  std::ostringstream pixels;  // the first mismatching pixels
  int examples = 0;
  auto example = [&](int i, const std::string& text) {
    if (examples++ < 8) pixels << "  (" << i % ref.width << ", " << i / ref.width << "): " << text << "\n";
  };
  std::vector<char> colours_agree(static_cast<size_t>(n), 1);
  for (int i = 0; i < n; ++i) {
    const uint8_t* a = pixel(ref, i);
    const uint8_t* b = pixel(got, i);
    const int d = channelDifference(a, b);
    r.max_colour_error = std::max(r.max_colour_error, d);
    if (t.ids > 0) {
      const int ia = idOf(a, t.ids), ib = idOf(b, t.ids);
      if (ia == -2) example(i, "OSMesa wrote " + rgba(a) + ", which is no ID colour");
      if (ia != ib || ia == -2) {
        ++r.pixels_off;
        colours_agree[static_cast<size_t>(i)] = 0;
        if (ia != -2) example(i, "OSMesa triangle " + std::to_string(ia) + ", primflow " + (ib == -2 ? rgba(b) : "triangle " + std::to_string(ib)));
      }
    } else if (d > t.colour) {
      ++r.pixels_off;
      colours_agree[static_cast<size_t>(i)] = 0;
      example(i, "OSMesa " + rgba(a) + ", primflow " + rgba(b));
    }
  }
  const int allowed = t.ids > 0 ? 0 : static_cast<int>(std::floor(t.off_fraction * n));
  if (r.pixels_off > allowed) {
    pass = false;
    why << r.pixels_off << " pixels off (allowed " << allowed << ")" << (t.ids > 0 ? " in ID coverage" : "") << ":\n"
        << pixels.str();
  }
  if (t.depth >= 0) {
    if (ref.depth.size() != static_cast<size_t>(n) || got.depth.size() != static_cast<size_t>(n)) {
      pass = false;
      why << "a depth buffer could not be read\n";
    } else {
      int bad = 0;
      for (int i = 0; i < n; ++i) {
        if (!colours_agree[static_cast<size_t>(i)]) continue;
        const double e = std::abs(ref.depth[static_cast<size_t>(i)] - got.depth[static_cast<size_t>(i)]);
        r.max_depth_error = std::max(r.max_depth_error, e);
        bad += e > t.depth;
      }
      if (bad) {
        pass = false;
        why << bad << " pixels with depth off by more than " << t.depth << " (largest " << r.max_depth_error << ")\n";
      }
    }
  }
  if (reference.output.errors != actual.output.errors) {
    pass = false;
    why << "GL error sequence differs: OSMesa";
    for (unsigned e : reference.output.errors) why << " 0x" << std::hex << e << std::dec;
    why << ", primflow";
    for (unsigned e : actual.output.errors) why << " 0x" << std::hex << e << std::dec;
    why << "\n";
  }
  const auto& na = reference.output.numbers;
  const auto& nb = actual.output.numbers;
  if (na.size() != nb.size()) {
    pass = false;
    why << "recorded " << na.size() << " numbers in OSMesa, " << nb.size() << " in primflow\n";
  } else {
    for (size_t k = 0; k < na.size(); ++k)
      if (!(std::abs(na[k] - nb[k]) <= t.numbers)) {
        pass = false;
        why << "number " << k << ": OSMesa " << na[k] << ", primflow " << nb[k] << "\n";
        break;
      }
  }
  r.status = pass ? Result::Status::Pass : Result::Status::Fail;
  r.detail = why.str();
  if (!pass)
    if (const char* reason = expectedDeviation(c.name)) {
      r.status = Result::Status::ExpectedDeviation;
      r.detail = std::string("expected deviation: ") + reason + "\n" + r.detail;
    }
  return r;
}

Image diffImage(const Image& a, const Image& b) {
  Image d;
  d.width = a.width;
  d.height = a.height;
  d.ok = true;
  d.rgba.assign(a.rgba.size(), 0);
  if (a.rgba.size() != b.rgba.size()) return d;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    const int diff = channelDifference(&a.rgba[i], &b.rgba[i]);
    if (diff == 0) {  // the reference, dimmed
      for (int c = 0; c < 3; ++c) d.rgba[i + c] = static_cast<uint8_t>(a.rgba[i + c] / 4);
    } else {          // differences in red, brighter for larger ones
      d.rgba[i] = static_cast<uint8_t>(std::min(255, 96 + diff * 4));
      d.rgba[i + 1] = d.rgba[i + 2] = static_cast<uint8_t>(std::min(255, diff));
    }
    d.rgba[i + 3] = 255;
  }
  return d;
}

const char* statusName(Result::Status s) {
  switch (s) {
    case Result::Status::Pass: return "pass";
    case Result::Status::Fail: return "FAIL";
    case Result::Status::ExpectedDeviation: return "expected deviation";
  }
  return "?";
}

}  // namespace pfconf
