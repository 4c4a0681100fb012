#include "ui/compare/compare_view.h"

#include "core/image/image_metrics.h"
#include "render/display/false_colour.h"
#include "ui/compare/compare_canvas.h"
#include "ui/rendering/display_controls.h"
#include "ui/rendering/pixel_probe.h"
#include "ui/compare/view_transform.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace lucerna {

CompareView::CompareView(QWidget* parent) : QWidget(parent) {
    transform_ = new ViewTransform(this);
    first_ = new CompareCanvas(transform_, this);
    first_->setObjectName("compareFirst");
    second_ = new CompareCanvas(transform_, this);
    second_->setObjectName("compareSecond");
    controls_ = new DisplayControls(this);
    modeBox_ = new QComboBox(this);
    modeBox_->setObjectName("compareMode");
    modeBox_->addItems({tr("Side by side"), tr("Split"), tr("Difference (absolute)"), tr("Difference (relative)")});
    auto* fit = new QPushButton(tr("Fit"), this);
    fit->setToolTip(tr("Show the whole image (wheel zooms, drag pans)"));
    relmseLabel_ = new QLabel(this);
    relmseLabel_->setObjectName("relmse");
    relmseLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    relmseLabel_->setToolTip(tr("relmse of the preview against the converged image (SPEC.md section 4)"));
    probe_ = new QLabel(this);
    probe_->setObjectName("probe");
    probe_->setTextInteractionFlags(Qt::TextSelectableByMouse);

    // Two rows: one row of everything would make the dock too wide to share the window.
    auto* top = new QHBoxLayout;
    top->addWidget(modeBox_);
    top->addWidget(fit);
    top->addStretch();
    top->addWidget(relmseLabel_);
    auto* canvases = new QHBoxLayout;
    canvases->setSpacing(2);
    canvases->addWidget(first_);
    canvases->addWidget(second_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(controls_);
    layout->addLayout(canvases, 1);
    layout->addWidget(probe_);

    connect(modeBox_, &QComboBox::currentIndexChanged, this, [this](int i) { setMode(Mode(i)); });
    connect(fit, &QPushButton::clicked, transform_, &ViewTransform::reset);
    connect(controls_, &DisplayControls::settingsChanged, this, &CompareView::setDisplaySettings);
    connect(controls_, &DisplayControls::rangeSetByUser, this, [this] {
        if (display_.falseColour && display_.quantity == FalseColourQuantity::Illuminance) luxRangeByUser_ = true;
    });
    connect(first_, &CompareCanvas::hovered, this, &CompareView::probe);
    connect(second_, &CompareCanvas::hovered, this, &CompareView::probe);
    refresh();
}

namespace {
bool isLuxView(const DisplaySettings& s) { return s.falseColour && s.quantity == FalseColourQuantity::Illuminance; }
}  // namespace

bool CompareView::fitLuxRange(DisplaySettings& settings) {
    if (!isLuxView(settings) || luxRangeByUser_ || luxRangeFitted_) return false;
    // The converged image is the better estimate; the preview where it has no lux yet.
    std::optional<FalseColourRange> range = illuminanceRange(converged_);
    if (!range) range = illuminanceRange(preview_);
    if (!range) return false;
    settings.falseMin = range->lo;
    settings.falseMax = range->hi;
    luxRangeFitted_ = true;
    return true;
}

void CompareView::setPreview(Image image) {
    preview_ = std::move(image);
    if (DisplaySettings s = display_; fitLuxRange(s)) return setDisplaySettings(s);
    refresh();
}

void CompareView::setConverged(Image image) {
    converged_ = std::move(image);
    if (DisplaySettings s = display_; fitLuxRange(s)) return setDisplaySettings(s);
    refresh();
}

void CompareView::setMode(Mode mode) {
    mode_ = mode;
    {
        const QSignalBlocker block(modeBox_);
        modeBox_->setCurrentIndex(int(mode));
    }
    refresh();
}

void CompareView::setDisplaySettings(const DisplaySettings& requested) {
    DisplaySettings settings = requested;
    if (!isLuxView(settings)) luxRangeFitted_ = false;  // entering the lux view again fits again
    else if (!isLuxView(display_)) fitLuxRange(settings);
    if (settings == display_) return;
    display_ = settings;
    controls_->setSettings(settings);
    refresh();
    emit displaySettingsChanged(display_);
}

void CompareView::setIlluminanceNote(const QString& note) {
    DisplaySettings s = display_;
    s.illuminanceNote = note;
    setDisplaySettings(s);
}

void CompareView::setLightsWhite(const Rgbd& lights) {
    DisplaySettings s = display_;
    s.lights = lights;
    setDisplaySettings(s);
}

void CompareView::showEvent(QShowEvent*) {
    if (stale_) refresh();
}

void CompareView::refresh() {
    const bool both = preview_.width > 0 && converged_.width > 0;
    // The number is cheap and the label is read even when the pictures are not shown.
    relmse_.reset();
    if (both) relmse_ = compareImages(resampledNearest(preview_, converged_.width, converged_.height), converged_).relmse;
    relmseLabel_->setText(relmse_ ? tr("relmse %1").arg(QString::number(*relmse_, 'g', 6)) : tr("relmse \u2014"));

    second_->setVisible(mode_ == Mode::SideBySide);
    if (!isVisible()) {
        stale_ = true;
        return;
    }
    stale_ = false;
    const auto picture = [this](const Image& image) { return image.width > 0 ? toDisplayImage(image, display_) : QImage(); };
    const std::optional<Legend> legend = luminanceLegend(display_);
    switch (mode_) {
    case Mode::SideBySide:
        first_->setImages(picture(preview_));
        second_->setImages(picture(converged_));
        first_->setCaptions(tr("Preview"));
        second_->setCaptions(tr("Converged"));
        first_->setLegend(std::nullopt);
        second_->setLegend(legend);
        break;
    case Mode::Split: {
        // Both at the converged image's size, so that the divider cuts the same pixel in each.
        const Image p = both ? resampledNearest(preview_, converged_.width, converged_.height) : preview_;
        first_->setImages(picture(p), both ? picture(converged_) : QImage());
        first_->setCaptions(tr("Preview"), tr("Converged"));
        first_->setLegend(legend);
        break;
    }
    case Mode::AbsoluteDifference:
    case Mode::RelativeDifference: {
        const bool absolute = mode_ == Mode::AbsoluteDifference;
        if (!both) {
            first_->setImages({});
            first_->setLegend(std::nullopt);
            break;
        }
        // Relative to the converged image, the reference, as relmse is.
        const DifferenceImage d = differenceImage(resampledNearest(preview_, converged_.width, converged_.height),
                                                  converged_, absolute ? DifferenceKind::Absolute : DifferenceKind::Relative);
        first_->setImages(d.picture);
        first_->setCaptions(absolute ? tr("|preview \u2212 converged|") : tr("|preview \u2212 converged| / (converged + 0.01)"));
        first_->setLegend(Legend{0, d.maxValue, false, absolute ? tr("W/(sr m\u00b2)") : tr("relative")});
        break;
    }
    }
}

void CompareView::probe(QPointF p) {
    const auto at = [&](const Image& image, const QString& name) -> QString {
        const auto px = pixelAt(image, p);
        return px ? tr("%1 %2").arg(name, probeText(image, *px)) : QString();
    };
    const auto px = pixelAt(converged_.width > 0 ? converged_ : preview_, p);
    if (!px) {
        probe_->clear();
        return;
    }
    QStringList parts{tr("(%1, %2)").arg(px->x()).arg(px->y())};
    for (const QString& s : {at(preview_, tr("preview")), at(converged_, tr("converged"))})
        if (!s.isEmpty()) parts << s;
    probe_->setText(parts.join(QStringLiteral("   ")));
}

}  // namespace lucerna
