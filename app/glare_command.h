#pragma once
// `lucerna glare`: discomfort glare (UGR, CIE 117) at an observer in a scene
// (render/photometry/glare_evaluation.h), or a luminaire file's UGR table by the tabular method
// (core/photometry/ugr_table.h).

#include <string>
#include <vector>

namespace lucerna::cli {

// glare SCENE.json --observer X,Y,Z --view X,Y,Z [--method M] [--error F] [--time S] [--seed N]
//       [--samples N] [--threads N]
// glare --table FILE.ies|FILE.ldt [--lumens LM] [--luminous-area W,L]
// Returns the exit status of SPEC.md section 2 (2 with one line for bad usage or input, 130 when
// interrupted).
int glare(const std::vector<std::string>& args);

}  // namespace lucerna::cli
