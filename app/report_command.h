#pragma once
// `lucerna report`: the PDF report a lighting designer hands in (README, "Reports";
// report/report_builder.h and report_writer.h).

#include <string>
#include <vector>

namespace lucerna::cli {

// report SCENE.json -o OUT.pdf [--method M] [--error F] [--seed N] [--samples N] [--time S]
//        [--spp N] [--threads N]
// Progress on a terminal; Ctrl-C cancels (exit 130, no file); bad input one line and exit 2.
// Prints each task area's figures as `lucerna grid` does.
int report(const std::vector<std::string>& args);

}  // namespace lucerna::cli
