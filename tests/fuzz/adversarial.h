// Structure-aware inputs for the fuzz targets (docs/reliability.md). Mutating raw text seldom
// makes what breaks a parser or a compiler -- a sum of ten thousand terms, five thousand calls
// each inlining the one before, a JSON text nested a million deep -- so the targets also feed
// inputs of such shapes, whose kind and size (up to far past every documented limit) the
// fuzzer's bytes choose. Each shape is one that once crashed, hung or ate memory here.
#pragma once

#include <pthread.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <string>

namespace pf::fuzz {

// The generators' choices, from a generator seeded with a hash of the whole input: any mutation
// anywhere in it changes them (a FuzzedDataProvider reads its choices off the input's last few
// bytes, which a corpus of text files and libFuzzer's mutations seldom vary).
class Choices {
 public:
  Choices(const uint8_t* data, size_t size) {
    uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
    rng_.seed(h);
  }
  template <typename T>
  T ConsumeIntegralInRange(T lo, T hi) {
    return std::uniform_int_distribution<T>(lo, hi)(rng_);
  }
  bool ConsumeBool() { return (rng_() & 1) != 0; }

 private:
  std::mt19937_64 rng_;
};

inline std::string repeat(const std::string& s, size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (size_t i = 0; i < n; ++i) out += s;
  return out;
}

// Runs `work` on a new thread with a 1 MB stack, an application's worker thread's: compiles
// and reads must fit in it (the main thread's 8 MB would hide a recursion that does not).
inline void onSmallStack(const std::function<void()>& work) {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, size_t{1} << 20);
  pthread_t thread;
  auto run = [](void* arg) -> void* {
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
  };
  if (pthread_create(&thread, &attr, run, const_cast<std::function<void()>*>(&work)) == 0) {
    pthread_join(thread, nullptr);
  } else {
    work();
  }
  pthread_attr_destroy(&attr);
}

// A size: mostly small, sometimes past the limits (256 levels, 384 inlined, 2^20 operations).
inline size_t sizeOf(Choices& in, size_t most) {
  switch (in.ConsumeIntegralInRange<int>(0, 3)) {
    case 0: return in.ConsumeIntegralInRange<size_t>(0, 16);
    case 1: return in.ConsumeIntegralInRange<size_t>(200, 420);
    default: return in.ConsumeIntegralInRange<size_t>(0, most);
  }
}

inline const char* anOperator(Choices& in) {
  static const char* const kOps[] = {" + ", " - ", " * ", " / ", " < ", " && ", " == "};
  return kOps[in.ConsumeIntegralInRange<size_t>(0, 6)];
}

inline std::string primitiveWith(const std::string& body, const std::string& functions = "") {
  return functions + "primitive p(float k[1]; varying float X, Y; inout varying float Z) {\n" + body + "\n}\n";
}

// A primitive-language source of one of the shapes that break compilers.
inline std::string languageSource(Choices& in) {
  const int shape = in.ConsumeIntegralInRange<int>(0, 10);
  const bool early = in.ConsumeBool();
  const std::string leaf = in.ConsumeBool() ? "Z" : "k[0]";
  switch (shape) {
    case 0: {  // a long flat chain: a + b + c + ...
      const size_t n = sizeOf(in, 20000);
      std::string e = leaf;
      for (size_t i = 0; i < n; ++i) e += std::string(anOperator(in)) + (i % 2 ? "1.5" : leaf);
      return primitiveWith("  Z = float(" + e + ");");
    }
    case 1: {  // deep parentheses, calls or unary operators
      const size_t n = sizeOf(in, 20000);
      const char* open[] = {"(", "abs(", "-", "!(", "float("};
      const char* close[] = {")", ")", "", ")", ")"};
      const size_t k = in.ConsumeIntegralInRange<size_t>(0, 4);
      return primitiveWith("  Z = float(" + repeat(open[k], n) + (k == 3 ? "Z > 0" : leaf) + repeat(close[k], n) + ");");
    }
    case 2: {  // postfixes: v.x.x.x... or a[0][0]...
      const size_t n = sizeOf(in, 100000);
      return primitiveWith("  float a[2]; a[0] = Z; a[1] = Z; vector v = vector(Z);\n  Z = " +
                           (in.ConsumeBool() ? "v" + repeat(".x", n) : "a" + repeat("[0]", n)) + ";");
    }
    case 3: case 4: {  // a call chain, each calling the one before once (3) or several times (4)
      const size_t n = shape == 3 ? sizeOf(in, 6000) : in.ConsumeIntegralInRange<size_t>(1, 30);
      const size_t calls = shape == 3 ? 1 : in.ConsumeIntegralInRange<size_t>(1, 3);
      // Named along the chain or against it (analyses that go in name order meet it backwards),
      // the innermost uniform or varying.
      const bool against = in.ConsumeBool();
      auto name = [&](size_t i) { return "f" + std::to_string(against ? n - i : i); };
      std::string fs = "float " + name(0) + "(float x) { return " + (in.ConsumeBool() ? "X" : "x * 0.5") + "; }\n";
      for (size_t i = 1; i <= n; ++i) {
        const std::string prev = name(i - 1);
        std::string sum = prev + "(x)";
        for (size_t c = 1; c < calls; ++c) sum += " + " + prev + "(x + " + std::to_string(c) + ".0)";
        fs += "float " + name(i) + "(float x) { " +
              (early ? "if (x > " + std::to_string(i) + ") return x; " : std::string()) + "return " + sum + "; }\n";
      }
      return primitiveWith("  Z = " + name(n) + "(" + leaf + ");", fs);
    }
    case 5: {  // an else-if chain, on a varying or a uniform value
      const size_t n = sizeOf(in, 5000);
      std::string body = "  float a = 0;\n  if (" + leaf + " < 0) a = 1;\n";
      for (size_t i = 1; i < n; ++i)
        body += "  else if (" + leaf + " < " + std::to_string(i) + ") a = " + std::to_string(i) + ";\n";
      return primitiveWith(body + "  Z = a;");
    }
    case 6: {  // nested blocks, ifs or loops
      const size_t n = sizeOf(in, 5000);
      const char* open[] = {"{ ", "if (Z > 0.5) { ", "for (int i = 0; i < 2; i += 1) { ", "while (Z > 2) { Z = Z - 1; "};
      const size_t k = in.ConsumeIntegralInRange<size_t>(0, 3);
      return primitiveWith("  " + repeat(open[k], n) + "Z = Z * 0.5;" + repeat(" }", n));
    }
    case 7: {  // nested conditionals
      const size_t n = sizeOf(in, 5000);
      std::string e;
      for (size_t i = 0; i < n; ++i) e += leaf + " > " + std::to_string(i) + " ? " + std::to_string(i) + ".0 : ";
      return primitiveWith("  Z = " + e + leaf + ";");
    }
    case 8: {  // extreme literals and names
      static const char* const kLiterals[] = {"1e999999", "1e39", "3.4e38", "1e-999", "2147483648", "0.0 / 0.0",
                                              "99999999999999999999", "1e38 * 1e38"};
      const std::string lit = kLiterals[in.ConsumeIntegralInRange<size_t>(0, 7)];
      const std::string name = repeat("n", in.ConsumeIntegralInRange<size_t>(1, 1 << 16));
      return primitiveWith("  float " + name + " = " + lit + ";\n  Z = " + name + ";");
    }
    case 9: {  // a runaway loop and very many statements
      const size_t n = sizeOf(in, 50000);
      return primitiveWith("  while (" + leaf + " >= 0) { Z = Z + 1; }\n" + repeat("  Z = Z * 0.999;\n", n));
    }
    default: {  // a long line with an error at its end, CR line ends, a NUL byte
      const size_t n = sizeOf(in, 1 << 20);
      std::string s = primitiveWith("  float a = 1.0" + std::string(n, ' ') + " + ;\r  Z = a;\r");
      if (in.ConsumeBool()) s.insert(s.size() / 2, 1, '\0');
      return s;
    }
  }
}

// A JSON scene text nested deep -- valid JSON whose scene is wrong (its error names a line:
// the line search once took memory quadratic in the depth), or cut off -- or with extreme
// numbers and sizes.
inline std::string sceneJson(Choices& in) {
  const int shape = in.ConsumeIntegralInRange<int>(0, 4);
  const size_t n = sizeOf(in, 2000000);
  switch (shape) {
    case 0: return "{\"objects\": [" + repeat("[", n) + "1" + repeat("]", n) + "]}";
    case 4: return "{\"objects\": [" + repeat("[", n) + (in.ConsumeBool() ? "1" : "") + repeat("]", n / 2);
    case 1: return "{\"objects\": []" + repeat(", \"x\": {\"y\": [", n % 100000) + "}";
    case 2: return "{\"objects\": [{\"primitive\": \"sphere\", \"params\": {\"radius\": " +
                   std::string(in.ConsumeBool() ? "1e999" : "-0.5e4444446") + "}}]}";
    default: return "{\"objects\": [" + repeat("{\"primitive\": \"sphere\"},", n % 20000) + "{}]}";
  }
}

// A field source of one of three formats ('format': 0 Fidget, 1 HyperFun, 2 language) whose
// values go NaN or infinite, whose tape is very long, or (HyperFun and language) whose
// expressions or statements nest deep, for every root-finding method.
inline std::string fieldSource(Choices& in, int& format) {
  format = in.ConsumeIntegralInRange<int>(0, 2);
  const int shape = in.ConsumeIntegralInRange<int>(0, format == 0 ? 2 : 3);
  const size_t n = sizeOf(in, 20000);
  if (format == 0) {  // Fidget: a ball, made NaN (sqrt of a negative), infinite, or a long chain
    std::string s = "_0 var-x\n_1 var-y\n_2 var-z\n_3 square _0\n_4 square _1\n_5 add _3 _4\n_6 square _2\n_7 add _5 _6\n"
                    "_8 sqrt _7\n_9 const 1\n_a sub _8 _9\n";
    if (shape == 0) s += "_b neg _9\n_c sqrt _b\n_d add _a _c\n";
    if (shape == 1) s += "_b const 0\n_c div _9 _b\n_d mul _a _c\n";
    if (shape == 2) {
      std::string last = "_a";
      for (size_t i = 0; i < n; ++i) {
        const std::string id = "_v" + std::to_string(i);
        s += id + " add " + last + " _9\n";
        last = id;
      }
    }
    return s;
  }
  if (format == 1 && shape == 3) {  // HyperFun nested deep: parentheses, calls, if or while blocks
    switch (in.ConsumeIntegralInRange<int>(0, 3)) {
      case 0: return "my_model(x[3], a[1])\n{\n  my_model = " + repeat("(", n) + "1 - x[1]" + repeat(")", n) + ";\n}\n";
      case 1: return "my_model(x[3], a[1])\n{\n  my_model = " + repeat("abs(", n) + "x[1]" + repeat(")", n) + " - 1" + ";\n}\n";
      case 2:
        return "my_model(x[3], a[1])\n{\n  t = 1;\n" + repeat("  if x[1] < 0.5 then\n", n) + "  t = x[2];\n" +
               repeat("  endif;\n", n) + "  my_model = t - x[3];\n}\n";
      default:
        return "my_model(x[3], a[1])\n{\n  t = x[1];\n" + repeat("  while t > 2 loop\n", n) + "  t = t - 1;\n" +
               repeat("  endloop;\n", n) + "  my_model = t;\n}\n";
    }
  }
  if (format == 2 && shape == 3) {  // a language field nested deep
    return in.ConsumeBool()
               ? "field float f(point p) {\n  return " + repeat("(", n) + "1 - p.x" + repeat(")", n) + ";\n}\n"
               : "field float f(point p) {\n  float t = p.x;\n  " + repeat("if (t < 0.5) { ", n) + "t = p.y;" +
                     repeat(" }", n) + "\n  return t - p.z;\n}\n";
  }
  if (format == 1) {  // HyperFun
    const std::string extra = shape == 0 ? " + sqrt(-1)" : shape == 1 ? " / 0" : repeat(" + 0.001", n);
    return "my_model(x[3], a[1])\n{\n  my_model = 1 - sqrt(x[1]^2 + x[2]^2 + x[3]^2)" + extra + ";\n}\n";
  }
  const std::string extra = shape == 0 ? " + sqrt(-1.0)" : shape == 1 ? " / 0.0" : repeat(" + 0.001", n);
  return "field float f(point p) {\n  return 1 - sqrt(p.x * p.x + p.y * p.y + p.z * p.z)" + extra + ";\n}\n";
}

}  // namespace pf::fuzz
