#include "ui/properties/light_set_properties.h"

#include "ui/disconnect_children.h"
#include "core/photometry/light_output.h"
#include "core/photometry/luminaire.h"
#include "ui/commands/light_commands.h"
#include "ui/commands/light_group_commands.h"
#include "ui/io/luminaire_import.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>

namespace lucerna {

namespace {
constexpr double kMixed = -1;  // a field's value below its real range: shown as "mixed"

bool hasPosition(const Light& l) { return l.type != LightType::Directional && l.type != LightType::Sun; }

// A distribution's own flux, integrated once per refresh however many luminaires share it (a
// field of 10,000 luminaires of one file integrates its table once, not 10,000 times).
using FluxCache = std::unordered_map<const GoniometricDistribution*, double>;

// A light's luminous flux in lm, where it has one the panel can set: luminaireFlux() with the
// file's integral taken from `cache`.
std::optional<double> fluxOf(const Light& l, FluxCache& cache) {
    switch (l.type) {
    case LightType::Point:
    case LightType::Spot: return luminousFluxLm(l);
    case LightType::Luminaire: {
        if (!l.luminaire || !l.luminaire->distribution) return std::nullopt;
        const LuminaireSpec& spec = *l.luminaire;
        const auto [it, fresh] = cache.try_emplace(spec.distribution.get(), 0.0);
        if (fresh) it->second = spec.distribution->integratedFlux();
        // As luminaireRadiantScale(): "lumens" rescales the file's flux, the tilt multiplies it.
        const double ownFlux = it->second;
        const Rgbd white(1, 1, 1);
        const Rgbd colour = spec.temperatureK ? blackbodyColour(*spec.temperatureK)
                                              : spec.colour.value_or(white) / luminance(spec.colour.value_or(white));
        const double scale = spec.lumens ? (ownFlux > 0 ? *spec.lumens / ownFlux : 0.0) : 1.0;
        return ownFlux * scale * spec.distribution->tiltMultiplier(luminaireTiltDeg(l.direction)) * luminance(colour);
    }
    case LightType::Directional:
    case LightType::Sun: return std::nullopt;
    }
    return std::nullopt;
}

// A light's colour temperature in K; nothing when it has a colour instead, or neither (white).
std::optional<double> temperatureOf(const Light& l) {
    if (l.type == LightType::Luminaire) return l.luminaire ? l.luminaire->temperatureK : std::nullopt;
    if (l.type == LightType::Directional || l.type == LightType::Sun) return std::nullopt;
    return photometricOf(l).temperatureK;
}

bool colourGivenFor(const Light& l) {
    if (l.type == LightType::Luminaire) return l.luminaire && l.luminaire->colour;
    if (l.type == LightType::Directional || l.type == LightType::Sun) return false;
    return photometricOf(l).colour.has_value();
}

Light withFlux(Light l, double lumens) {
    if (l.type == LightType::Luminaire) {
        // The flux shown is after the tilt multiplier; "lumens" is the flux before it.
        const double tilt = l.luminaire->distribution->tiltMultiplier(luminaireTiltDeg(l.direction));
        if (tilt > 0) l.luminaire->lumens = lumens / tilt;
        return l;
    }
    PhotometricSpec spec = photometricOf(l);
    spec.quantity = PhotometricSpec::Quantity::Lumens;
    spec.value = lumens;
    return withPhotometric(l, spec);
}

Light withTemperature(Light l, double kelvin) {
    if (l.type == LightType::Luminaire) {
        l.luminaire->temperatureK = kelvin;
        l.luminaire->colour.reset();
        return l;
    }
    PhotometricSpec spec = photometricOf(l);
    spec.temperatureK = kelvin;
    spec.colour.reset();
    return withPhotometric(l, spec);
}

// The one value all give, or nothing when they differ (within rounding) or there are none.
std::optional<double> shared(const std::vector<double>& values) {
    if (values.empty()) return std::nullopt;
    for (double v : values)
        if (!(std::abs(v - values.front()) <= 1e-9 * std::max(std::abs(v), std::abs(values.front())))) return std::nullopt;
    return values.front();
}

// "1 light", "3 lights" (no translation files, so no %n plurals).
QString counted(int n, const QString& one, const QString& many) {
    return QStringLiteral("%1 %2").arg(n).arg(n == 1 ? one : many);
}

void showValue(QDoubleSpinBox* spin, std::optional<double> value) {
    spin->setValue(value ? *value : spin->minimum());
}
}  // namespace

LightSetProperties::~LightSetProperties() { disconnectChildren(this); }

LightSetProperties::LightSetProperties(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* rows = new QVBoxLayout(this);
    title_ = new QLabel(this);
    title_->setObjectName("lightSetTitle");
    QFont bold = title_->font();
    bold.setBold(true);
    title_->setFont(bold);
    title_->setWordWrap(true);
    rows->addWidget(title_);
    summary_ = makeWrappingLabel(this, "lightSetSummary");
    rows->addWidget(summary_);

    group_ = new QLineEdit(this);
    group_->setObjectName("lightSetGroup");
    group_->setToolTip(tr("The group of these lights: a new name renames the group or gathers the lights into it; "
                          "empty takes them out of any group"));
    addPropertyRow(rows, tr("Group"), {group_});
    on_ = new QCheckBox(tr("Switched on"), this);
    on_->setObjectName("lightSetOn");
    addPropertyRow(rows, tr("Lights"), {on_});
    flux_ = makePropertySpin(this, kMixed, 1e9, 1);
    flux_->setObjectName("lightSetFlux");
    flux_->setSuffix(QStringLiteral(" lm"));
    flux_->setSpecialValueText(tr("mixed"));
    fluxRow_ = addPropertyRow(rows, tr("Flux of each"), {flux_});
    temperature_ = makePropertySpin(this, 999, 40000, 0);
    temperature_->setObjectName("lightSetTemperature");
    temperature_->setSuffix(QStringLiteral(" K"));
    temperature_->setSpecialValueText(tr("mixed"));
    temperature_->setSingleStep(100);
    temperatureRow_ = addPropertyRow(rows, tr("Colour temperature"), {temperature_});
    file_ = makeWrappingLabel(this, "lightSetFile");
    replace_ = new QPushButton(tr("Replace..."), this);
    replace_->setObjectName("lightSetReplaceFile");
    replace_->setToolTip(tr("Make every light with a position a luminaire of an IES or EULUMDAT file"));
    addPropertyRow(rows, tr("Luminaire file"), {file_, replace_});
    rows->addStretch(1);

    connect(group_, &QLineEdit::editingFinished, this, [this] { apply(Field::Group, group_); });
    connect(on_, &QCheckBox::clicked, this, [this] { apply(Field::On, on_); });
    for (QDoubleSpinBox* spin : {flux_, temperature_}) {
        connect(spin, &QDoubleSpinBox::valueChanged, this,
                [this, spin] { apply(spin == flux_ ? Field::Flux : Field::Temperature, spin); });
        connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { merge_.finish(); });
    }
    connect(replace_, &QPushButton::clicked, this, [this] {
        const QString path = askFile_ ? askFile_() : QString();
        if (path.isEmpty()) return;
        QString error;
        if (!replaceLuminaireFile(path, &error)) emit message(error);
    });
    connect(doc_, &Document::changed, this, [this] {
        if (!lights_.empty() || !groupName_.empty()) refresh();
    });
    refresh();
}

void LightSetProperties::setGroup(const std::string& group) {
    merge_.finish();
    groupName_ = group;
    lights_ = groupMembers(doc_->scene(), group);
    refresh();
}

void LightSetProperties::setLights(std::vector<int> lights) {
    merge_.finish();
    groupName_.clear();
    lights_ = std::move(lights);
    refresh();
}

void LightSetProperties::refresh() {
    const Scene& scene = doc_->scene();
    if (!groupName_.empty()) lights_ = groupMembers(scene, groupName_);
    std::erase_if(lights_, [&scene](int i) { return i < 0 || size_t(i) >= scene.lights.size(); });
    std::vector<QSignalBlocker> blocks;
    blocks.reserve(4);
    for (QObject* o : std::initializer_list<QObject*>{group_, on_, flux_, temperature_}) blocks.emplace_back(o);

    const int n = int(lights_.size());
    const QString count = counted(n, tr("light"), tr("lights"));
    title_->setText(groupName_.empty() ? tr("%1 selected").arg(count)
                                       : tr("Group %1: %2").arg(QString::fromStdString(groupName_), count));
    std::map<LightType, int> types;
    int on = 0;
    std::vector<std::string> groups, files;
    std::vector<double> fluxes, temperatures;
    bool colourGiven = false, white = false, anyPositioned = false;
    int luminaires = 0;
    FluxCache cache;
    for (int i : lights_) {
        const Light& l = scene.lights[size_t(i)];
        ++types[l.type];
        on += l.on ? 1 : 0;
        groups.push_back(l.group);
        anyPositioned = anyPositioned || hasPosition(l);
        if (const auto f = fluxOf(l, cache)) fluxes.push_back(*f);
        if (hasPosition(l)) {
            if (const auto t = temperatureOf(l)) temperatures.push_back(*t);
            else if (colourGivenFor(l)) colourGiven = true;
            else white = true;
        }
        if (l.type == LightType::Luminaire && l.luminaire) {
            ++luminaires;
            if (std::find(files.begin(), files.end(), l.luminaire->file) == files.end()) files.push_back(l.luminaire->file);
        }
    }
    QStringList parts;
    const std::tuple<LightType, QString, QString> names[] = {
        {LightType::Point, tr("point light"), tr("point lights")},
        {LightType::Spot, tr("spot"), tr("spots")},
        {LightType::Luminaire, tr("luminaire"), tr("luminaires")},
        {LightType::Directional, tr("directional light"), tr("directional lights")},
        {LightType::Sun, tr("sun"), tr("suns")}};
    for (const auto& [type, one, many] : names)
        if (types[type] > 0) parts << counted(types[type], one, many);
    if (on < n) parts << tr("%1 switched off").arg(n - on);
    summary_->setText(parts.join(", "));

    const bool oneGroup =
        std::all_of(groups.begin(), groups.end(), [&](const std::string& g) { return g == groups.front(); });
    if (!group_->hasFocus())
        group_->setText(oneGroup && !groups.empty() ? QString::fromStdString(groups.front()) : QString());
    group_->setPlaceholderText(oneGroup ? tr("none") : tr("mixed"));
    on_->setCheckState(on == n ? Qt::Checked : on == 0 ? Qt::Unchecked : Qt::PartiallyChecked);

    fluxRow_->setVisible(!fluxes.empty());
    showValue(flux_, shared(fluxes));
    temperatureRow_->setVisible(anyPositioned);
    // One temperature for all, or what they have instead: a colour each, white (neither), or a mix.
    showValue(temperature_, colourGiven || white ? std::nullopt : shared(temperatures));
    const bool onlyColours = colourGiven && !white && temperatures.empty();
    const bool onlyWhite = white && !colourGiven && temperatures.empty();
    temperature_->setSpecialValueText(onlyColours ? tr("colours given") : onlyWhite ? tr("white (none given)") : tr("mixed"));

    if (luminaires == 0) file_->setText(tr("none"));
    else if (files.size() == 1 && luminaires == n) file_->setText(QString::fromStdString(files.front()));
    else if (files.size() == 1)
        file_->setText(tr("%1 (%2)").arg(QString::fromStdString(files.front()), counted(luminaires, tr("luminaire"), tr("luminaires"))));
    else file_->setText(tr("mixed (%1 files)").arg(files.size()));
    replace_->setEnabled(anyPositioned);
}

void LightSetProperties::push(std::vector<int> indices, std::vector<Light> after, const void* sender, const QString& text) {
    if (indices.empty()) {
        refresh();
        return;
    }
    const int key = sender ? merge_.keyFor(sender) : 0;
    doc_->undoStack()->push(new EditLightsCommand(doc_, std::move(indices), std::move(after), key, text));
}

void LightSetProperties::apply(Field field, const void* sender) {
    const Scene& scene = doc_->scene();
    const QString what = !groupName_.empty() ? tr("group %1").arg(QString::fromStdString(groupName_))
                                             : counted(int(lights_.size()), tr("light"), tr("lights"));
    std::vector<int> indices;
    std::vector<Light> after;
    const auto change = [&](int i, Light l) {
        if (l == scene.lights[size_t(i)]) return;
        indices.push_back(i);
        after.push_back(std::move(l));
    };
    switch (field) {
    case Field::Group: {
        const std::string name = group_->text().trimmed().toStdString();
        for (int i : lights_) {
            Light l = scene.lights[size_t(i)];
            l.group = name;
            change(i, std::move(l));
        }
        if (!indices.empty() && !groupName_.empty() && !name.empty()) groupName_ = name;  // the panel follows
        push(std::move(indices), std::move(after), nullptr,
             name.empty() ? tr("Ungroup %1").arg(what) : tr("Group %1 as %2").arg(what, QString::fromStdString(name)));
        return;
    }
    case Field::On: {
        const bool allOn = std::all_of(lights_.begin(), lights_.end(), [&](int i) { return scene.lights[size_t(i)].on; });
        for (int i : lights_) {
            Light l = scene.lights[size_t(i)];
            l.on = !allOn;
            change(i, std::move(l));
        }
        push(std::move(indices), std::move(after), nullptr,
             allOn ? tr("Switch off %1").arg(what) : tr("Switch on %1").arg(what));
        return;
    }
    case Field::Flux: {
        const double lumens = flux_->value();
        if (lumens < 0) return;  // "mixed": nothing typed
        FluxCache cache;
        for (int i : lights_)
            if (fluxOf(scene.lights[size_t(i)], cache)) change(i, withFlux(scene.lights[size_t(i)], lumens));
        push(std::move(indices), std::move(after), sender, tr("Change flux of %1").arg(what));
        return;
    }
    case Field::Temperature: {
        const double kelvin = temperature_->value();
        if (kelvin < 1000) return;  // "mixed"
        for (int i : lights_)
            if (hasPosition(scene.lights[size_t(i)])) change(i, withTemperature(scene.lights[size_t(i)], kelvin));
        push(std::move(indices), std::move(after), sender, tr("Change colour temperature of %1").arg(what));
        return;
    }
    }
}

bool LightSetProperties::replaceLuminaireFile(const QString& path, QString* error) {
    Light model;
    try {
        model = luminaireFromFile(*doc_, path);
    } catch (const std::exception& e) {
        const QString text = tr("Could not read %1: %2").arg(path, QString::fromStdString(e.what()));
        if (error) *error = text;
        return false;
    }
    const Scene& scene = doc_->scene();
    std::vector<int> indices;
    std::vector<Light> after;
    for (int i : lights_) {
        const Light& old = scene.lights[size_t(i)];
        if (!hasPosition(old)) continue;
        Light l = old;
        LuminaireSpec spec = *model.luminaire;  // the file and its distribution, at its own flux
        if (old.type == LightType::Luminaire && old.luminaire) {
            spec.rotationDeg = old.luminaire->rotationDeg;
            spec.colour = old.luminaire->colour;
            spec.temperatureK = old.luminaire->temperatureK;
        } else {
            const PhotometricSpec p = photometricOf(old);
            spec.colour = p.colour;
            spec.temperatureK = p.temperatureK;
            if (old.type == LightType::Point) l.direction = V3d(0, -1, 0);
        }
        l.type = LightType::Luminaire;
        l.photometric.reset();
        l.intensity = Rgbd(0, 0, 0);
        l.luminaire = std::move(spec);
        if (!(l == old)) {
            indices.push_back(i);
            after.push_back(std::move(l));
        }
    }
    const QString what = !groupName_.empty() ? tr("group %1").arg(QString::fromStdString(groupName_))
                                             : counted(int(lights_.size()), tr("light"), tr("lights"));
    push(std::move(indices), std::move(after), nullptr,
         tr("Use %1 for %2").arg(QString::fromStdString(model.luminaire->file), what));
    return true;
}

}  // namespace lucerna
