#pragma once
// `lucerna annual`: a year of daylight on a grid's points from an EPW weather file, and the
// climate-based metrics of SPEC.md section 6 (sDA300/50%, ASE1000,250h, UDI, EN 17037's
// illuminance method).

#include <string>
#include <vector>

namespace lucerna {
class ProcessGroup;
}

namespace lucerna::cli {

// annual SCENE.json --weather FILE.epw (--work-plane HEIGHT_M [--border M] | --task-area NAME)
//        [--spacing M] [--occupancy FROM-TO] [--dew-point C] [--csv OUT.csv] [--hourly OUT.csv]
//        [--export-hour MM-DD-HH OUT.json] [--seed N] [--threads N] [--resume]
//        additions: [--hourly-error OUT.csv] [--hourly-direct OUT.csv] [--sky-subdivision M] [--paths N]
//        [--sun-paths N]
// The traced points are kept in the user's cache as they go (render/annual/annual_checkpoint.h);
// --resume reads those of an interrupted run of the same year instead of tracing them again.
// Returns the exit status of SPEC.md section 2 (2 with one line for bad usage or input, 130 when
// interrupted, with no file written).
// Under mpirun (app/mpi_session.h), `processes` are the ranks that share the year
// (AnnualSettings::processes): rank 0 prints and writes; nullptr: this process alone.
int annual(const std::vector<std::string>& args, ProcessGroup* processes = nullptr);

}  // namespace lucerna::cli
