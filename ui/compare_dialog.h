#pragma once
// CompareDialog: choose up to three integrators to run side by side from the same start.

#include <QDialog>
#include <QStringList>

class QComboBox;
class QLineEdit;

namespace elui {

class CompareDialog : public QDialog {
    Q_OBJECT
public:
    CompareDialog(const QStringList& current, double dt, QWidget* parent = nullptr);
    QStringList integrators() const;  // one to three names
    double dt() const;

private:
    QComboBox* m_combo[3] = {};
    QLineEdit* m_dt = nullptr;
};

}  // namespace elui
