#pragma once
// HelpDialog: the model in a page, each integrator, the presets, and links to docs/.

#include <QDialog>

namespace elui {

class HelpDialog : public QDialog {
    Q_OBJECT
public:
    explicit HelpDialog(QWidget* parent = nullptr);
    static QString html();
};

}  // namespace elui
