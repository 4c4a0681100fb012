#include "ui/rendering/render_panel.h"

#include "core/number_format.h"
#include "render/display/display.h"
#include "render/display/false_colour.h"
#include "render/engine/backend_table.h"
#include "ui/rendering/error_plot.h"
#include "ui/viewport/image_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTextStream>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <map>

namespace lucerna {

RenderPanel::RenderPanel(ConvergingRender* render, QWidget* parent) : QWidget(parent), render_(render) {
    view_ = new ImageView(this);
    view_->setObjectName("convergingView");
    view_->setPlaceholder(tr("The converging render appears here."));
    start_ = new QPushButton(tr("Start"), this);
    start_->setObjectName("renderStart");
    pause_ = new QPushButton(tr("Pause"), this);
    pause_->setObjectName("renderPause");
    pause_->setCheckable(true);
    restart_ = new QPushButton(tr("Restart"), this);
    restart_->setObjectName("renderRestart");
    backend_ = new QComboBox(this);
    backend_->setObjectName("renderBackend");
    backend_->addItem(tr("auto"), QStringLiteral("auto"));
    for (const BackendInfo& b : backendTable())
        backend_->addItem(QString::fromUtf8(b.name.data(), int(b.name.size())),
                          QString::fromUtf8(b.name.data(), int(b.name.size())));
    lightLayers_ = new QCheckBox(tr("Per-light layers"), this);
    lightLayers_->setObjectName("renderLightLayers");
    lightLayers_->setToolTip(tr("Render one layer per light: dimming, switching off or recolouring a light then "
                                "updates this image at once, without restarting (each pass costs one pass per light)."));
    reason_ = new QLabel(this);
    reason_->setObjectName("renderReason");
    reason_->setWordWrap(true);
    figures_ = new QLabel(this);
    figures_->setObjectName("renderFigures");
    plot_ = new ErrorPlot(this);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(start_);
    buttons->addWidget(pause_);
    buttons->addWidget(restart_);
    // The backend on a row of its own, so that the dock stays narrow enough for the viewport to
    // keep half the window.
    auto* method = new QHBoxLayout;
    method->addWidget(backend_, 1);
    method->addWidget(lightLayers_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(view_, 1);
    layout->addLayout(buttons);
    layout->addLayout(method);
    layout->addWidget(reason_);
    layout->addWidget(figures_);
    layout->addWidget(plot_);

    connect(start_, &QPushButton::clicked, render_, &ConvergingRender::start);
    connect(pause_, &QPushButton::toggled, render_, &ConvergingRender::setPaused);
    connect(restart_, &QPushButton::clicked, render_, &ConvergingRender::restart);
    connect(backend_, &QComboBox::currentIndexChanged, this,
            [this] { render_->setBackend(backend_->currentData().toString().toStdString()); });
    connect(lightLayers_, &QCheckBox::toggled, render_, &ConvergingRender::setLightLayers);
    connect(render_, &ConvergingRender::frameReady, this, &RenderPanel::showFrame);
    connect(render_, &ConvergingRender::stateChanged, this, &RenderPanel::showState);
    showState();
}

void RenderPanel::setDisplaySettings(const DisplaySettings& settings) {
    display_ = settings;
    view_->setLegend(luminanceLegend(settings));
    showFrame();
}

namespace {
// "mir 81%": a method and its share (0 to 1) of auto's time.
QString methodShare(const QString& method, double share) {
    return QStringLiteral("%1 %2%").arg(method).arg(std::lround(100 * share));
}

// "; pilots done at 3.2 s, path 96% of the time since", from lucerna:auto_decided ("3.2 path
// 0.96": when every pilot was done, in seconds, the method carrying the image and its share of
// the time since); empty where it is not of that form.
QString describeDecision(const std::string& decided) {
    QString text = QString::fromStdString(decided);
    QTextStream in(&text);
    double pilotsDoneSeconds = 0, share = 0;
    QString carrying;
    in >> pilotsDoneSeconds >> carrying >> share;
    if (in.status() != QTextStream::Ok || carrying.isEmpty()) return {};  // a number that was not one
    in.skipWhiteSpace();
    if (!in.atEnd()) return {};
    // One multi-argument arg(): the text it puts in is not scanned again.
    return RenderPanel::tr("; pilots done at %1 s, %2 of the time since")
        .arg(QString::number(pilotsDoneSeconds, 'f', 1), methodShare(carrying, share));
}

// "carried by mir, path; time mir 81%, ir 6%, ...; pilots done at 3.2 s, mir 96% of the time
// since", from a frame of auto's attributes.
QString describeAuto(const std::map<std::string, std::string>& attributes) {
    const auto methods = attributes.find("lucerna:auto_methods"), time = attributes.find("lucerna:auto_time");
    if (methods == attributes.end() || time == attributes.end() || methods->second.empty()) return {};
    std::vector<std::pair<double, QString>> shares;
    for (const QString& entry : QString::fromStdString(time->second).split(' ', Qt::SkipEmptyParts)) {
        const QStringList nameAndShare = entry.split('=');
        bool number = false;
        const double share = nameAndShare.size() == 2 ? nameAndShare[1].toFloat(&number) : 0.0f;
        if (number) shares.emplace_back(share, nameAndShare[0]);
    }
    std::ranges::sort(shares, std::greater<>());
    QStringList parts;
    for (const auto& [share, name] : shares)
        if (share >= 0.01) parts << methodShare(name, share);
    const auto decided = attributes.find("lucerna:auto_decided");
    return RenderPanel::tr("carried by %1; time %2%3")
        .arg(QString::fromStdString(methods->second).replace(' ', QStringLiteral(", ")), parts.join(QStringLiteral(", ")),
             decided != attributes.end() ? describeDecision(decided->second) : QString());
}
}  // namespace

void RenderPanel::showFrame() {
    const auto frame = render_->frame();
    if (!frame) return;
    if (const QString status = describeAuto(frame->image.attributes); status != autoStatus_) {
        autoStatus_ = status;
        showState();
    }
    view_->setImage(toDisplayImage(frame->image, display_));
    const double err = frame->estimatedRelmse;
    figures_->setText(tr("%1   %2 spp   estimated relmse %3")
                          .arg(QString::fromStdString(formatDuration(frame->seconds)))
                          .arg(frame->samplesPerPixel, 0, 'g', 4)
                          .arg(std::isfinite(err) ? QString::number(err, 'g', 3) : tr("(after two passes)")));
    plot_->setPoints(render_->history());
}

void RenderPanel::showState() {
    const bool running = render_->isRunning();
    start_->setEnabled(!running || render_->isPaused());
    pause_->setEnabled(running);
    {
        const QSignalBlocker block(pause_);
        pause_->setChecked(render_->isPaused());
    }
    if (!render_->frame()) autoStatus_.clear();  // a new render: nothing measured yet
    QString text;
    if (!render_->error().isEmpty())
        text = tr("Error: %1").arg(render_->error());
    else if (!render_->backendInUse().empty())
        text = render_->autoReason().empty()
                   ? tr("Backend: %1").arg(QString::fromStdString(render_->backendInUse()))
                   : tr("auto: %1").arg(autoStatus_.isEmpty() ? QString::fromStdString(render_->autoReason()) : autoStatus_);
    if (running && render_->isPaused()) text += tr(" (paused)");
    reason_->setText(text);
}

}  // namespace lucerna
