#pragma once
// The converging render's panel: its image, start / pause / restart, the backend choice (auto,
// with the reason it gives, and every backend of the table), and the convergence figures:
// elapsed render time, samples per pixel, the error estimated from the half-buffers, and their
// plot against time.

#include "render/display/display.h"
#include "ui/rendering/converging_render.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;

namespace lucerna {

class ErrorPlot;
class ImageView;

class RenderPanel : public QWidget {
    Q_OBJECT
public:
    RenderPanel(ConvergingRender* render, QWidget* parent = nullptr);

    ImageView* view() const { return view_; }
    QLabel* figures() const { return figures_; }
    // How the converged radiance is shown (the comparison's display controls set it).
    void setDisplaySettings(const DisplaySettings& settings);

private:
    void showFrame();
    void showState();

    ConvergingRender* render_;
    ImageView* view_;
    QPushButton *start_, *pause_, *restart_;
    QComboBox* backend_;
    QCheckBox* lightLayers_;
    QLabel *reason_, *figures_;
    QString autoStatus_;  // from the latest frame of auto: the methods that carry the image
    ErrorPlot* plot_;
    DisplaySettings display_;
};

}  // namespace lucerna
