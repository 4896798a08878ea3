#pragma once
// CompareDialog: choose up to three integrators to run side by side from the same start.
// It shows the common DT; the Run dock is its one editor.

#include <QDialog>
#include <QStringList>

class QComboBox;

namespace elui {

class CompareDialog : public QDialog {
    Q_OBJECT
public:
    CompareDialog(const QStringList& current, double dt, QWidget* parent = nullptr);
    QStringList integrators() const;  // one to three names
    // What Compare > Side by side proposes: the views running now when there are several;
    // from a single view, its integrator and then euler, midpoint, rk4 (the thesis's three),
    // skipping the one already chosen: three distinct names.
    static QStringList proposal(const QStringList& current);

private:
    QComboBox* m_combo[3] = {};
};

}  // namespace elui
