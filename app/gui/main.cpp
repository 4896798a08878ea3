// elastic-lab: the GUI.
//
//   elastic-lab [FILE.json | --scene S|FILE.json] [--set key=value]... [--integrator NAME] [--compare A,B,C]
//               [--preset ID | --lesson ID] [--experiments] [--docks LIST]
//               [--screenshot FILE --after SECONDS [--travel-back SECONDS [--branch key=value]]]
//
// A scene file may also be given alone (the desktop entry's Exec=elastic-lab %f, a file manager's
// "Open with"). --screenshot runs (as fast as possible) to the given simulated time, renders the main
// window, writes the PNG and exits: used by the tests and for the README's screenshots.
//
// The command line is checked by app/gui/command_line.h through simlab's front door before any
// window exists (a refusal: one line, exit 2); app/gui/window_start.h builds and runs the window.
#include <QApplication>

#include "app/gui/command_line.h"
#include "app/gui/window_start.h"

int main(int argc, char** argv) {
    elgui::beforeApplication(argc, argv);
    elgui::HeldStartupMessages held;
    QApplication app(argc, argv);
    held.release();
    elgui::describeApplication();
    try {
        elgui::GuiCommandLine commandLine;
        commandLine.parse(QApplication::arguments());
        elgui::applyLanguage(commandLine);  // before any widget or translated text (lessons too)
        return elgui::runWindow(app, commandLine.request());
    } catch (const simlab::RequestError& e) {
        return elgui::fail(QString::fromStdString(e.what()));
    }
}
