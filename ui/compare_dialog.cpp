#include "ui/compare_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "ui/parameter_dock.h"

namespace elui {

CompareDialog::CompareDialog(const QStringList& current, double dt, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Side by side"));
    auto* layout = new QVBoxLayout(this);
    auto* text = new QLabel(tr("Run the same scene with up to three integrators from the same start state. "
                               "Parameter edits and mouse drags go to all of them."),
                            this);
    text->setWordWrap(true);
    layout->addWidget(text);
    auto* form = new QFormLayout;
    for (int i = 0; i < 3; ++i) {
        m_combo[i] = new QComboBox(this);
        if (i > 0) m_combo[i]->addItem(tr("(none)"));
        for (const simcore::IntegratorInfo& info : simcore::integratorTable()) m_combo[i]->addItem(toQString(info.name));
        if (i < current.size()) m_combo[i]->setCurrentText(current[i]);
        else if (i > 0) m_combo[i]->setCurrentIndex(0);
        form->addRow(tr("View %1").arg(i + 1), m_combo[i]);
    }
    auto* dtLabel = new QLabel(tr("%1 s, common to every view (set it in the Run dock)").arg(dt, 0, 'g', 10), this);
    dtLabel->setObjectName(QStringLiteral("dtShown"));
    form->addRow(tr("DT"), dtLabel);
    layout->addLayout(form);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

QStringList CompareDialog::proposal(const QStringList& current) {
    if (current.size() >= 2) return current;
    QStringList out{current.value(0, QStringLiteral("euler"))};
    for (const QString& name : {QStringLiteral("euler"), QStringLiteral("midpoint"), QStringLiteral("rk4")})
        if (out.size() < 3 && !out.contains(name)) out << name;
    return out;
}

QStringList CompareDialog::integrators() const {
    QStringList out;
    for (QComboBox* c : m_combo)
        if (c->currentText() != tr("(none)")) out << c->currentText();
    return out;
}

}  // namespace elui
