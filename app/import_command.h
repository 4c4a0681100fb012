#pragma once
// `lucerna import`: a model file (core/mesh/model_import.h) written out as a SPEC.md scene with a
// camera that looks at it, and the import report printed.

#include <string>
#include <vector>

namespace lucerna::cli {

// import MODEL -o SCENE.json [--meters-per-unit M] [--model-unit M]
// Returns the exit status of SPEC.md section 2 (2 with one line for bad usage or an unreadable
// model; no file is written then).
int importModelCommand(const std::vector<std::string>& args);

}  // namespace lucerna::cli
