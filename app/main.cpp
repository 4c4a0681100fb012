// lucerna: the application, or one of the headless commands of SPEC.md section 2.

#include "app/annual_command.h"
#include "app/bench_command.h"
#include "app/cli.h"
#include "app/glare_command.h"
#include "app/grid_command.h"
#include "app/import_command.h"
#include "app/report_command.h"
#include "app/mpi_session.h"
#include "core/resources.h"
#include "ui/document/autosave.h"
#include "ui/window/main_window.h"

#include <QApplication>
#include <QCoreApplication>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {
std::string defaultScenePath() { return lucerna::resourceDirectory() + "/scenes/cornell-box.json"; }
}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2) {
        const std::string command = argv[1];
        const std::vector<std::string> rest(argv + 2, argv + argc);
        if (command == "render" || command == "compare" || command == "info" || command == "convert" ||
            command == "bench" || command == "grid" || command == "import" || command == "standards" ||
            command == "glare" || command == "annual") {
            // Started by mpirun: render, grid and annual share their work among the ranks (MPI set up
            // before Qt, finalised after it).
            std::unique_ptr<lucerna::ProcessGroup> processes;
            if (command == "render" || command == "grid" || command == "annual") {
                try {
                    processes = lucerna::startMpiSession(argc, argv);
                } catch (const std::exception& e) {
                    std::fprintf(stderr, "lucerna: %s\n", e.what());
                    return 1;
                }
            }
            QCoreApplication app(argc, argv);  // Qt's file and image helpers; no display needed
            if (command == "render") return lucerna::cli::render(rest, processes.get());
            if (command == "grid") return lucerna::cli::grid(rest, processes.get());
            if (command == "compare") return lucerna::cli::compare(rest);
            if (command == "convert") return lucerna::cli::convert(rest);
            if (command == "bench") return lucerna::cli::bench(rest);
            if (command == "import") return lucerna::cli::importModelCommand(rest);
            if (command == "standards") return lucerna::cli::standards(rest);
            if (command == "glare") return lucerna::cli::glare(rest);
            if (command == "annual") return lucerna::cli::annual(rest, processes.get());
            return lucerna::cli::info(rest);
        }
        // The PDF report makes its own QGuiApplication (its fonts need one) once its input is good.
        if (command == "report") return lucerna::cli::report(rest, argc, argv);
        if (command == "-h" || command == "--help" || command == "help") {
            lucerna::cli::printUsage();
            return 0;
        }
        if (argc > 2 || (!command.empty() && command[0] == '-')) {
            lucerna::cli::printUsage();
            return 2;
        }
    }
    QApplication app(argc, argv);
    QApplication::setApplicationName("Lucerna");
    QApplication::setOrganizationName("Lucerna");
    lucerna::MainWindow window(argc >= 2 ? argv[1] : defaultScenePath());
    window.show();
    window.startAutosave(lucerna::Autosave::defaultDirectory());
    return app.exec();
}
