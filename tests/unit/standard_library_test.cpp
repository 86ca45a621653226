// The standard library the compiler embeds (compiler/stdlib.pfl and the field library's
// compiler/hyperfun*.pfl) parses without a diagnostic: the library index reads the files
// quietly when a program first calls into them, so a syntax error there would otherwise only
// show as functions that silently do not exist.
#include <gtest/gtest.h>

#include <string>

#include "compiler/embedded_primitives.h"
#include "compiler/parser.h"

namespace pf {
namespace {

TEST(StandardLibrary, EveryFileParsesCleanly) {
  ASSERT_GE(kStandardLibraryCount, 4);  // stdlib.pfl, hyperfun.pfl, hyperfun_convolution.pfl, hyperfun_sardf.pfl
  for (int i = 0; i < kStandardLibraryCount; ++i) {
    DiagnosticLog log;
    const Program p = parse(log.addSource(kStandardLibrary[i].file_name, kStandardLibrary[i].text), log);
    EXPECT_EQ(log.errorCount(), 0) << kStandardLibrary[i].file_name << ":\n" << log.format();
    EXPECT_FALSE(p.units.empty()) << kStandardLibrary[i].file_name;
  }
}

}  // namespace
}  // namespace pf
