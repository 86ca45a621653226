// pfclientcompare: judges a client's output (tests/clients) against OSMesa's, pixel by pixel.
//   pfclientcompare image REF.pam GOT.pam [--tolerance T] [--off-pixels N]
//       every channel within T/255 (default 1), except at most N pixels (default 0); the count
//       and the worst pixels are printed.
//   pfclientcompare depth REF GOT [--tolerance D] [--off-pixels N]   depth files of client_output.h
//   pfclientcompare raw REF GOT                                       tests/clients/formats.c dumps
// Exit 0: alike; 1: different; 2: a file could not be read.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Samples {
  int width = 0, height = 0, channels = 0;
  std::vector<double> values;  // channel values in units of the tolerance's scale
};

bool readFile(const char* path, std::string& out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream s;
  s << f.rdbuf();
  out = s.str();
  return true;
}

bool readPam(const char* path, Samples& s) {
  std::string data;
  if (!readFile(path, data)) return false;
  const size_t end = data.find("ENDHDR\n");
  if (data.compare(0, 3, "P7\n") != 0 || end == std::string::npos) return false;
  std::istringstream header(data.substr(3, end - 3));
  std::string key;
  int maxval = 0;
  while (header >> key) {
    if (key == "WIDTH") header >> s.width;
    else if (key == "HEIGHT") header >> s.height;
    else if (key == "DEPTH") header >> s.channels;
    else if (key == "MAXVAL") header >> maxval;
    else header >> key;
  }
  const size_t n = static_cast<size_t>(s.width) * s.height * s.channels;
  if (maxval != 255 || s.width <= 0 || s.height <= 0 || data.size() < end + 7 + n) return false;
  // (As unsigned bytes: std::string's chars are signed, and 128 would read as -128.)
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data()) + end + 7;
  s.values.assign(bytes, bytes + n);
  return true;
}

bool readDepth(const char* path, Samples& s) {
  std::string data;
  if (!readFile(path, data)) return false;
  const size_t nl = data.find('\n');
  if (nl == std::string::npos || std::sscanf(data.c_str(), "PFDEPTH %d %d", &s.width, &s.height) != 2) return false;
  const size_t n = static_cast<size_t>(s.width) * s.height;
  if (data.size() < nl + 1 + n * 4) return false;
  s.channels = 1;
  s.values.resize(n);
  for (size_t i = 0; i < n; ++i) {
    float f;
    std::memcpy(&f, data.data() + nl + 1 + i * 4, 4);
    s.values[i] = f;
  }
  return true;
}

// formats.c's dumps: "PFRAW format type width height row_pixels y_up bytes\n" and the bytes.
// Values are decoded by type and scaled to 1/255 units: the tolerance is then the same.
bool readRaw(const char* path, Samples& s, std::string& header) {
  std::string data;
  if (!readFile(path, data)) return false;
  const size_t nl = data.find('\n');
  unsigned format = 0, type = 0;
  int row = 0, y_up = 0;
  size_t bytes = 0;
  if (nl == std::string::npos ||
      std::sscanf(data.c_str(), "PFRAW %x %x %d %d %d %d %zu", &format, &type, &s.width, &s.height, &row, &y_up, &bytes) != 7 ||
      data.size() < nl + 1 + bytes)
    return false;
  header = data.substr(0, nl);
  const unsigned char* p = reinterpret_cast<const unsigned char*>(data.data()) + nl + 1;
  // Channels a pixel (0x1907: OSMESA_RGB, 5: OSMESA_RGB_565); depth: one.
  s.channels = type == 0 ? 1 : format == 0x1907 || format == 5 ? 3 : 4;
  s.values.clear();
  if (type == 0x1401) {  // GL_UNSIGNED_BYTE
    for (size_t i = 0; i < bytes; ++i) s.values.push_back(p[i]);
  } else if (type == 0x1403) {  // GL_UNSIGNED_SHORT
    for (size_t i = 0; i + 1 < bytes; i += 2) s.values.push_back((p[i] | p[i + 1] << 8) / 257.0);
  } else if (type == 0x1406) {  // GL_FLOAT
    for (size_t i = 0; i + 3 < bytes; i += 4) {
      float f;
      std::memcpy(&f, p + i, 4);
      s.values.push_back(f * 255.0);
    }
  } else if (type == 0x8363) {  // GL_UNSIGNED_SHORT_5_6_5: each channel in its own steps
    for (size_t i = 0; i + 1 < bytes; i += 2) {
      const unsigned v = p[i] | p[i + 1] << 8;
      s.values.push_back(v >> 11);
      s.values.push_back(v >> 5 & 63);
      s.values.push_back(v & 31);
    }
  } else if (type == 0) {  // depth: 2-byte or Z24 in 4 bytes, in 24-bit steps
    const int per = bytes == static_cast<size_t>(s.width) * s.height * 2 ? 2 : 4;
    for (size_t i = 0; i + per - 1 < bytes; i += per) {
      uint32_t v = 0;
      std::memcpy(&v, p + i, per);
      s.values.push_back(per == 2 ? v * 256.0 : (v & 0xffffff));
    }
  } else {
    return false;
  }
  return true;
}

int judge(const Samples& ref, const Samples& got, double tolerance, long off_allowed, const char* unit) {
  if (ref.width != got.width || ref.height != got.height || ref.values.size() != got.values.size()) {
    std::printf("different sizes: %dx%d (%zu values) and %dx%d (%zu values)\n", ref.width, ref.height,
                ref.values.size(), got.width, got.height, got.values.size());
    return 1;
  }
  const size_t per = ref.channels > 0 ? ref.channels : 1;
  const size_t pixels = ref.values.size() / per;
  long off = 0;
  double worst = 0;
  size_t worst_at = 0;
  for (size_t i = 0; i < pixels; ++i) {
    double d = 0;
    for (size_t c = 0; c < per; ++c) d = std::max(d, std::fabs(ref.values[i * per + c] - got.values[i * per + c]));
    if (!(d <= tolerance)) ++off;
    if (!(d <= worst)) {
      worst = d;
      worst_at = i;
    }
  }
  std::printf("%zu values of %zu channel(s): %ld beyond %g %s (allowed %ld); largest difference %g %s at value %zu\n",
              pixels, per, off, tolerance, unit, off_allowed, worst, unit, worst_at);
  return off <= off_allowed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: pfclientcompare image|depth|raw REF GOT [--tolerance T] [--off-pixels N]\n");
    return 2;
  }
  const std::string mode = argv[1];
  double tolerance = mode == "depth" ? 1e-5 : 1.0;
  long off_allowed = 0;
  for (int i = 4; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--tolerance") == 0) tolerance = std::atof(argv[i + 1]);
    else if (std::strcmp(argv[i], "--off-pixels") == 0) off_allowed = std::atol(argv[i + 1]);
  }
  Samples ref, got;
  if (mode == "image") {
    if (!readPam(argv[2], ref) || !readPam(argv[3], got)) return std::fprintf(stderr, "cannot read the images\n"), 2;
    return judge(ref, got, tolerance, off_allowed, "/255");
  }
  if (mode == "depth") {
    if (!readDepth(argv[2], ref) || !readDepth(argv[3], got)) return std::fprintf(stderr, "cannot read the depths\n"), 2;
    return judge(ref, got, tolerance, off_allowed, "");
  }
  if (mode == "raw") {
    std::string ref_header, got_header;
    if (!readRaw(argv[2], ref, ref_header) || !readRaw(argv[3], got, got_header))
      return std::fprintf(stderr, "cannot read the dumps\n"), 2;
    if (ref_header != got_header) {
      std::printf("different layouts: '%s' and '%s'\n", ref_header.c_str(), got_header.c_str());
      return 1;
    }
    return judge(ref, got, tolerance, off_allowed, "steps");
  }
  std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
  return 2;
}
