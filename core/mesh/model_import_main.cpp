// lucerna-model-import: the model importer's own process (core/mesh/model_import.h), so that a
// crash in Assimp costs this process, not the application and its unsaved work.

#include "core/mesh/model_import.h"

#include <QCoreApplication>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);  // for QImage's readers of embedded textures
    return lucerna::runModelImportProcess(argc, argv);
}
