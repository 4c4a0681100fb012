#include "ui/calculation/grid_panel.h"

#include "ui/properties/number_fields.h"
#include "core/daylight/daylight.h"
#include "core/daylight/daylight_provision.h"

#include "core/atomic_file.h"
#include "core/number_format.h"
#include "core/scene/scene_change.h"
#include "core/scene/scene_geometry.h"
#include "render/display/display.h"
#include "render/display/plan_scales.h"
#include "render/photometry/grid_text.h"
#include "render/photometry/task_area_figures.h"
#include "ui/calculation/ugr_table.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSignalBlocker>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace lucerna {

namespace {
// The lines of render/photometry/grid_text.h and ugr_grid.h for a label.
QString text(const std::string& line) { return QString::fromStdString(line); }
QStringList text(const std::vector<std::string>& lines) {
    QStringList list;
    for (const std::string& line : lines) list << text(line);
    return list;
}

QString outOfDateText() { return GridPanel::tr("The scene changed since this result: Compute again to update it."); }
}  // namespace

void GridPanel::quantityChanged() {
    const bool ugr = quantity_->currentIndex() == kUgr;
    eyeHeight_->setEnabled(ugr);
    viewAlong_->setEnabled(ugr);
    height_->setEnabled(!ugr && !taskArea_);  // the eyes stand at their own height above the floor
    enableExtras();
}

void GridPanel::enableExtras() {
    const bool on = taskArea_ && quantity_->currentIndex() == kIlluminance;
    cylindrical_->setEnabled(on);
    roomSurfaces_->setEnabled(on);
}

void GridPanel::sceneChanged() {
    if (!(shown_ || shownGlare_) || stale_ || !resultScene_) return;
    if (!diff(*resultScene_, doc_->scene()).changesIlluminance()) return;  // the camera moved, say
    stale_ = true;
    status_->setText(outOfDateText());
}

void GridPanel::listTaskAreas() {
    QStringList names{tr("None: whole room or drawn")};
    for (const TaskArea& t : doc_->scene().taskAreas)
        names << (t.activity.empty() ? QString::fromStdString(t.grid.name)
                                     : tr("%1 (%2)").arg(QString::fromStdString(t.grid.name), QString::fromStdString(t.activity)));
    QStringList shown;
    for (int i = 0; i < areaChoice_->count(); ++i) shown << areaChoice_->itemText(i);
    if (names != shown) {
        const QSignalBlocker quiet(areaChoice_);
        areaChoice_->clear();
        areaChoice_->addItems(names);
    }
    // The chosen area keeps its place by name; gone from the scene, the whole room again.
    int chosen = 0;
    const std::vector<TaskArea>& areas = doc_->scene().taskAreas;
    for (size_t i = 0; taskArea_ && i < areas.size(); ++i)
        if (areas[i].grid.name == *taskArea_) chosen = int(i) + 1;
    if (taskArea_ && chosen == 0) useWholeRoom();
    const QSignalBlocker quiet(areaChoice_);
    areaChoice_->setCurrentIndex(chosen);
}

void GridPanel::areaChosen() {
    const int index = areaChoice_->currentIndex() - 1;
    if (index < 0) useWholeRoom();
    else useTaskArea(index);
}

void GridPanel::useTaskArea(int index) {
    const std::vector<TaskArea>& areas = doc_->scene().taskAreas;
    if (index < 0 || size_t(index) >= areas.size()) return;
    const TaskArea& t = areas[size_t(index)];
    drawn_.reset();
    taskArea_ = t.grid.name;
    const ActivityRequirement* activity = t.activity.empty() ? nullptr : findActivity(t.activity, lightingStandardOf(doc_->scene()));
    area_->setText(activity ? tr("Task area '%1': %2").arg(QString::fromStdString(t.grid.name),
                                                            QString::fromStdString(describeRequirement(*activity, lightingStandardOf(doc_->scene()))))
                            : tr("Task area '%1' (no activity: nothing to check)").arg(QString::fromStdString(t.grid.name)));
    wholeRoom_->setEnabled(true);
    border_->setEnabled(false);
    height_->setEnabled(false);  // the area lies where it was placed
    if (spacing_->isEnabled()) userSpacing_ = spacing_->value();
    spacing_->setValue(t.grid.spacingMeters.value_or(0));  // its own (0: the rule), shown as it is used
    spacing_->setEnabled(false);
    const TaskAreaExtrasRequest asked = extrasFor(activity);  // the designer may add or leave them out
    cylindrical_->setChecked(asked.cylindrical);
    roomSurfaces_->setChecked(asked.roomSurfaces);
    enableExtras();
    const QSignalBlocker quiet(areaChoice_);
    areaChoice_->setCurrentIndex(index + 1);
}

void GridPanel::leaveTaskArea() {
    taskArea_.reset();
    height_->setEnabled(quantity_->currentIndex() != kUgr);
    if (!spacing_->isEnabled()) spacing_->setValue(userSpacing_);
    spacing_->setEnabled(true);
    cylindrical_->setChecked(false);  // not computed for these: unticked, not only greyed
    roomSurfaces_->setChecked(false);
    enableExtras();
    const QSignalBlocker quiet(areaChoice_);
    areaChoice_->setCurrentIndex(0);
}

void GridPanel::setDrawnRectangle(const V3d& a, const V3d& normal, const V3d& b) {
    drawn_ = Drawn{a, normal, b};
    leaveTaskArea();
    const bool horizontal = std::abs(normal.y) >= 0.7;
    area_->setText(horizontal ? tr("Rectangle drawn on a horizontal surface") : tr("Rectangle drawn on a wall"));
    wholeRoom_->setEnabled(true);
    border_->setEnabled(false);
}

void GridPanel::useWholeRoom() {
    drawn_.reset();
    leaveTaskArea();
    area_->setText(tr("Work plane over the whole room"));
    wholeRoom_->setEnabled(false);
    border_->setEnabled(true);
}

void GridPanel::compute() {
    cancel();
    const SceneSnapshot current = doc_->snapshot();
    SceneSnapshot scene = current;
    dfPerLux_.reset();
    maintenance_ = QString::fromStdString(describeMaintenance(maintenanceRange(*scene)));
    if (quantity_->currentIndex() == kDaylightFactor) {
        const Scene& s = *scene;
        medianGiven_ = s.site && s.site->medianDiffuseIlluminance;
        medianDiffuseIlluminance_ = medianGiven_ ? *s.site->medianDiffuseIlluminance : kDefaultMedianDiffuseIlluminance;
        DaylightFactorScene df = daylightFactorScene(s);
        if (!(df.skyHorizontalIlluminance > 0)) {
            status_->setText(tr("The sky gives no light: no daylight factor"));
            return;
        }
        dfPerLux_ = 100.0 / df.skyHorizontalIlluminance;
        scene = std::make_shared<const Scene>(std::move(df.scene));
    }
    CalculationGrid grid;
    requirement_ = nullptr;
    zones_ = {};
    extras_ = {};
    doneText_.clear();
    all_.reset();
    const TaskArea* area = nullptr;
    for (const TaskArea& t : current->taskAreas)  // the document's (the daylight-factor scene is derived)
        if (taskArea_ && t.grid.name == *taskArea_) area = &t;
    try {
        if (area) {
            grid = area->grid;  // its own spacing (EN 12464-1's rule unless given), as grid --task-area
            if (!area->activity.empty()) requirement_ = findActivity(area->activity, lightingStandardOf(*current));
        } else if (drawn_) {
            grid = gridFromCorners(drawn_->a, drawn_->normal, drawn_->b, scene->metersPerUnit, height_->value());
        } else {
            const SceneBounds b = sceneBounds(*scene);
            grid = workPlaneGrid(b.lo, b.hi, scene->metersPerUnit, height_->value(), border_->value());
        }
        if (spacing_->value() > 0 && !area) grid.spacingMeters = spacing_->value();
        layout_ = layoutGrid(grid, scene->metersPerUnit);
        grid_ = grid;
        if (area && quantity_->currentIndex() == kIlluminance) {
            // The zones are clipped to the area's room, as in grid --task-area and the report.
            const TaskAreaRoom room = taskAreaRoom(*current, *area);
            const ActivityRequirement* activity =
                area->activity.empty() ? nullptr : findActivity(area->activity, lightingStandardOf(*current));
            zones_ = ZoneGrids(*area, activity, current->metersPerUnit, room.lo, room.hi, layout_.points.size());
            extras_ = TaskAreaExtrasFigures(*area, *current, {cylindrical_->isChecked(), roomSurfaces_->isChecked()});
        }
    } catch (const std::invalid_argument& e) {
        status_->setText(QString::fromStdString(e.what()));
        return;
    }
    shown_.reset();
    shownGlare_.reset();
    latest_.reset();
    latestGlare_.reset();
    resultScene_ = current;
    if (quantity_->currentIndex() == kUgr) {
        computeUgr(scene, grid);
        return;
    }
    GridSettings settings;
    const int method = method_->currentData().toInt();
    settings.autoMethod = method == kAutoMethod;
    if (!settings.autoMethod) settings.method = GridMethod(method);
    settings.targetRelativeError = target_->value() / 100.0;
    settings_ = settings;
    latest_ = std::make_shared<Latest<GridResult>>();
    shownVersion_ = 0;
    stale_ = false;
    std::vector<V3d> points = layout_.points;  // and the task area's zones' after them
    points.insert(points.end(), zones_.points().begin(), zones_.points().end());
    job_ = tasks_.submit([scene, points = std::move(points), normal = grid.normal(), settings,
                          latest = latest_, gate = gate_.counter()](TaskContext& ctx) {
        const YieldGate::Scope hold(gate);
        // As `lucerna grid` and the report compute it (the maintained values among others).
        computeSceneGrid(scene, points, normal, settings, ctx, [&](const GridResult& r) {
            latest->publish(std::make_shared<const GridResult>(r));
        });
    });
    compute_->setEnabled(false);
    cancel_->setEnabled(true);
    progress_->setValue(0);
    status_->setText(tr("Computing %1 x %2 points...").arg(layout_.nu).arg(layout_.nv));
    poll_.start();
}

void GridPanel::computeUgr(const SceneSnapshot& scene, const CalculationGrid& grid) {
    if (std::abs(grid.normal().y) < 0.7) {
        status_->setText(tr("UGR needs a horizontal grid (the observers stand over it): draw it on a floor or a table"));
        return;
    }
    eyeHeightM_ = eyeHeight_->currentData().value<double>();
    eyes_ = observerPositions(layout_, sceneBounds(*scene).lo.y, scene->metersPerUnit, eyeHeightM_);
    const auto along = GridViewDirection(viewAlong_->currentData().toInt());
    view_ = gridViewDirection(grid, along);
    viewLabel_ = describeGridView(grid, along);
    GlareSettings settings;
    const int method = method_->currentData().toInt();
    if (method != kAutoMethod) settings.backgroundMethod = GridMethod(method);  // auto: path
    settings.targetRelativeError = target_->value() / 100.0;
    latestGlare_ = std::make_shared<Latest<GlareGridResult>>();
    shownVersion_ = 0;
    stale_ = false;
    job_ = tasks_.submit([scene, eyes = eyes_, view = view_, settings, latest = latestGlare_,
                          gate = gate_.counter()](TaskContext& ctx) {
        const YieldGate::Scope hold(gate);
        evaluateGlareGrid(*scene, eyes, view, settings, ctx, [&](const GlareGridResult& r) {
            latest->publish(std::make_shared<const GlareGridResult>(r));
        });
    });
    compute_->setEnabled(false);
    cancel_->setEnabled(true);
    progress_->setValue(0);
    status_->setText(tr("Computing UGR for %1 x %2 observers...").arg(layout_.nu).arg(layout_.nv));
    poll_.start();
}

void GridPanel::cancel() {
    if (!job_) return;
    job_->cancel();
    job_->wait();
    job_.reset();
    poll_.stop();
    compute_->setEnabled(true);
    cancel_->setEnabled(false);
    const bool extras = extras_.state() == TaskAreaExtrasFigures::State::Computing;
    extras_.cancel();  // none of them shown, not even a cancelled job's partial figures
    showFigures();
    if ((shown_ && !shown_->converged) || (shownGlare_ && !shownGlare_->converged))
        status_->setText(tr("Cancelled: the figures are those of the last pass."));
    else if (extras)
        status_->setText(doneText_ + "\n" + tr("Cancelled: the EN 12464-1:2021 figures are not computed."));
}

void GridPanel::poll() {
    if (!job_) return;
    progress_->setValue(int(std::lround(1000 * job_->progress())));
    // Whether it finished, before the newest result is read: the job publishes its last pass
    // before it finishes, so a job seen finished has nothing left to publish (read the other way
    // round, a pass published in between would never be shown).
    const bool jobDone = job_->isFinished();
    if (latest_ && latest_->version() != shownVersion_) {
        shownVersion_ = latest_->version();
        shown_ = latest_->get();
        if (!zones_.empty() && shown_) {
            all_ = shown_;
            shown_ = std::make_shared<const GridResult>(zones_.taskPart(*all_));
        }
        showResult();
    }
    if (latestGlare_ && latestGlare_->version() != shownVersion_) {
        shownVersion_ = latestGlare_->version();
        shownGlare_ = latestGlare_->get();
        showGlareResult();
    }
    if (!jobDone) return;
    poll_.stop();
    QString error;
    if (extras_.state() == TaskAreaExtrasFigures::State::Computing) {
        extras_.finish(*job_);  // a failure is told in its lines
        job_.reset();
        showFigures();
    } else {
        try {
            job_->rethrowIfFailed();
        } catch (const std::exception& e) {
            error = QString::fromStdString(e.what());
        }
        job_.reset();
        if (shownGlare_)
            doneText_ = tr("Done: %1 passes of the background, %2%3.")
                            .arg(shownGlare_->passes)
                            .arg(text(formatDuration(shownGlare_->seconds)))
                            .arg(shownGlare_->converged ? QString() : tr(" (error target not reached)"));
        else if (shown_)
            doneText_ = tr("Done: %1 passes, %2 samples per point, %3.")
                            .arg(shown_->passes)
                            .arg(shown_->samplesPerPoint)
                            .arg(text(formatDuration(shown_->seconds)));
        if (error.isEmpty() && startExtras()) return;
        extras_.cancel();  // the Em grid failed: not started
    }
    compute_->setEnabled(true);
    cancel_->setEnabled(false);
    progress_->setValue(1000);
    QString status = error.isEmpty() ? doneText_ : tr("The calculation failed: %1").arg(error);
    if (!extras_.doneText().empty()) status += "\n" + tr("%1.").arg(text(extras_.doneText()));
    if (stale_) status += "\n" + outOfDateText();  // changed while it ran
    status_->setText(status);
    emit finished();
}

bool GridPanel::startExtras() {
    if (extras_.state() != TaskAreaExtrasFigures::State::Waiting || !shown_ || !resultScene_) return false;
    job_ = extras_.start(tasks_, resultScene_, settings_, gate_.counter());
    progress_->setValue(0);
    status_->setText(doneText_ + "\n" + tr("Computing %1...").arg(text(extras_.computingText())));
    showFigures();
    poll_.start();
    return true;
}

void GridPanel::showFigures() {
    if (!shown_) return;
    // Daylight factor: every value is lux times 100 / Eh,sky, in %.
    std::vector<double> values = shown_->lux;
    for (double& v : values) v *= dfPerLux_.value_or(1.0);
    const GridStatistics s = gridStatistics(values, shown_->insideGeometry);
    QStringList lines;
    if (dfPerLux_) {
        lines << text(daylightFactorFiguresLine(s));
        const DaylightProvision p = checkDaylightProvision(values, shown_->insideGeometry, medianDiffuseIlluminance_);
        lines << tr("EN 17037 (E v,d,med %1 lx%2):").arg(medianDiffuseIlluminance_, 0, 'f', 0)
                                                   .arg(medianGiven_ ? QString() : tr(", the usual value"));
        for (const ProvisionLevel& l : p.levels)
            lines << tr("  %1 level: %2 (half the plane %3% for %4%, margin %5; 95% %6% for %7%, margin %8)")
                         .arg(QString::fromLatin1(l.name), l.met ? tr("met") : tr("not met"))
                         .arg(p.dfHalf, 0, 'f', 2)
                         .arg(l.targetDf, 0, 'f', 2)
                         .arg(l.targetMargin, 0, 'f', 2)
                         .arg(p.df95, 0, 'f', 2)
                         .arg(l.minimumTargetDf, 0, 'f', 2)
                         .arg(l.minimumMargin, 0, 'f', 2);
    } else {
        lines << text(gridFiguresLine(s));
        lines << text(extras_.lines(s));
        lines << maintenance_;
        lines << requirementLines(s);
        if (all_ && resultScene_) lines << text(zones_.lines(*all_, valuesAreMaintained(maintenanceRange(*resultScene_))));
    }
    if (s.excluded > 0) lines << text(excludedPointsLine(s, shown_->lux.size(), dfPerLux_.has_value()));
    lines << tr("method %1").arg(QString::fromLatin1(gridMethodName(shown_->method)));
    if (!shown_->autoMeasured.empty()) lines.back() += tr(" (auto: %1)").arg(text(shown_->autoMeasured));
    lines << text(gridErrorLines(*shown_, s.counted));
    figures_->setText(lines.join('\n'));
}

void GridPanel::showResult() {
    if (!shown_) return;
    showFigures();
    const double scale = dfPerLux_.value_or(1.0);
    std::vector<double> values = shown_->lux;
    for (double& v : values) v *= scale;
    const GridStatistics s = gridStatistics(values, shown_->insideGeometry);
    // Rows from the far side (largest j) down, as the plane is seen from above with u to the right.
    table_->setRowCount(layout_.nv);
    table_->setColumnCount(layout_.nu);
    const double lo = std::max(s.minimum, 1e-3), hi = std::max(s.maximum, lo * 1.001);
    // The plan's colours (ui/plan/plan_view.h): a task area's lux centred on its Em, else a log
    // scale over the values.
    const Legend legend = requirement_ && !dfPerLux_ ? requirementScale(requirement_->maintainedLux, s).legend(tr("lx"))
                                                     : Legend(lo, hi, true, QString());
    for (int j = 0; j < layout_.nv; ++j)
        for (int i = 0; i < layout_.nu; ++i) {
            const size_t k = size_t(j) * size_t(layout_.nu) + size_t(i);
            const double e = values[k];
            if (shown_->insideGeometry[k]) {
                // Not a reading: grey, hatched, no number that could be taken for one.
                auto* item = new QTableWidgetItem(tr("inside"));
                item->setTextAlignment(Qt::AlignCenter);
                item->setBackground(QBrush(QColor(150, 150, 150), Qt::BDiagPattern));
                item->setForeground(QColor(90, 90, 90));
                item->setToolTip(tr("Inside geometry: excluded from Eavg, Emin, Emax and U0"));
                table_->setItem(layout_.nv - 1 - j, i, item);
                continue;
            }
            auto* item = new QTableWidgetItem(QString::number(e, 'f', dfPerLux_ ? 2 : 0));
            item->setTextAlignment(Qt::AlignCenter);
            const QColor c = legendColour(legend, e);
            item->setBackground(c);
            item->setForeground(c.lightnessF() > 0.55 ? Qt::black : Qt::white);
            const QString unit = dfPerLux_ ? tr("%") : tr(" lx");
            item->setToolTip(shown_->errorBarUnknown
                                 ? tr("%1%2, error bar unknown (light through glass missing)").arg(e, 0, 'f', 2).arg(unit)
                                 : tr("%1%3 +- %2%3").arg(e, 0, 'f', 2).arg(shown_->errorLux[k] * scale, 0, 'f', 2).arg(unit));
            table_->setItem(layout_.nv - 1 - j, i, item);
        }
    export_->setEnabled(true);
    emit resultChanged();
}

QStringList GridPanel::requirementLines(const GridStatistics& s) const {
    if (!requirement_ || !shown_ || !resultScene_ || s.counted == 0) return {};
    // The figures and verdicts of `lucerna grid --task-area` (app/grid_command.cpp).
    TaskAreaFigures figures;
    figures.grid = s;
    if (!shown_->errorBarUnknown) figures.gridErrors = gridErrorBars(s, shown_->lux, shown_->errorLux, shown_->insideGeometry);
    figures.colourRendering = statedColourRendering(*resultScene_);
    figures.maintainedValues = valuesAreMaintained(maintenanceRange(*resultScene_));
    extras_.addTo(figures);
    QStringList lines{QString::fromStdString(describeRequirement(*requirement_, lightingStandardOf(*resultScene_)))};
    for (const RequirementCheck& c : checkRequirements(*requirement_, figures)) lines << "  " + QString::fromStdString(c.describe());
    return lines;
}

void GridPanel::showGlareResult() {
    if (!shownGlare_ || shownGlare_->observers.size() != layout_.points.size()) return;
    figures_->setText(text(ugrGridFigures(*shownGlare_, layout_, eyeHeightM_, viewLabel_)).join('\n'));
    fillUgrTable(*table_, layout_, *shownGlare_);
    export_->setEnabled(true);
    emit resultChanged();
}

void GridPanel::exportCsv(const QString& path) const {
    if (shownGlare_) {
        writeTextAtomically(path.toStdString(), ugrCsv(layout_, eyes_, *shownGlare_));
        return;
    }
    if (!shown_) throw std::runtime_error("no grid result to export");
    writeTextAtomically(path.toStdString(),
                        gridCsv(layout_, shown_->lux, shown_->errorLux, shown_->insideGeometry, shown_->errorBarUnknown,
                                dfPerLux_));
}

void GridPanel::exportClicked() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export grid"), QString(), tr("CSV files (*.csv)"));
    if (path.isEmpty()) return;
    try {
        exportCsv(path);
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Export grid"), QString::fromStdString(e.what()));
    }
}

}  // namespace lucerna
