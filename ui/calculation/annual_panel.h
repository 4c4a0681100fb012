#pragma once
// The Annual dock (SPEC.md section 6): a weather file, the points (a work plane over the room or
// one of the scene's task areas, as `lucerna annual` places them), the occupied hours; Compute
// runs the year in the background (render/annual/annual_calculation.h) with progress and Cancel,
// holding the yield gate as the grid dock does. The result: the section's figures (sDA, ASE, UDI,
// EN 17037) and the stated error, one metric per point in false colour (DA300, the three UDI
// bands, ASE hours, mean lux) on the dock's map and on the plan, and the year of a clicked point
// as a heat map. A scene edit marks the result out of date.

#include "core/daylight/annual_metrics.h"
#include "core/daylight/epw_file.h"
#include "core/photometry/calculation_grid.h"
#include "core/task_system.h"
#include "render/annual/annual_calculation.h"
#include "render/photometry/grid_calculation.h"
#include "ui/document/document.h"
#include "ui/rendering/yield_gate.h"

#include <QTimer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace lucerna {

class AnnualGridMap;
class YearHeatMap;

class AnnualPanel : public QWidget {
    Q_OBJECT
public:
    AnnualPanel(Document* doc, const YieldGate& gate, QWidget* parent = nullptr);
    ~AnnualPanel() override;

    // Asked for a weather file by Browse (a file dialog; empty: none chosen).
    void setFileQuestion(std::function<QString()> ask) { askFile_ = std::move(ask); }
    void setWeatherFile(const QString& path);
    void compute();
    void cancel();
    bool isComputing() const { return job_ != nullptr; }

    // The newest result, its points and figures (null before the first year).
    const AnnualResult* result() const { return result_ ? &*result_ : nullptr; }
    const AnnualMetrics* metrics() const { return metrics_ ? &*metrics_ : nullptr; }
    const CalculationGrid& grid() const { return grid_; }
    const GridLayout& layout() const { return layout_; }
    // The metric shown, as values per point for the plan (in its `lux` field) and its unit.
    std::shared_ptr<const GridResult> planValues() const { return planValues_; }
    QString planUnit() const;
    // The weather file, its path and the occupied hours of the shown year (the report's annual
    // section takes them once a year was computed here).
    const std::optional<WeatherFile>& weatherFile() const { return weatherFile_; }
    QString weatherPath() const { return weatherPath_; }
    const Occupancy& occupancy() const { return occupancy_; }
    // Shows the year of point `index` in the heat map.
    void showPoint(int index);

signals:
    void resultChanged();
    void finished();

private:
    enum Metric { kDa300, kUdiShort, kUdiUseful, kUdiExceeded, kAseHours, kMeanLux };

    void poll();
    void showResult();
    void showMetric();
    void listTaskAreas();
    void browse();

    Document* doc_;
    YieldGate gate_;
    std::function<QString()> askFile_;
    QLineEdit* weather_;
    QComboBox *area_, *metric_;
    QDoubleSpinBox *height_, *spacing_, *occupiedFrom_, *occupiedTo_;
    QPushButton *compute_, *cancel_, *browse_;
    QProgressBar* progress_;
    QLabel *status_, *figures_, *pointLabel_;
    AnnualGridMap* map_;
    YearHeatMap* heatMap_;
    QTimer poll_;

    TaskSystem tasks_;
    std::shared_ptr<TaskHandle> job_;
    std::shared_ptr<std::optional<AnnualResult>> pending_;  // the running job's
    std::optional<AnnualResult> result_;
    std::optional<AnnualMetrics> metrics_;
    std::optional<WeatherFile> weatherFile_, pendingWeather_;  // the shown year's, the running one's
    QString weatherPath_, pendingPath_;
    Occupancy occupancy_;
    CalculationGrid grid_;
    GridLayout layout_;
    SceneSnapshot resultScene_;
    std::shared_ptr<const GridResult> planValues_;
};

}  // namespace lucerna
