#pragma once
// `lucerna report`: the PDF report a lighting designer hands in (README, "Reports";
// report/report_builder.h and report_writer.h).

#include <string>
#include <vector>

namespace lucerna::cli {

// report SCENE.json -o OUT.pdf [--method M] [--error F] [--seed N] [--samples N] [--time S]
//        [--spp N] [--threads N]
// Progress on a terminal; Ctrl-C cancels (exit 130, no file); bad input one line and exit 2.
// Prints each task area's figures as `lucerna grid` does. Makes its own QGuiApplication from
// argc and argv (the PDF's fonts need one) once the input is known to be good, so that bad input
// is one line (a GUI application may say things of its own).
int report(const std::vector<std::string>& args, int& argc, char** argv);

}  // namespace lucerna::cli
