#pragma once
// The headless commands of SPEC.md section 2: render, compare, info. Each returns the process
// exit status: 0 success, 2 bad usage or bad input (one line on stderr), 1 internal error.

#include <string>
#include <vector>

namespace lucerna {
class ProcessGroup;
}

namespace lucerna::cli {

// Under mpirun (app/mpi_session.h), `processes` are the ranks that share the render
// (render/backend/pooled_films.h); nullptr: this process alone.
int render(const std::vector<std::string>& args, ProcessGroup* processes = nullptr);
int compare(const std::vector<std::string>& args);
int info(const std::vector<std::string>& args);
// convert IN.exr OUT.png [--exposure STOPS]: what the screen would show (sRGB).
int convert(const std::vector<std::string>& args);
// `lucerna standards`: the bundled EN 12464-1 table (core/photometry/lighting_standards.h), one activity a line.
int standards(const std::vector<std::string>& args);
void printUsage();

}  // namespace lucerna::cli
