// The tools' one rule for command lines (docs/models.md, README): `--help` prints and exits 0;
// any other parse error -- an unknown option, a value out of range, a missing argument -- is a
// bad command line and exits 2, whatever CLI11's own code for that error (105, 109, ...).
#pragma once

#include <CLI/CLI.hpp>

// Parses argv into `app`, returning from the calling main() on --help or a bad command line.
#define PF_PARSE_COMMAND_LINE(app, argc, argv)          \
  do {                                                  \
    try {                                               \
      (app).parse((argc), (argv));                      \
    } catch (const CLI::ParseError& pf_parse_error) {   \
      return (app).exit(pf_parse_error) == 0 ? 0 : 2;   \
    }                                                   \
  } while (false)
