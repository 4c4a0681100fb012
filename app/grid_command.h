#pragma once
// `lucerna grid`: illuminance on a calculation grid (core/photometry/calculation_grid.h) with the figures of
// EN 12464-1 (Eavg, Emin, Emax, U0) and a Monte Carlo error bar per point.

#include <string>
#include <vector>

namespace lucerna {
class ProcessGroup;
}

namespace lucerna::cli {

// grid SCENE.json (--work-plane HEIGHT_M [--border M] | --corner X,Y,Z --u X,Y,Z --v X,Y,Z)
//      [--spacing M] [--method path|ir] [--error FRACTION] [--time SECONDS] [--seed N]
//      [--samples N] [--vpl-paths N] [--threads N] [--name NAME] [--csv OUT.csv] [--cylindrical]
//      [--task-area NAME [--room-surfaces] [--horizontal-only]]
// With --task-area, the area's zones and the EN 12464-1:2021 figures its activity asks for
// (app/grid_task_area.h) follow its figures, with every check.
// Returns the exit status of SPEC.md section 2 (2 with one line for bad usage or input, 130 when
// interrupted, with no file written).
// Under mpirun (app/mpi_session.h), `processes` are the ranks that share the grid
// (GridSettings::processes); nullptr: this process alone.
int grid(const std::vector<std::string>& args, ProcessGroup* processes = nullptr);

}  // namespace lucerna::cli
