#include "ui/calculation/annual_panel.h"

#include "core/resources.h"
#include "core/scene/scene_change.h"
#include "core/scene/scene_geometry.h"
#include "ui/calculation/annual_charts.h"
#include "render/annual/annual_text.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace lucerna {

namespace {

// The command line's lines, one a paragraph.
QString figuresText(const WeatherFile& weather, const AnnualResult& r, const AnnualMetrics& m, const Occupancy& o) {
    QStringList lines;
    for (const std::string& line : annualFigureLines(weather, r, m, o)) lines << QString::fromStdString(line);
    lines << QString::fromStdString(annualErrorLine(r));
    return lines.join('\n');
}

}  // namespace

AnnualPanel::AnnualPanel(Document* doc, const YieldGate& gate, QWidget* parent) : QWidget(parent), doc_(doc), gate_(gate) {
    auto* form = new QFormLayout;
    weather_ = new QLineEdit(this);
    weather_->setObjectName("annualWeather");
    weather_->setToolTip(tr("An EnergyPlus weather file (.epw): a year of hourly irradiances"));
    browse_ = new QPushButton(tr("Browse..."), this);
    auto* weatherRow = new QHBoxLayout;
    weatherRow->addWidget(weather_, 1);
    weatherRow->addWidget(browse_);
    form->addRow(tr("Weather file"), weatherRow);
    area_ = new QComboBox(this);
    area_->setObjectName("annualArea");
    form->addRow(tr("Points"), area_);
    const auto spin = [this](const char* name, double lo, double hi, double value, const QString& suffix, int decimals) {
        auto* s = new QDoubleSpinBox(this);
        s->setObjectName(name);
        s->setRange(lo, hi);
        s->setDecimals(decimals);
        s->setValue(value);
        s->setSuffix(suffix);
        s->setFocusPolicy(Qt::StrongFocus);  // the wheel scrolls the dock unless the field has focus
        return s;
    };
    height_ = spin("annualHeight", -100, 100, 0.85, tr(" m"), 2);
    form->addRow(tr("Work plane height"), height_);
    spacing_ = spin("annualSpacing", 0, 10, 0, tr(" m"), 2);
    spacing_->setSpecialValueText(tr("EN 12464-1's rule"));
    form->addRow(tr("Spacing"), spacing_);
    occupiedFrom_ = spin("annualOccupiedFrom", 0, 24, 8, tr(":00"), 0);
    occupiedTo_ = spin("annualOccupiedTo", 0, 24, 18, tr(":00"), 0);
    auto* occupied = new QHBoxLayout;
    occupied->addWidget(occupiedFrom_);
    occupied->addWidget(new QLabel(tr("to"), this));
    occupied->addWidget(occupiedTo_);
    form->addRow(tr("Occupied"), occupied);

    compute_ = new QPushButton(tr("Compute the year"), this);
    compute_->setObjectName("annualCompute");
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setEnabled(false);
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(compute_);
    buttons->addWidget(cancel_);
    buttons->addWidget(progress_, 1);
    status_ = new QLabel(this);
    status_->setObjectName("annualStatus");
    status_->setWordWrap(true);
    figures_ = new QLabel(this);
    figures_->setObjectName("annualFigures");
    figures_->setWordWrap(true);
    figures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    metric_ = new QComboBox(this);
    metric_->setObjectName("annualMetric");
    metric_->addItems({tr("DA300 (% of occupied hours with 300 lx)"), tr("UDI fell short (< 100 lx)"),
                       tr("UDI useful (100 to 3000 lx)"), tr("UDI exceeded (> 3000 lx)"),
                       tr("ASE: hours of direct sun over 1000 lx"), tr("Mean illuminance, occupied hours")});
    map_ = new AnnualGridMap(this);
    map_->setObjectName("annualMap");
    pointLabel_ = new QLabel(this);
    heatMap_ = new YearHeatMap(this);
    heatMap_->setObjectName("annualHeatMap");

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addWidget(status_);
    layout->addWidget(figures_);
    layout->addWidget(metric_);
    layout->addWidget(map_, 1);
    layout->addWidget(pointLabel_);
    layout->addWidget(heatMap_, 1);

    const QString bundled = QString::fromStdString(resourceDirectory()) + "/weather/paris_synthetic.epw";
    weather_->setText(bundled);
    weather_->setPlaceholderText(tr("a .epw file"));
    connect(browse_, &QPushButton::clicked, this, &AnnualPanel::browse);
    connect(compute_, &QPushButton::clicked, this, &AnnualPanel::compute);
    connect(cancel_, &QPushButton::clicked, this, &AnnualPanel::cancel);
    connect(metric_, &QComboBox::currentIndexChanged, this, &AnnualPanel::showMetric);
    connect(map_, &AnnualGridMap::pointClicked, this, &AnnualPanel::showPoint);
    connect(area_, &QComboBox::currentIndexChanged, this, [this] { height_->setEnabled(area_->currentIndex() == 0); });
    connect(doc_, &Document::structureChanged, this, &AnnualPanel::listTaskAreas);
    connect(doc_, &Document::replaced, this, &AnnualPanel::listTaskAreas);
    connect(doc_, &Document::changed, this, [this] {
        if (result_ && resultScene_ && diff(*resultScene_, doc_->scene()).changesIlluminance())
            status_->setText(tr("Out of date: the scene changed since this year was computed. Compute again."));
    });
    poll_.setInterval(100);
    connect(&poll_, &QTimer::timeout, this, &AnnualPanel::poll);
    listTaskAreas();
}

AnnualPanel::~AnnualPanel() { cancel(); }

void AnnualPanel::setWeatherFile(const QString& path) { weather_->setText(path); }

void AnnualPanel::browse() {
    if (!askFile_) return;
    const QString path = askFile_();
    if (!path.isEmpty()) weather_->setText(path);
}

void AnnualPanel::listTaskAreas() {
    const QSignalBlocker quiet(area_);
    const QString current = area_->currentText();
    area_->clear();
    area_->addItem(tr("Work plane over the room"));
    for (const TaskArea& t : doc_->scene().taskAreas) area_->addItem(QString::fromStdString(t.grid.name));
    area_->setCurrentIndex(std::max(0, area_->findText(current)));
    height_->setEnabled(area_->currentIndex() == 0);
}

void AnnualPanel::compute() {
    cancel();
    const SceneSnapshot scene = doc_->snapshot();
    try {
        pendingWeather_ = readWeatherFile(weather_->text().toStdString());
        pendingPath_ = weather_->text();
        if (area_->currentIndex() == 0) {
            const SceneBounds b = sceneBounds(*scene);
            grid_ = workPlaneGrid(b.lo, b.hi, scene->metersPerUnit, height_->value(), 0.5);
        } else {
            grid_ = scene->taskAreas.at(size_t(area_->currentIndex() - 1)).grid;
        }
        if (spacing_->value() > 0) grid_.spacingMeters = spacing_->value();
        layout_ = layoutGrid(grid_, scene->metersPerUnit);
    } catch (const std::exception& e) {
        status_->setText(QString::fromStdString(e.what()));
        return;
    }
    occupancy_ = Occupancy{occupiedFrom_->value(), occupiedTo_->value()};
    if (!(occupancy_.fromHour < occupancy_.toHour)) {
        status_->setText(tr("The occupied hours must start before they end."));
        return;
    }
    // The shown year is another grid's or occupancy's from here on.
    result_.reset();
    metrics_.reset();
    figures_->clear();
    resultScene_ = scene;
    pending_ = std::make_shared<std::optional<AnnualResult>>();
    job_ = tasks_.submit([scene, points = layout_.points, normal = grid_.normal(), weather = *pendingWeather_,
                          pending = pending_, gate = gate_.counter()](TaskContext& ctx) {
        const YieldGate::Scope hold(gate);
        // Compute after Cancel goes on from the points traced (annual_checkpoint.h).
        AnnualSettings settings;
        settings.checkpointDirectory = cacheDirectory("annual");
        settings.resume = true;
        *pending = computeAnnual(*scene, points, normal, weather, settings, ctx);
    });
    compute_->setEnabled(false);
    cancel_->setEnabled(true);
    progress_->setValue(0);
    status_->setText(tr("Computing a year on %1 points...").arg(layout_.points.size()));
    poll_.start();
}

void AnnualPanel::cancel() {
    if (!job_) return;
    job_->cancel();
    job_->wait();
    job_.reset();
    poll_.stop();
    compute_->setEnabled(true);
    cancel_->setEnabled(false);
    progress_->setValue(0);
    status_->setText(tr("Cancelled."));
}

void AnnualPanel::poll() {
    if (!job_) return;
    progress_->setValue(int(1000 * job_->progress()));
    if (!job_->isFinished()) return;
    poll_.stop();
    try {
        job_->rethrowIfFailed();
    } catch (const std::exception& e) {
        status_->setText(tr("The year failed: %1").arg(e.what()));
    }
    job_.reset();
    compute_->setEnabled(true);
    cancel_->setEnabled(false);
    if (*pending_ && !(*pending_)->cancelled) {
        result_ = std::move(**pending_);
        weatherFile_ = std::move(pendingWeather_);
        weatherPath_ = pendingPath_;
        showResult();
    }
    pending_.reset();
    emit finished();
}

void AnnualPanel::showResult() {
    std::vector<uint8_t> counted(result_->points);
    for (size_t p = 0; p < counted.size(); ++p) counted[p] = !result_->insideGeometry[p];
    metrics_ = computeAnnualMetrics(result_->hours, result_->points, result_->lux, result_->directSunLux, occupancy_, counted);
    status_->setText(tr("A year on %1 points in %2 s.").arg(result_->points).arg(result_->tracingSeconds + result_->hoursSeconds, 0, 'f', 1));
    figures_->setText(figuresText(*weatherFile_, *result_, *metrics_, occupancy_));
    showMetric();
    showPoint(int(result_->points / 2));
}

QString AnnualPanel::planUnit() const {
    const int m = metric_->currentIndex();
    return m == kAseHours ? tr("h") : m == kMeanLux ? tr("lx") : tr("%");
}

void AnnualPanel::showMetric() {
    if (!metrics_) return;
    const int m = metric_->currentIndex();
    std::vector<double> values;
    for (const PointAnnualMetrics& p : metrics_->points)
        values.push_back(m == kDa300 ? 100 * p.da300 : m == kUdiShort ? 100 * p.udiFellShort : m == kUdiUseful ? 100 * p.udiUseful
                         : m == kUdiExceeded ? 100 * p.udiExceeded : m == kAseHours ? double(p.aseHours) : p.meanLux);
    // Fractions on a fixed 0 to 100% ramp so that two rooms compare; hours and lux by their range.
    double hi = 100;
    if (m == kAseHours || m == kMeanLux) hi = std::max(1.0, *std::max_element(values.begin(), values.end()));
    const Legend legend{0, hi, false, planUnit()};
    const double cell = std::min(layout_.spacingUMeters, layout_.spacingVMeters) / resultScene_->metersPerUnit;
    map_->setValues(layout_.points, cell, values, legend, result_->insideGeometry);
    auto plan = std::make_shared<GridResult>();
    plan->lux = values;
    plan->errorLux.assign(values.size(), 0.0);
    plan->insideGeometry = result_->insideGeometry;
    planValues_ = plan;
    emit resultChanged();
}

void AnnualPanel::showPoint(int index) {
    if (!result_ || index < 0 || size_t(index) >= result_->points) return;
    map_->setSelected(index);
    std::vector<float> lux(result_->hours.size());
    for (size_t row = 0; row < lux.size(); ++row) lux[row] = result_->lux[row * result_->points + size_t(index)];
    heatMap_->setYear(result_->hours, std::move(lux));
    const V3d& p = layout_.points[size_t(index)];
    pointLabel_->setText(tr("Point %1 at (%2, %3, %4): its year, hour by hour")
                             .arg(index + 1)
                             .arg(p.x, 0, 'f', 2)
                             .arg(p.y, 0, 'f', 2)
                             .arg(p.z, 0, 'f', 2));
}

}  // namespace lucerna
