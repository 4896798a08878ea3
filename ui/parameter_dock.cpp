#include "ui/parameter_dock.h"

#include <algorithm>
#include <cmath>

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "simcore/scenes.h"
#include "ui/accessibility.h"
#include "ui/field_keys.h"
#include "ui/language.h"

namespace elui {

QString toQString(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

QString groupName(simcore::ParamGroup group) {
    using G = simcore::ParamGroup;
    switch (group) {
        case G::Springs: return QObject::tr("Springs");
        case G::Gas: return QObject::tr("Gas");
        case G::Mass: return QObject::tr("Mass");
        case G::Environment: return QObject::tr("Environment");
        case G::Contact: return QObject::tr("Contact");
        case G::Pointer: return QObject::tr("Mouse spring");
        case G::Time: return QObject::tr("Time");
        case G::Shape: return QObject::tr("Shape");
        case G::Start: return QObject::tr("Start");
    }
    return {};
}

QString fieldLabel(const simcore::ParamSpec& spec) {
    // The gas keys hold nRT (P = nRT / V), an energy in J, not a pressure: named for what they
    // are beside the plots of pressure in N/m or Pa. The key (CLI, files, Python) stays.
    switch (spec.id) {
        case simcore::Param::Pressure: return QObject::tr("gas nRT");
        case simcore::Param::PressureInner: return QObject::tr("gas nRT inner");
        case simcore::Param::PressureOuter: return QObject::tr("gas nRT outer");
        default: return toQString(spec.key);
    }
}

// In the locale's spelling (a decimal comma in German); fields read it and the C spelling.
static QString formatValue(double v) { return num(v, 'g', 10); }

namespace {
// The span a main parameter's slider covers: the values a class tries, inside the table's
// allowed range (clipped to it); log for stiffnesses and masses, which matter by factors.
// Other parameters have the typed field only.
struct SliderSpan {
    simcore::Param id;
    double lo, hi;
    bool log;
};
constexpr SliderSpan kSliderSpans[] = {
    {simcore::Param::Ks, 10.0, 1e5, true},          {simcore::Param::Kd, 0.0, 200.0, false},
    {simcore::Param::Rks, 10.0, 1e5, true},         {simcore::Param::Rkd, 0.0, 200.0, false},
    {simcore::Param::Pressure, 0.0, 200.0, false},  {simcore::Param::PressureInner, 0.0, 200.0, false},
    {simcore::Param::PressureOuter, 0.0, 200.0, false}, {simcore::Param::Mass, 0.05, 20.0, true},
    {simcore::Param::MassInner, 0.05, 20.0, true},  {simcore::Param::MassOuter, 0.05, 20.0, true},
    {simcore::Param::Gravity, 0.0, 30.0, false},    {simcore::Param::Restitution, 0.0, 1.0, false},
    {simcore::Param::Friction, 0.0, 1.0, false},    {simcore::Param::Mks, 0.0, 2000.0, false},
    {simcore::Param::Mkd, 0.0, 200.0, false},
};
constexpr int kSliderSteps = 1000;

// v rounded to three significant digits (a slider stands for readable numbers).
double threeDigits(double v) {
    if (v == 0.0 || !std::isfinite(v)) return v;
    const double scale = std::pow(10.0, 2 - std::floor(std::log10(std::abs(v))));
    return std::round(v * scale) / scale;
}
}  // namespace

ParameterForm::ParameterForm(simcore::SceneKind kind, const std::set<simcore::ParamGroup>& groups,
                             QWidget* parent)
    : QWidget(parent), m_kind(kind) {
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    std::map<simcore::ParamGroup, QFormLayout*> forms;
    for (const simcore::ParamSpec* spec : simcore::parametersFor(kind)) {
        if (!groups.count(spec->group)) continue;
        QFormLayout*& form = forms[spec->group];
        if (!form) {
            auto* box = new QGroupBox(groupName(spec->group), this);
            form = new QFormLayout(box);
            form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
            // A row too wide for the dock puts its field under its label (a long key such as
            // contact_stiffness in presentation mode) instead of making the dock scroll sideways.
            form->setRowWrapPolicy(QFormLayout::WrapLongRows);
            outer->addWidget(box);
        }
        if (!spec->choices.empty()) {
            addChoiceRow(*spec, form);
            continue;
        }
        addFieldRow(*spec, form);
        for (const SliderSpan& span : kSliderSpans)
            if (span.id == spec->id) addSliderRow(*spec, span.lo, span.hi, span.log, form);
    }
    outer->addStretch(1);
    setValues(simcore::ParameterSet(kind));
}

// The ↺ at the end of a row: the key back to the scene's default.
QToolButton* ParameterForm::addDefaultButton(QHBoxLayout* row, const QString& key, const QString& tip) {
    auto* back = new QToolButton(row->parentWidget());
    back->setObjectName(QStringLiteral("default_") + key);
    back->setText(QStringLiteral("↺"));
    back->setToolTip(tip);
    connect(back, &QToolButton::clicked, this, [this, key] { setToDefault(key); });
    row->addWidget(back);
    m_defaults[key] = back;
    return back;
}

// A choice: its names, in the table's order (index = the parameter's value), and ↺.
void ParameterForm::addChoiceRow(const simcore::ParamSpec& param, QFormLayout* form) {
    const simcore::ParamSpec* spec = &param;
    const simcore::SceneKind kind = m_kind;
    const QString key = toQString(spec->key);
    auto* box = new QComboBox(this);
    box->setObjectName(QStringLiteral("param_") + key);
    for (int k = 0; !spec->choiceName(k).empty(); ++k) box->addItem(QString::fromStdString(spec->choiceName(k)));
    const QString tip = tr("<b>%1</b><br>%2<br>default: %3")
                            .arg(key, simcoreText(spec->meaning).toHtmlEscaped(),
                                 QString::fromStdString(spec->choiceName(spec->defaultFor(kind))));
    box->setToolTip(tip);
    setAccessibleText(box, key + QStringLiteral(": ") + simcoreText(spec->meaning), tip);
    auto* label = new QLabel(key, this);
    label->setToolTip(tip);
    auto* choiceRow = new QWidget(this);
    auto* ch = new QHBoxLayout(choiceRow);
    ch->setContentsMargins(0, 0, 0, 0);
    ch->addWidget(box, 1);
    addDefaultButton(ch, key,
                     tr("Back to the default: %1").arg(QString::fromStdString(spec->choiceName(spec->defaultFor(kind)))));
    form->addRow(label, choiceRow);
    m_choices[key] = box;
    connect(box, &QComboBox::activated, this, [this, key, id = spec->id](int index) {
        if (m_updating) return;
        if (m_shown.count(key) && m_shown[key] == index) return;
        m_shown[key] = index;
        emit edited(id, index);
    });
}

// A number: the field, its unit and ↺ on one row, labelled with the key (or its name).
void ParameterForm::addFieldRow(const simcore::ParamSpec& param, QFormLayout* form) {
    const simcore::ParamSpec* spec = &param;
    const simcore::SceneKind kind = m_kind;
    const QString key = toQString(spec->key);
    const QString unit = toQString(spec->unit);
    auto* edit = new QLineEdit(this);
    edit->setObjectName(QStringLiteral("param_") + key);
    QString tip = tr("<b>%1</b>%2<br>%3<br>allowed: %4<br>default: %5")
                            .arg(key, unit.isEmpty() ? QString() : QStringLiteral(" [%1]").arg(unit),
                                 simcoreText(spec->meaning).toHtmlEscaped(),
                                 QString::fromStdString(spec->rangeText()),
                                 formatValue(spec->defaultFor(kind)));
    if (spec->id == simcore::Param::Dt) {
        // One editor for DT: the Run dock's (it also offers the stable step). Shown here.
        edit->setReadOnly(true);
        edit->setEnabled(false);
        tip = tr("Set DT in the Run dock.") + QStringLiteral("<br>") + tip;
    }
    edit->setToolTip(tip);
    edit->setProperty("tip", tip);
    // Read as "ks: structural spring stiffness ... , newtons per metre" (the unit as written).
    setAccessibleText(edit, key + QStringLiteral(": ") + simcoreText(spec->meaning) +
                                (unit.isEmpty() ? QString() : QStringLiteral(" [%1]").arg(unit)),
                      tip);
    auto* row = new QWidget(this);
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(edit, 1);
    auto* unitLabel = new QLabel(unit, row);
    unitLabel->setMinimumWidth(44);
    h->addWidget(unitLabel);
    addDefaultButton(h, key, tr("Back to the default: %1 %2").arg(formatValue(spec->defaultFor(kind)), unit))
        ->setEnabled(spec->id != simcore::Param::Dt);
    auto* label = new QLabel(fieldLabel(*spec), this);
    label->setObjectName(QStringLiteral("label_") + key);
    if (label->text() != key) tip += QStringLiteral("<br>") + tr("key: %1").arg(key);
    edit->setToolTip(tip);
    edit->setProperty("tip", tip);
    label->setToolTip(tip);
    form->addRow(label, row);
    m_fields[key] = edit;
    connect(edit, &QLineEdit::editingFinished, this, [this, key] { commit(key); });
    // Enter commits and leaves the field, Escape puts back the value in use (field_keys.h).
    installFieldKeys(
        edit, [this, key] { return commit(key); },
        [this, key, edit] {
            if (m_shown.count(key)) edit->setText(formatValue(m_shown[key]));
            markField(edit, {}, edit->property("tip").toString());
        });
}

// The slider under a main parameter's field, inside the table's range, its ends and unit beside it.
void ParameterForm::addSliderRow(const simcore::ParamSpec& param, double spanLo, double spanHi, bool spanLog,
                                 QFormLayout* form) {
    const simcore::ParamSpec* spec = &param;
    const QString key = toQString(spec->key);
    const QString unit = toQString(spec->unit);
    // Inside the table's range; the ends and the unit beside it.
    const double lo = std::max(spanLo, spec->minValue), hi = std::min(spanHi, spec->maxValue);
    m_spans[key] = {lo, hi, spanLog && lo > 0.0};
    auto* slideRow = new QWidget(this);
    auto* sh = new QHBoxLayout(slideRow);
    sh->setContentsMargins(0, 0, 0, 0);
    auto* slider = new QSlider(Qt::Horizontal, slideRow);
    slider->setObjectName(QStringLiteral("slider_") + key);
    slider->setRange(0, kSliderSteps);
    slider->setToolTip(tr("%1 from %2 to %3 %4%5 (the field takes any value in %6)")
                           .arg(key, formatValue(lo), formatValue(hi), unit,
                                m_spans[key].log ? tr(", logarithmic") : QString(),
                                QString::fromStdString(spec->rangeText())));
    auto* loLabel = new QLabel(formatValue(lo), slideRow);
    auto* hiLabel = new QLabel(unit.isEmpty() ? formatValue(hi) : formatValue(hi) + QLatin1Char(' ') + unit, slideRow);
    QFont small = loLabel->font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    loLabel->setFont(small);
    hiLabel->setFont(small);
    sh->addWidget(loLabel);
    sh->addWidget(slider, 1);
    sh->addWidget(hiLabel);
    form->addRow(QString(), slideRow);
    m_sliders[key] = slider;
    connect(slider, &QSlider::valueChanged, this, [this, key, id = spec->id](int position) {
        if (m_updating) return;
        const double v = sliderValue(key, position);
        if (m_shown.count(key) && m_shown[key] == v) return;
        m_shown[key] = v;
        m_updating = true;
        m_fields[key]->setText(formatValue(v));
        m_updating = false;
        showDefaultState(key, v);
        emit edited(id, v);
    });
}

QStringList ParameterForm::keys() const {
    QStringList out;
    for (const simcore::ParamSpec* spec : simcore::parametersFor(m_kind)) {
        const QString key = toQString(spec->key);
        if (m_fields.count(key) || m_choices.count(key)) out << key;
    }
    return out;
}

QSlider* ParameterForm::slider(const QString& key) const {
    auto it = m_sliders.find(key);
    return it == m_sliders.end() ? nullptr : it->second;
}

QToolButton* ParameterForm::defaultButton(const QString& key) const {
    auto it = m_defaults.find(key);
    return it == m_defaults.end() ? nullptr : it->second;
}

double ParameterForm::sliderValue(const QString& key, int position) const {
    auto it = m_spans.find(key);
    if (it == m_spans.end()) return 0.0;
    const Span& s = it->second;
    const double f = double(std::clamp(position, 0, kSliderSteps)) / kSliderSteps;
    const double v = s.log ? s.lo * std::pow(s.hi / s.lo, f) : s.lo + f * (s.hi - s.lo);
    return std::clamp(threeDigits(v), s.lo, s.hi);
}

int ParameterForm::sliderPosition(const QString& key, double value) const {
    auto it = m_spans.find(key);
    if (it == m_spans.end()) return 0;
    const Span& s = it->second;
    const double v = std::clamp(value, s.lo, s.hi);
    const double f = s.log ? std::log(v / s.lo) / std::log(s.hi / s.lo) : (v - s.lo) / (s.hi - s.lo);
    return int(std::lround(f * kSliderSteps));
}

void ParameterForm::showDefaultState(const QString& key, double value) {
    const simcore::ParamSpec* spec = simcore::findParam(key.toStdString());
    if (QToolButton* back = defaultButton(key); back && spec)
        back->setEnabled(spec->id != simcore::Param::Dt && value != spec->defaultFor(m_kind));
}

void ParameterForm::setToDefault(const QString& key) {
    const simcore::ParamSpec* spec = simcore::findParam(key.toStdString());
    if (!spec) return;
    const double v = spec->defaultFor(m_kind);
    if (m_shown.count(key) && m_shown[key] == v) return;
    m_shown[key] = v;
    emit edited(spec->id, v);
}

void ParameterForm::resetAll() {
    // DT included: it is edited in the Run dock, but the scene's default belongs to "all".
    for (const QString& key : keys()) setToDefault(key);
}

QComboBox* ParameterForm::choice(const QString& key) const {
    auto it = m_choices.find(key);
    return it == m_choices.end() ? nullptr : it->second;
}

QLineEdit* ParameterForm::field(const QString& key) const {
    auto it = m_fields.find(key);
    return it == m_fields.end() ? nullptr : it->second;
}

QString ParameterForm::validate(const simcore::ParamSpec& spec, const QString& text, double* value) {
    const std::string t = toCNumber(text).trimmed().toStdString();  // "0,5" in German: 0.5
    const auto parsed = simcore::parseValue(spec, t);  // a number, or a choice's name
    if (!parsed)
        return tr("%1: '%2' is not a number; allowed %3").arg(toQString(spec.key), text, QString::fromStdString(spec.rangeText()));
    // simcore's message in English; in another language the same facts in its words.
    if (auto error = simcore::validateValue(spec, *parsed))
        return currentLanguage() == QLatin1String("en")
                   ? QString::fromStdString(*error)
                   : tr("%1 = %2 is not allowed; allowed %3%4")
                         .arg(toQString(spec.key), text.trimmed(), QString::fromStdString(spec.rangeText()),
                              spec.integer ? tr(", whole numbers") : QString());
    if (value) *value = *parsed;
    return {};
}

simcore::ParameterSet ParameterForm::values() const {
    simcore::ParameterSet out(m_kind);
    for (const auto& [key, edit] : m_fields) {
        const simcore::ParamSpec* spec = simcore::findParam(key.toStdString());
        double v = 0.0;
        if (spec && validate(*spec, edit->text(), &v).isEmpty()) out.set(key.toStdString(), v);
    }
    for (const auto& [key, box] : m_choices) out.set(key.toStdString(), box->currentIndex());
    return out;
}

void ParameterForm::setValues(const simcore::ParameterSet& params) {
    m_updating = true;
    for (auto& [key, edit] : m_fields) {
        const double v = params.get(simcore::findParam(key.toStdString())->id);
        m_shown[key] = v;
        // A field being typed in keeps its text, and its red mark if the text was refused: the
        // mark says the text is not the value in use.
        if (QSlider* sl = slider(key)) sl->setValue(sliderPosition(key, v));
        showDefaultState(key, v);
        if (edit->hasFocus() && !edit->text().isEmpty()) continue;
        edit->setText(formatValue(v));
        markField(edit, {}, edit->property("tip").toString());
    }
    for (auto& [key, box] : m_choices) {
        const double v = params.get(simcore::findParam(key.toStdString())->id);
        m_shown[key] = v;
        box->setCurrentIndex(static_cast<int>(v));
        showDefaultState(key, v);
    }
    m_updating = false;
}

bool ParameterForm::commit(const QString& key) {
    if (m_updating) return false;
    QLineEdit* edit = field(key);
    const simcore::ParamSpec* spec = simcore::findParam(key.toStdString());
    if (!edit || !spec) return false;
    double v = 0.0;
    const QString error = validate(*spec, edit->text(), &v);
    markField(edit, error, edit->property("tip").toString());
    if (!error.isEmpty()) {
        emit rejected(key, error);
        return false;
    }
    if (m_shown.count(key) && m_shown[key] == v) return true;  // nothing changed
    m_shown[key] = v;
    if (QSlider* sl = slider(key)) {
        m_updating = true;
        sl->setValue(sliderPosition(key, v));
        m_updating = false;
    }
    showDefaultState(key, v);
    emit edited(spec->id, v);
    return true;
}

ParameterDock::ParameterDock(QWidget* parent) : QDockWidget(tr("Parameters"), parent) {
    setObjectName(QStringLiteral("ParametersDock"));
    auto* scroll = new QScrollArea(this);
    scroll->setAccessibleName(tr("Parameters"));
    scroll->setAccessibleDescription(tr("Every parameter of the scene with its unit; a change applies at once"));
    scroll->setWidgetResizable(true);
    m_host = new QWidget(scroll);
    m_layout = new QVBoxLayout(m_host);
    m_layout->setContentsMargins(4, 4, 4, 4);
    m_bodies = new QComboBox(m_host);
    m_bodies->setObjectName(QStringLiteral("bodySelector"));
    m_bodies->setToolTip(tr("The body whose parameters are shown and edited; world parameters (gravity, box, "
                            "contact, dt) are every body's."));
    m_bodies->hide();
    m_layout->addWidget(m_bodies);
    connect(m_bodies, &QComboBox::activated, this, [this](int index) {
        emit bodyChosen(index >= int(m_kinds.size()) ? -1 : index);
    });
    m_resetAll = new QPushButton(tr("Reset all to the scene's defaults"), m_host);
    m_resetAll->setObjectName(QStringLiteral("resetAllParameters"));
    m_resetAll->setToolTip(tr("Every parameter here (and DT) back to the scene's default; the body's shape "
                              "stays (Scene dock)."));
    connect(m_resetAll, &QPushButton::clicked, this, [this] {
        if (m_form) m_form->resetAll();
    });
    m_layout->addWidget(m_resetAll);
    scroll->setWidget(m_host);
    setWidget(scroll);
}

void ParameterDock::showBodies(const std::vector<simcore::SceneKind>& kinds, int chosen) {
    if (kinds != m_kinds) {
        m_kinds = kinds;
        m_bodies->clear();
        for (std::size_t k = 0; k < kinds.size(); ++k)
            m_bodies->addItem(tr("body%1 (%2)").arg(k + 1).arg(toQString(simcore::sceneInfo(kinds[k]).name)));
        if (!kinds.empty()) m_bodies->addItem(tr("every body"));
    }
    m_bodies->setVisible(!kinds.empty());
    if (!kinds.empty()) m_bodies->setCurrentIndex(chosen < 0 ? int(kinds.size()) : chosen);
}

void ParameterDock::showParameters(const simcore::ParameterSet& params) {
    if (!m_form || m_form->kind() != params.kind()) {
        delete m_form;
        using G = simcore::ParamGroup;
        m_form = new ParameterForm(params.kind(), {G::Springs, G::Gas, G::Mass, G::Environment, G::Contact,
                                                   G::Pointer, G::Time, G::Start},
                                   m_host);
        m_layout->addWidget(m_form);
        connect(m_form, &ParameterForm::edited, this, &ParameterDock::parameterEdited);
        connect(m_form, &ParameterForm::rejected, this, &ParameterDock::parameterRejected);
    }
    m_form->setValues(params);
}

}  // namespace elui
