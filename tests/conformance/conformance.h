// The conformance suite: cases, their renderings and how they are judged.
//
// A GL case is one GL-1.x source function (cases.inc) compiled twice -- against OSMesa, the
// reference, and against primflow through <primflow/gl_mangle.h> -- rendered at the same size,
// read back with glReadPixels after glFinish and compared pixel by pixel with the case's own
// tolerance. An extension case (extension_cases.cpp) has no OSMesa counterpart: it renders with
// primflow and is judged against a reference computed in double precision inside the case.
// A case may also record GL error codes and numbers (glGet*, glReadPixels in other formats),
// compared exactly or within the case's tolerance. The only way a failing case is excused is an
// entry, with its reason, in the expected-deviations list (expected_deviations.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pfconf {

// Every GL case clears to this colour first (RGBA bytes); the ID comparison treats it as "no
// triangle".
constexpr uint8_t kClear[4] = {16, 32, 48, 255};

// What a case records besides the image: GL error codes in order, and numbers.
struct CaseOutput {
  std::vector<unsigned> errors;
  std::vector<double> numbers;
};

// How a case is judged.
struct Tolerance {
  // Coverage by ID colours (GL cases): every pixel must show the same triangle ID in both
  // images (see cases.inc: idColor); `ids` is how many IDs the case draws. 0: colours instead.
  int ids = 0;
  int colour = 0;              // per channel, in 1/255
  double off_fraction = 0.0;   // of all pixels, allowed beyond `colour` (edge decisions)
  double depth = -1.0;         // depth-buffer tolerance; < 0: depth not compared
  double numbers = 0.0;        // tolerance for CaseOutput::numbers
  const char* why = nullptr;   // required when the tolerance is looser than exact
};

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;   // row 0 at the bottom
  std::vector<double> depth;   // window depth per pixel; empty if the case has no depth buffer
  bool ok = false;             // false: the context could not be made
};

struct Rendering {
  Image image;
  CaseOutput output;
};

using DrawFunction = void (*)(int width, int height, CaseOutput& out);

struct GlCase {
  const char* name;
  const char* category;
  const char* what;
  DrawFunction draw;
  Tolerance tolerance;
};

// The GL cases, from the primflow build of cases.inc (the OSMesa build has the same table).
const std::vector<GlCase>& glCases();

// Renders GL case `name` (glCases()) through each implementation at width x height.
Rendering renderOsmesa(const std::string& name, int width, int height);
// `native`: the context's PF_JIT attribute (1 native code, 0 the interpreter; -1 the default).
Rendering renderPrimflow(const std::string& name, int width, int height, int threads, int native = -1);

// The verdict on one case.
struct Result {
  enum class Status { Pass, Fail, ExpectedDeviation } status = Status::Fail;
  int max_colour_error = 0;   // per channel, in 1/255, over all pixels
  int pixels_off = 0;         // beyond the tolerance
  double max_depth_error = 0;
  std::string detail;         // why it failed (first mismatches), or the deviation's reason
  double milliseconds = 0;    // rendering time, both implementations
  Image reference, actual;    // for the report
};

// Judges GL case `c` from the two renderings.
Result compareGl(const GlCase& c, const Rendering& reference, const Rendering& actual);

// An image whose pixels show where `a` and `b` differ (bright: more), for the report.
Image diffImage(const Image& a, const Image& b);

// The extension's own cases: primflow only, references in double precision.
struct ExtensionCase {
  const char* name;
  const char* what;
  // Fills `result` (status, errors, detail, and the images it compared).
  void (*run)(Result& result);
};
const std::vector<ExtensionCase>& extensionCases();

// The expected deviations: case name -> the reason primflow differs there on purpose.
const char* expectedDeviation(const std::string& name);

// Writes `dir`/index.html with the table and, per case, reference / actual / diff PNGs.
struct ReportRow {
  std::string name, category, what;
  Result result;
};
bool writeHtmlReport(const std::string& dir, const std::vector<ReportRow>& rows, std::string* error);

const char* statusName(Result::Status s);

}  // namespace pfconf
