// Field sources by format (see field_source.h).
#include "compiler/field/field_source.h"

#include <filesystem>

#include "compiler/field/fidget_reader.h"
#include "compiler/field/field_unit.h"
#include "compiler/field/hyperfun_reader.h"
#include "compiler/field/sampled_reader.h"

namespace pf::field {

std::optional<FieldFormat> fieldFormatOfPath(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".vm") return FieldFormat::Fidget;
  if (ext == ".hf") return FieldFormat::HyperFun;
  if (ext == ".pfl") return FieldFormat::Language;
  if (ext == ".pfgrid") return FieldFormat::Sampled;
  return std::nullopt;
}

std::optional<FieldTape> compileFieldSource(FieldFormat format, const std::string& name, const std::string& text,
                                            const std::vector<double>& params, double time, DiagnosticLog& log,
                                            const std::string& unit, std::vector<FieldTape>* attributes) {
  if (attributes) attributes->clear();
  switch (format) {
    case FieldFormat::Fidget: return readFidgetModel(name, text, log);
    case FieldFormat::HyperFun: return readHyperFunModel(name, text, log, params, "my_model", time, attributes);
    case FieldFormat::Language: {
      const std::vector<float> values(params.begin(), params.end());
      return compileFieldUnit(name, text, unit.empty() ? std::filesystem::path(name).stem().string() : unit, values, log);
    }
    case FieldFormat::Sampled: {
      std::shared_ptr<const SampledGrid> grid = readSampledField(name, text, log);
      if (!grid) return std::nullopt;
      return sampledFieldTape(std::move(grid));
    }
  }
  return std::nullopt;
}

}  // namespace pf::field
