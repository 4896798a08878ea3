#pragma once
// ParameterForm and ParameterDock: fields generated from simcore::parameterTable().
//
// One field per key of the current scene (a combo box for a choice such as contact or
// scaling, whose names come from the table): its unit, its range and meaning in the tooltip,
// validated by the same table the CLI uses (simcore::validateValue). Widget -> model: a valid
// edit emits edited(Param, value) (the key is text only inside the form); model -> widget: setValues() refreshes the fields under a
// guard, so showing a value never echoes back as an edit.

#include <map>
#include <set>
#include <vector>

#include <QDockWidget>
#include <QWidget>

#include "simcore/params.h"

class QComboBox;
class QFormLayout;
class QHBoxLayout;
class QLineEdit;
class QPushButton;
class QSlider;
class QToolButton;
class QVBoxLayout;

namespace elui {

class ParameterForm : public QWidget {
    Q_OBJECT
public:
    // The keys of `kind` whose group is in `groups`, grouped under a heading per group.
    ParameterForm(simcore::SceneKind kind, const std::set<simcore::ParamGroup>& groups,
                  QWidget* parent = nullptr);

    simcore::SceneKind kind() const { return m_kind; }
    QStringList keys() const;
    QLineEdit* field(const QString& key) const;    // a number's field (nullptr for a choice)
    // A main parameter's slider beside its field (nullptr for the others), and every key's
    // button back to the scene's default (disabled while the value is the default).
    QSlider* slider(const QString& key) const;
    QToolButton* defaultButton(const QString& key) const;
    // The value a slider position stands for (3 significant digits), and back.
    double sliderValue(const QString& key, int position) const;
    int sliderPosition(const QString& key, double value) const;
    // Every key of this form back to the scene's default (an edit per key that differs).
    void resetAll();
    QComboBox* choice(const QString& key) const;   // a choice's box, e.g. contact, scaling
    // The values shown, as a parameter set of this form's scene (only keys of this form).
    simcore::ParameterSet values() const;
    void setValues(const simcore::ParameterSet& params);
    // Validates a text with the table; an error message, or empty when the text is valid.
    static QString validate(const simcore::ParamSpec& spec, const QString& text, double* value = nullptr);

signals:
    void edited(simcore::Param id, double value);
    void rejected(const QString& key, const QString& message);

private:
    QToolButton* addDefaultButton(QHBoxLayout* row, const QString& key, const QString& tip);
    void addChoiceRow(const simcore::ParamSpec& spec, QFormLayout* form);
    void addFieldRow(const simcore::ParamSpec& spec, QFormLayout* form);
    void addSliderRow(const simcore::ParamSpec& spec, double lo, double hi, bool log, QFormLayout* form);
    bool commit(const QString& key);  // false: refused (the field is marked red)
    void setToDefault(const QString& key);
    void showDefaultState(const QString& key, double value);

    simcore::SceneKind m_kind;
    struct Span {
        double lo = 0.0, hi = 1.0;
        bool log = false;
    };
    std::map<QString, QSlider*> m_sliders;
    std::map<QString, Span> m_spans;
    std::map<QString, QToolButton*> m_defaults;
    std::map<QString, QLineEdit*> m_fields;
    std::map<QString, QComboBox*> m_choices;
    std::map<QString, double> m_shown;  // value last shown or accepted per key
    bool m_updating = false;
};

class ParameterDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ParameterDock(QWidget* parent = nullptr);
    ParameterForm* form() const { return m_form; }
    // A scene of several bodies: the body selector (hidden for one body). Its entries are
    // "body1 (ring2d)", ..., then "every body"; an edit goes to the chosen body (a world
    // parameter, such as gravity or dt, to every body whatever is chosen).
    QComboBox* bodySelector() const { return m_bodies; }
    QPushButton* resetAllButton() const { return m_resetAll; }

public slots:
    // Rebuilds the fields when the scene kind changes, then shows the values.
    void showParameters(const simcore::ParameterSet& params);
    // The world's bodies (kinds in order; empty: one body) and the one chosen (-1: every body).
    void showBodies(const std::vector<simcore::SceneKind>& kinds, int chosen);

signals:
    void parameterEdited(simcore::Param id, double value);
    void parameterRejected(const QString& key, const QString& message);
    void bodyChosen(int body);  // from 0; -1: every body

private:
    QComboBox* m_bodies = nullptr;
    std::vector<simcore::SceneKind> m_kinds;
    QWidget* m_host = nullptr;
    QVBoxLayout* m_layout = nullptr;
    ParameterForm* m_form = nullptr;
    QPushButton* m_resetAll = nullptr;
};

QString groupName(simcore::ParamGroup group);
// A field's label: its key, except the gas keys (pressure, pressure_inner, pressure_outer),
// which hold nRT in J and are shown as "gas nRT", "gas nRT inner", "gas nRT outer".
QString fieldLabel(const simcore::ParamSpec& spec);
QString toQString(std::string_view text);

}  // namespace elui
